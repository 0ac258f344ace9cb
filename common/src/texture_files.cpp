#include "rasterlab/texture_files.hpp"

#include <cstdio>

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

namespace {
thread_local TexelBudget* open_budget = nullptr;
}

TexelBudget::TexelBudget(std::uint64_t texels) : limit_(texels) {
    if (open_budget) return;  // an inner loader: the outer budget counts
    open_budget = this;
    opened_ = true;
}

TexelBudget::~TexelBudget() {
    if (opened_) open_budget = nullptr;
}

bool TexelBudget::take(std::uint64_t texels) {
    if (texels > limit_ - used_) return false;
    used_ += texels;
    return true;
}

TexelBudget* TexelBudget::current() {
    return open_budget;
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
        Image image = load_image(*path);
        const auto texels =
            static_cast<std::uint64_t>(image.width()) * static_cast<std::uint64_t>(image.height());
        TexelBudget* budget = TexelBudget::current();
        if (!budget || budget->take(texels)) return {std::move(image), *path, false};
        char text[400];
        std::snprintf(text, sizeof text,
                      ": its %dx%d texels would bring the scene's textures to %.3g texels, past "
                      "the budget of %.3g (%.3g GiB as RGBA) for all the maps of all the models "
                      "together; using a neutral default ",
                      image.width(), image.height(), static_cast<double>(budget->used() + texels),
                      static_cast<double>(budget->limit()),
                      static_cast<double>(budget->limit()) * 4 / (1u << 30));
        warnings.push_back(path->string() + text + texture_suffix(role) + " texture");
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
