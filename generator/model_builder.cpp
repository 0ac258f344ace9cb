#include "model_builder.hpp"

#include <cstdio>

#include "rasterlab/file_io.hpp"

namespace assets {

int Model::add_position(dvec3 p) {
    positions.push_back(p);
    return static_cast<int>(positions.size()) - 1;
}

int Model::add_uv(dvec2 t) {
    uvs.push_back(t);
    return static_cast<int>(uvs.size()) - 1;
}

int Model::add_normal(dvec3 n) {
    normals.push_back(rl::normalize(n));
    return static_cast<int>(normals.size()) - 1;
}

void Model::add_face(std::array<int, 3> p, std::array<int, 3> t, std::array<int, 3> n) {
    faces.push_back({p, t, n});
}

void compute_smooth_normals(Model& model) {
    std::vector<dvec3> sums(model.positions.size());
    for (const Face& f : model.faces) {
        const dvec3 a = model.positions[f.position[0]];
        // The cross product's length is twice the face's area: weighting by it
        // keeps slivers from tilting their neighbours' normals.
        const dvec3 n =
            rl::cross(model.positions[f.position[1]] - a, model.positions[f.position[2]] - a);
        for (int p : f.position) sums[p] += n;
    }
    model.normals.clear();
    for (const dvec3& s : sums) model.add_normal(s);
    for (Face& f : model.faces) f.normal = f.position;
}

namespace {

// "%.6f" with negative zero printed as zero, so that tiny rounding noise in
// sin/cos cannot flip a sign character between runs.
void append_number(std::string& out, double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6f", value);
    if (std::string(buffer) == "-0.000000") std::snprintf(buffer, sizeof buffer, "%.6f", 0.0);
    out += buffer;
}

template <std::size_t N>
void append_vector(std::string& out, const char* keyword, const rl::Vec<N, double>& v) {
    out += keyword;
    for (std::size_t i = 0; i < N; ++i) {
        out += ' ';
        append_number(out, v[i]);
    }
    out += '\n';
}

void write_text(const std::filesystem::path& path, const std::string& text) {
    rl::write_file_atomically(
        path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

}  // namespace

void write_model(const std::filesystem::path& dir, const Model& model) {
    std::string obj = model.comment + "# made by rasterlab's generator (generator/), do not edit\n";
    obj += "mtllib " + model.name + ".mtl\n";
    for (const dvec3& p : model.positions) append_vector(obj, "v", p);
    for (const dvec2& t : model.uvs) append_vector(obj, "vt", t);
    for (const dvec3& n : model.normals) append_vector(obj, "vn", n);
    obj += "usemtl " + model.name + "\n";
    for (const Face& f : model.faces) {
        char line[128];  // nine numbers of at most 11 characters each
        std::snprintf(line, sizeof line, "f %d/%d/%d %d/%d/%d %d/%d/%d\n", f.position[0] + 1,
                      f.uv[0] + 1, f.normal[0] + 1, f.position[1] + 1, f.uv[1] + 1, f.normal[1] + 1,
                      f.position[2] + 1, f.uv[2] + 1, f.normal[2] + 1);
        obj += line;
    }
    write_text(dir / (model.name + ".obj"), obj);

    std::string mtl = "newmtl " + model.name + "\nKa 0 0 0\nKd 1 1 1\nKs 1 1 1\nNs 32\n";
    for (const std::string& line : model.mtl_lines) mtl += line + '\n';
    write_text(dir / (model.name + ".mtl"), mtl);
}

}  // namespace assets
