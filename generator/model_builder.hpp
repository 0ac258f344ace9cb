// Building a model in memory and writing it as OBJ + MTL text, with fixed
// number formatting so that the output is byte-for-byte reproducible.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "rasterlab/vec.hpp"

namespace assets {

using rl::dvec2;
using rl::dvec3;

struct Face {
    std::array<int, 3> position, uv, normal;  // 0-based; the writer adds 1
};

struct Model {
    std::string name;     // file stem: <name>.obj, <name>.mtl, <name>_diffuse.png, ...
    std::string comment;  // first lines of the OBJ, saying what the model is
    std::vector<std::string> mtl_lines;  // texture statements of the one material
    std::vector<dvec3> positions;
    std::vector<dvec2> uvs;
    std::vector<dvec3> normals;
    std::vector<Face> faces;  // counter-clockwise seen from outside

    int add_position(dvec3 p);
    int add_uv(dvec2 t);
    int add_normal(dvec3 n);
    void add_face(std::array<int, 3> p, std::array<int, 3> t, std::array<int, 3> n);
};

// Vertex normals as the area-weighted mean of the adjacent faces' normals,
// one per position; sets every face's normal indices to its positions.
void compute_smooth_normals(Model& model);

// Writes <dir>/<name>.obj and <dir>/<name>.mtl.
void write_model(const std::filesystem::path& dir, const Model& model);

}  // namespace assets
