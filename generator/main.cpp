// make_assets: writes the models and textures of obj/ (see obj/README.md).
#include "rasterlab/cli.hpp"

#include <cstdio>
#include <filesystem>

#include "models.hpp"
#include "rasterlab/main_guard.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{"Generate rasterlab's own models and textures (deterministic)."};
    std::string out = "obj";
    std::vector<std::string> only;
    app.add_option("-o,--out", out, "Folder to write into")->capture_default_str();
    app.add_option("--model", only, "Make only these models (globe, crate, floor, torus, rock)");
    return app.run(argc, argv, "make_assets", [&] {
        std::filesystem::create_directories(out);
        int made = 0;
        for (const assets::ModelMaker& maker : assets::all_models()) {
            if (!only.empty() && std::find(only.begin(), only.end(), maker.name) == only.end())
                continue;
            maker.make(out);
            std::printf("made %s\n", maker.name.c_str());
            ++made;
        }
        if (made == 0) throw std::runtime_error("no model of that name");
        return 0;
    });
}
