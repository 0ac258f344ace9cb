// Triangle meshes loaded from Wavefront OBJ files through tinyobjloader.
//
//   std::vector<std::string> warnings;
//   const rl::Mesh mesh = rl::load_obj(rl::project_model("rock"), &warnings);  // obj/rock.obj
//   for (const rl::Face& face : mesh.faces)
//       draw(mesh.position(face, 0), mesh.position(face, 1), mesh.position(face, 2));
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "rasterlab/file_io.hpp"
#include "rasterlab/vec.hpp"

namespace rl {

class MeshError : public FileError {
  public:
    using FileError::FileError;
};

// One corner of a triangle: indices into the mesh's arrays; -1 where the OBJ
// gave no texture coordinate or normal.
struct Corner {
    int position = 0;
    int uv = -1;
    int normal = -1;
};

// A face of the mesh, always a triangle: three corners of indices.
struct Face {
    std::array<Corner, 3> corners;
    int material = -1;  // index into Mesh::materials, -1 for none
};

// Texture file names as the MTL file gives them, resolved against its folder.
struct Material {
    std::string name;
    std::filesystem::path diffuse;         // map_Kd
    std::filesystem::path normal_tangent;  // map_Bump / bump (tangent-space normal map)
    std::filesystem::path normal_object;   // norm (object-space normal map)
    std::filesystem::path specular;        // map_Ks
};

struct Mesh {
    std::filesystem::path source;  // the OBJ file, for texture discovery and messages
    std::vector<vec3> positions;
    std::vector<vec2> uvs;
    std::vector<vec3> normals;
    std::vector<Face> faces;  // polygons are triangulated on loading
    std::vector<Material> materials;

    vec3 position(const Face& t, int corner) const { return positions[t.corners[corner].position]; }
};

// The largest OBJ file load_obj() reads: 256 MiB, unless the environment
// variable RASTERLAB_MAX_OBJ_MB says otherwise (a whole number of MiB).
inline constexpr std::uintmax_t kDefaultMaxObjBytes = std::uintmax_t{256} << 20;
std::uintmax_t max_obj_bytes();

// Vertices one face may have: tinyobjloader triangulates by ear clipping,
// whose time grows with the square of the count (4096 take milliseconds,
// 10^5 took 23 s).
inline constexpr std::size_t kMaxFaceVertices = 4096;

// The most MTL text one model's files may hold together: 16 MiB (an MTL
// holds a few lines per material), and the most materials they may define:
// 4096 (each takes about 2 KB parsed; a 16 MiB MTL of bare `newmtl` lines
// once took 3.85 GB). Each MTL file is read once however many `mtllib`
// lines name it; files past either bound are skipped with a warning.
inline constexpr std::uintmax_t kMaxMtlBytes = std::uintmax_t{16} << 20;
inline constexpr std::size_t kMaxMaterials = 4096;
// Texture coordinates from this magnitude on are coarse in a float (a step
// of 1/8192 of the texture at 1024): load_obj() warns of them.
inline constexpr float kCoarseTextureCoordinate = 1024;

// Loads an OBJ and its MTL files. Throws MeshError naming the file and the
// problem (with tinyobjloader's own message) for an unreadable or malformed
// file: index 0 or out of range, a face of fewer than three vertices or more
// than kMaxFaceVertices, a coordinate that is not a finite float, a file
// over max_obj_bytes(). Details: docs/robustness.md.
// Warnings that do not stop loading are appended to `warnings`.
Mesh load_obj(const std::filesystem::path& path, std::vector<std::string>* warnings = nullptr);

// The path of one of the project's own models, e.g. project_model("rock")
// for obj/rock.obj: what the lessons load when given no --model.
inline std::filesystem::path project_model(const std::string& name) {
    return std::filesystem::path(RASTERLAB_OBJ_DIR) / (name + ".obj");
}

// The same from text, for tests; `name` stands for the file in messages.
Mesh parse_obj(std::string_view obj_text, std::string_view mtl_text, const std::string& name,
               std::vector<std::string>* warnings = nullptr);

}  // namespace rl
