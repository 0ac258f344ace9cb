#include "rasterlab/mesh.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <new>
#include <set>
#include <sstream>
#include <stdexcept>

#include "obj_validation.hpp"

namespace rl {
namespace {

// tinyobjloader reports some structural problems only as warnings and then
// drops the face; for us they make the file malformed.
constexpr std::string_view kFatalWarnings[] = {"Degenerated face", "invalid vertex index"};

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line != ".") lines.push_back(line);
    return lines;
}

int checked_index(int index, std::size_t count, const char* what, const std::string& name) {
    if (index < -1 || index >= static_cast<int>(count))
        throw MeshError(name, std::string(what) + " index " + std::to_string(index + 1) +
                                  " is out of range (the file defines " + std::to_string(count) +
                                  ")");
    return index;
}

// What tinyobjloader hands back for one file.
struct Parsed {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    bool ok = false;
};

// How many materials an MTL text defines: its `newmtl` lines.
std::size_t count_materials(std::string_view text) {
    std::size_t count = 0;
    for (std::size_t at = text.find("newmtl"); at != std::string_view::npos;
         at = text.find("newmtl", at + 6))
        count += at == 0 || text[at - 1] == '\n' || text[at - 1] == ' ' || text[at - 1] == '\t';
    return count;
}

// Reads the MTL files an OBJ names as every other input is read: regular
// files only, each once, within kMaxMtlBytes and kMaxMaterials for all of
// them together. A missing, refused or skipped MTL is a warning, as
// tinyobjloader's own reader makes it.
class BoundedMaterialReader : public tinyobj::MaterialReader {
  public:
    explicit BoundedMaterialReader(std::filesystem::path folder) : folder_(std::move(folder)) {}
    bool operator()(const std::string& file, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warning,
                    std::string*) override {
        const std::filesystem::path path = folder_ / file;
        std::error_code ec;
        const std::filesystem::path key = std::filesystem::weakly_canonical(path, ec);
        if (!read_.insert(ec ? path : key).second) return true;  // read already: nothing new
        try {
            const std::vector<std::uint8_t> bytes = read_file(path, kMaxMtlBytes - bytes_);
            bytes_ += bytes.size();
            const std::string text(bytes.begin(), bytes.end());
            const std::size_t count = count_materials(text);
            if (materials->size() + count > kMaxMaterials) {
                *warning += "material file " + path.string() + ": defines " +
                            std::to_string(count) + " materials, past the " +
                            std::to_string(kMaxMaterials) +
                            " a model's MTL files may hold together; skipped\n";
                return false;
            }
            std::istringstream in(text);
            std::string mtl_warning;
            tinyobj::LoadMtl(names, materials, &in, &mtl_warning, nullptr);
            *warning += mtl_warning;
            return true;
        } catch (const FileError& e) {
            *warning += std::string("material file ") + e.what() +
                        (bytes_ > 0 ? " (with the model's other MTL files)" : "") + "\n";
            return false;
        }
    }

  private:
    std::filesystem::path folder_;
    std::set<std::filesystem::path> read_;
    std::uintmax_t bytes_ = 0;  // read so far, of kMaxMtlBytes
};

// Material text given directly (for tests): every mtllib reads it.
class TextMaterialReader : public tinyobj::MaterialReader {
  public:
    explicit TextMaterialReader(std::string_view text) : text_(text) {}
    bool operator()(const std::string&, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warning,
                    std::string*) override {
        std::istringstream in(text_);
        tinyobj::LoadMtl(names, materials, &in, warning, nullptr);
        return true;
    }

  private:
    std::string text_;
};

Parsed parse(std::string_view obj_text, tinyobj::MaterialReader& materials,
             const std::string& name) {
    validate_obj_text(obj_text, name);
    Parsed parsed;
    try {
        std::istringstream in{std::string(obj_text)};
        parsed.ok = tinyobj::LoadObj(&parsed.attrib, &parsed.shapes, &parsed.materials,
                                     &parsed.warning, &parsed.error, &in, &materials,
                                     /*triangulate=*/true, /*default_vcols_fallback=*/false);
    } catch (const std::bad_alloc&) {
        throw MeshError(name, "out of memory parsing the OBJ");
    }
    return parsed;
}

bool all_finite(const std::vector<tinyobj::real_t>& values) {
    for (tinyobj::real_t v : values)
        if (!std::isfinite(v)) return false;
    return true;
}

// Texture coordinates far from 0 are coarse in a float: at 65536 the step
// between two floats is 1/128 of the texture, and at 2^24 it is 2 whole
// periods. The digits are lost when the file is read (the parser keeps
// floats), so the picture differs from the same coordinates moved towards 0
// by whole numbers, which `repeat` would draw alike. From 1024 on (a step of
// 1/8192: an eighth of a texel of a 1024-texel map) it is said.
void warn_of_coarse_texture_coordinates(const std::vector<vec2>& uvs, const std::string& name,
                                        std::vector<std::string>& warnings) {
    float largest = 0;
    for (const vec2& uv : uvs) largest = std::max({largest, std::abs(uv.x), std::abs(uv.y)});
    if (largest < kCoarseTextureCoordinate) return;
    const float step = std::nextafter(largest, std::numeric_limits<float>::infinity()) - largest;
    char text[400];
    std::snprintf(text, sizeof text,
                  "%s: texture coordinates reach %g, where a float steps by %g of the texture's "
                  "width: the file's digits are lost when it is read, and the picture differs "
                  "from the same coordinates moved by whole numbers towards 0 (do that)",
                  name.c_str(), static_cast<double>(largest), static_cast<double>(step));
    warnings.push_back(text);
}

Mesh convert(const Parsed& parsed, const std::string& name,
             const std::filesystem::path& material_folder, std::vector<std::string>* warnings) {
    if (!parsed.ok) throw MeshError(name, "cannot load OBJ: " + parsed.error);
    for (const std::string& line : split_lines(parsed.warning)) {
        for (std::string_view fatal : kFatalWarnings)
            if (line.find(fatal) != std::string::npos)
                throw MeshError(name, "malformed OBJ: " + line +
                                          " (faces need three or more valid vertex indices)");
        if (warnings) warnings->push_back(name + ": " + line);
    }
    // validate_obj_text() has refused every non-finite number in the text;
    // this is the same rule checked on what the parser made of it.
    if (!all_finite(parsed.attrib.vertices) || !all_finite(parsed.attrib.texcoords) ||
        !all_finite(parsed.attrib.normals))
        throw MeshError(name, "a coordinate is not a finite number");

    const tinyobj::attrib_t& attrib = parsed.attrib;
    Mesh mesh;
    mesh.source = name;
    for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
        mesh.positions.push_back(
            {attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
    for (std::size_t i = 0; i + 1 < attrib.texcoords.size(); i += 2)
        mesh.uvs.push_back({attrib.texcoords[i], attrib.texcoords[i + 1]});
    for (std::size_t i = 0; i + 2 < attrib.normals.size(); i += 3)
        mesh.normals.push_back({attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]});
    if (warnings) warn_of_coarse_texture_coordinates(mesh.uvs, name, *warnings);

    for (const tinyobj::shape_t& shape : parsed.shapes) {
        const auto& indices = shape.mesh.indices;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            if (shape.mesh.num_face_vertices[f] != 3)
                throw MeshError(name, "face with " +
                                          std::to_string(shape.mesh.num_face_vertices[f]) +
                                          " vertices was not triangulated");
            Face t;
            t.material = shape.mesh.material_ids[f];
            for (int k = 0; k < 3; ++k) {
                const tinyobj::index_t& idx = indices[3 * f + static_cast<std::size_t>(k)];
                Corner& c = t.corners[static_cast<std::size_t>(k)];
                c.position = checked_index(idx.vertex_index, mesh.positions.size(), "vertex", name);
                if (c.position < 0) throw MeshError(name, "face corner without a vertex index");
                c.uv =
                    checked_index(idx.texcoord_index, mesh.uvs.size(), "texture coordinate", name);
                c.normal = checked_index(idx.normal_index, mesh.normals.size(), "normal", name);
            }
            mesh.faces.push_back(t);
        }
    }
    if (mesh.faces.empty()) throw MeshError(name, "OBJ holds no faces");

    auto resolve = [&](const std::string& file) {
        return file.empty() ? std::filesystem::path{} : material_folder / file;
    };
    for (const tinyobj::material_t& m : parsed.materials) {
        Material material;
        material.name = m.name;
        material.diffuse = resolve(m.diffuse_texname);
        material.normal_tangent = resolve(m.bump_texname);
        material.normal_object = resolve(m.normal_texname);
        material.specular = resolve(m.specular_texname);
        mesh.materials.push_back(material);
    }
    for (const Face& t : mesh.faces)
        if (t.material >= static_cast<int>(mesh.materials.size()))
            throw MeshError(name, "face refers to material " + std::to_string(t.material) +
                                      " that no MTL file defines");
    return mesh;
}

}  // namespace

std::uintmax_t max_obj_bytes() {
    const char* text = std::getenv("RASTERLAB_MAX_OBJ_MB");
    if (!text) return kDefaultMaxObjBytes;
    const std::string value = text;
    // Digits only: strtoull would take " 5", "+5" or "-5" (as a huge number).
    const bool digits = !value.empty() && value.size() <= 7 &&
                        value.find_first_not_of("0123456789") == std::string::npos;
    const unsigned long long mib = digits ? std::strtoull(text, nullptr, 10) : 0;
    if (mib < 1 || mib > (1ull << 20))
        throw std::invalid_argument("RASTERLAB_MAX_OBJ_MB='" + value +
                                    "': need a whole number of MiB from 1 to 1048576");
    return mib << 20;
}

Mesh load_obj(const std::filesystem::path& path, std::vector<std::string>* warnings) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw MeshError(path, "no such file");
    const std::uintmax_t cap = max_obj_bytes();
    // Over the cap: say how to raise it (and only then: a folder or a device
    // is not helped by a larger cap).
    if (std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) > cap &&
        !ec)
        throw MeshError(path, "is " + std::to_string(std::filesystem::file_size(path, ec) >> 20) +
                                  " MiB, more than the " + std::to_string(cap >> 20) +
                                  " MiB this program reads (set RASTERLAB_MAX_OBJ_MB to raise the "
                                  "cap)");
    std::vector<std::uint8_t> bytes;
    try {
        bytes = read_file(path, cap);
    } catch (const FileError& e) {
        throw MeshError(path, std::string(e.what()).substr(path.string().size() + 2));
    }
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    BoundedMaterialReader materials(path.parent_path());
    Mesh mesh =
        convert(parse(text, materials, path.string()), path.string(), path.parent_path(), warnings);
    mesh.source = path;
    return mesh;
}

Mesh parse_obj(std::string_view obj_text, std::string_view mtl_text, const std::string& name,
               std::vector<std::string>* warnings) {
    TextMaterialReader materials(mtl_text);
    return convert(parse(obj_text, materials, name), name,
                   std::filesystem::path(name).parent_path(), warnings);
}

}  // namespace rl
