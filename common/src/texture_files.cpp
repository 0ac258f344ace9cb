#include "rasterlab/texture_files.hpp"

#include "rasterlab/image_io.hpp"

namespace rl {

const char* texture_suffix(TextureRole role) {
    switch (role) {
        case TextureRole::diffuse:
            return "diffuse";
        case TextureRole::normal_tangent:
            return "nm_tangent";
        case TextureRole::normal_object:
            return "nm";
        case TextureRole::specular:
            return "spec";
    }
    return "";
}

namespace {

const std::filesystem::path& named_by_material(const Material& m, TextureRole role) {
    switch (role) {
        case TextureRole::diffuse:
            return m.diffuse;
        case TextureRole::normal_tangent:
            return m.normal_tangent;
        case TextureRole::normal_object:
            return m.normal_object;
        default:
            return m.specular;
    }
}

}  // namespace

std::optional<std::filesystem::path> find_texture(const Mesh& mesh, int material,
                                                  TextureRole role) {
    std::error_code ec;
    if (material >= 0 && material < static_cast<int>(mesh.materials.size())) {
        const std::filesystem::path& named = named_by_material(mesh.materials[material], role);
        if (!named.empty()) return named;  // the MTL's word wins, even if the file is missing
    }
    const std::filesystem::path stem = mesh.source.parent_path() / mesh.source.stem();
    for (const char* extension : {".tga", ".png", ".jpg"}) {
        std::filesystem::path candidate = stem;
        candidate += std::string("_") + texture_suffix(role) + extension;
        if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
    }
    return std::nullopt;
}

Texture default_texture(TextureRole role) {
    Rgba value{255, 255, 255, 255};
    if (role == TextureRole::normal_tangent || role == TextureRole::normal_object)
        value = {128, 128, 255, 255};
    if (role == TextureRole::specular) value = {0, 0, 0, 255};
    return {Image(1, 1, value), {}, true};
}

Texture load_texture(const Mesh& mesh, int material, TextureRole role,
                     std::vector<std::string>& warnings) {
    const std::optional<std::filesystem::path> path = find_texture(mesh, material, role);
    if (!path) {
        warnings.push_back(mesh.source.string() + ": no " + texture_suffix(role) +
                           " texture found; using a neutral default");
        return default_texture(role);
    }
    try {
        return {load_image(*path), *path, false};
    } catch (const FileError& e) {
        warnings.push_back(std::string(e.what()) + "; using a neutral default " +
                           texture_suffix(role) + " texture");
    } catch (const std::exception& e) {  // out of memory, or anything else: still optional
        warnings.push_back(path->string() + ": " + e.what() + "; using a neutral default " +
                           texture_suffix(role) + " texture");
    }
    return default_texture(role);
}

}  // namespace rl
