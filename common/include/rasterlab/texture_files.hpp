// Finding and loading the texture files that go with a mesh (the sampling of
// textures is lesson 04's, in lessons/04_textures/sampling.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rasterlab/image.hpp"
#include "rasterlab/mesh.hpp"

namespace rl {

enum class TextureRole { diffuse, normal_tangent, normal_object, specular };

// The file-name suffix tinyrenderer's models use for each role: "diffuse",
// "nm_tangent", "nm", "spec".
const char* texture_suffix(TextureRole role);

struct Texture {
    Image image;
    std::filesystem::path source;  // empty for a default
    bool is_default = false;
};

// Where the texture for `role` is: the file the material's MTL entry names,
// or else `<obj stem>_<suffix>` beside the OBJ with .tga, .png or .jpg.
// Empty when neither exists.
std::optional<std::filesystem::path> find_texture(const Mesh& mesh, int material, TextureRole role);

// A 1x1 stand-in that leaves shading as if the map were absent: white
// diffuse, flat normal (0, 0, 1) in tangent space, no specular. An
// object-space normal map has no neutral value; its default is marked
// is_default so that lessons fall back to the interpolated normal.
Texture default_texture(TextureRole role);

// Finds and loads a texture. A missing or unreadable file is not fatal: it
// adds a warning and returns default_texture(role), so rendering goes on.
Texture load_texture(const Mesh& mesh, int material, TextureRole role,
                     std::vector<std::string>& warnings);

}  // namespace rl
