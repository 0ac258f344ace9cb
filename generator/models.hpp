// One function per model of obj/; each writes <name>.obj, <name>.mtl and its
// textures into `dir`.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace assets {

void make_globe(const std::filesystem::path& dir);
void make_crate(const std::filesystem::path& dir);
void make_floor(const std::filesystem::path& dir);
void make_torus(const std::filesystem::path& dir);
void make_rock(const std::filesystem::path& dir);

struct ModelMaker {
    std::string name;
    std::function<void(const std::filesystem::path&)> make;
};

inline std::vector<ModelMaker> all_models() {
    return {{"globe", make_globe},
            {"crate", make_crate},
            {"floor", make_floor},
            {"torus", make_torus},
            {"rock", make_rock}};
}

}  // namespace assets
