#include "normal_mapped.hpp"

#include "rasterlab/texture_files.hpp"

namespace normal_mapping {

namespace {

std::optional<textures::MipChain> load_map(const rl::Mesh& mesh, rl::TextureRole role,
                                           std::vector<std::string>& warnings) {
    if (!rl::find_texture(mesh, 0, role)) return std::nullopt;  // the model has none
    rl::Texture t = rl::load_texture(mesh, 0, role, warnings);  // warns if unreadable
    if (t.is_default) return std::nullopt;
    return textures::MipChain(std::move(t.image));
}

}  // namespace

Maps load_maps(const rl::Mesh& mesh, std::vector<std::string>& warnings,
               std::optional<NormalMap> only) {
    Maps maps;
    if (mesh.uvs.empty()) {
        if (rl::find_texture(mesh, 0, rl::TextureRole::normal_tangent) ||
            rl::find_texture(mesh, 0, rl::TextureRole::normal_object))
            warnings.push_back(mesh.source.string() +
                               ": no texture coordinates, so its normal and specular maps are "
                               "ignored");
        return maps;
    }
    if (!only || *only == NormalMap::tangent)
        maps.tangent_normals = load_map(mesh, rl::TextureRole::normal_tangent, warnings);
    if (!only || *only == NormalMap::object)
        maps.object_normals = load_map(mesh, rl::TextureRole::normal_object, warnings);
    maps.specular = load_map(mesh, rl::TextureRole::specular, warnings);
    return maps;
}

}  // namespace normal_mapping
