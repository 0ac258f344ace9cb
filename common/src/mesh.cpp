#include "rasterlab/mesh.hpp"

#include <tiny_obj_loader.h>

#include <sstream>

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

Mesh convert(const tinyobj::ObjReader& reader, const std::string& name,
             const std::filesystem::path& material_folder, std::vector<std::string>* warnings) {
    if (!reader.Valid()) throw MeshError(name, "cannot load OBJ: " + reader.Error());
    for (const std::string& line : split_lines(reader.Warning())) {
        for (std::string_view fatal : kFatalWarnings)
            if (line.find(fatal) != std::string::npos)
                throw MeshError(name, "malformed OBJ: " + line +
                                          " (faces need three or more valid vertex indices)");
        if (warnings) warnings->push_back(name + ": " + line);
    }

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    Mesh mesh;
    mesh.source = name;
    for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
        mesh.positions.push_back(
            {attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
    for (std::size_t i = 0; i + 1 < attrib.texcoords.size(); i += 2)
        mesh.uvs.push_back({attrib.texcoords[i], attrib.texcoords[i + 1]});
    for (std::size_t i = 0; i + 2 < attrib.normals.size(); i += 3)
        mesh.normals.push_back({attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]});

    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& indices = shape.mesh.indices;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            if (shape.mesh.num_face_vertices[f] != 3)
                throw MeshError(name, "face with " +
                                          std::to_string(shape.mesh.num_face_vertices[f]) +
                                          " vertices was not triangulated");
            Triangle t;
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
            mesh.triangles.push_back(t);
        }
    }
    if (mesh.triangles.empty()) throw MeshError(name, "OBJ holds no faces");

    auto resolve = [&](const std::string& file) {
        return file.empty() ? std::filesystem::path{} : material_folder / file;
    };
    for (const tinyobj::material_t& m : reader.GetMaterials()) {
        Material material;
        material.name = m.name;
        material.diffuse = resolve(m.diffuse_texname);
        material.normal_tangent = resolve(m.bump_texname);
        material.normal_object = resolve(m.normal_texname);
        material.specular = resolve(m.specular_texname);
        mesh.materials.push_back(material);
    }
    for (const Triangle& t : mesh.triangles)
        if (t.material >= static_cast<int>(mesh.materials.size()))
            throw MeshError(name, "face refers to material " + std::to_string(t.material) +
                                      " that no MTL file defines");
    return mesh;
}

tinyobj::ObjReaderConfig reader_config() {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    return config;
}

}  // namespace

Mesh load_obj(const std::filesystem::path& path, std::vector<std::string>* warnings) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw MeshError(path,
                        std::filesystem::exists(path, ec) ? "not a regular file" : "no such file");
    tinyobj::ObjReaderConfig config = reader_config();
    config.mtl_search_path = path.parent_path().string();
    tinyobj::ObjReader reader;
    reader.ParseFromFile(path.string(), config);
    Mesh mesh = convert(reader, path.string(), path.parent_path(), warnings);
    mesh.source = path;
    return mesh;
}

Mesh parse_obj(std::string_view obj_text, std::string_view mtl_text, const std::string& name,
               std::vector<std::string>* warnings) {
    tinyobj::ObjReader reader;
    reader.ParseFromString(std::string(obj_text), std::string(mtl_text), reader_config());
    return convert(reader, name, std::filesystem::path(name).parent_path(), warnings);
}

}  // namespace rl
