#include "normals.hpp"

#include <cmath>

namespace shading {

namespace {
rl::dvec3 position(const rl::Mesh& mesh, const rl::Face& face, int k) {
    return rl::cast<double>(mesh.position(face, k));
}
}  // namespace

rl::dvec3 area_normal(const rl::Mesh& mesh, const rl::Face& face) {
    const rl::dvec3 p0 = position(mesh, face, 0);
    return rl::cross(position(mesh, face, 1) - p0, position(mesh, face, 2) - p0);
}

double corner_angle(const rl::Mesh& mesh, const rl::Face& face, int k) {
    const rl::dvec3 p = position(mesh, face, k);
    const rl::dvec3 a = position(mesh, face, (k + 1) % 3) - p,
                    b = position(mesh, face, (k + 2) % 3) - p;
    const double la = rl::length(a), lb = rl::length(b);
    if (!(la > 0 && lb > 0)) return 0;
    return std::acos(std::clamp(rl::dot(a, b) / (la * lb), -1.0, 1.0));
}

// [doc:vertex-normals]
std::vector<rl::vec3> vertex_normals(const rl::Mesh& mesh, Weighting weighting) {
    std::vector<rl::dvec3> sum(mesh.positions.size());
    for (const rl::Face& face : mesh.faces) {
        const rl::dvec3 n = area_normal(mesh, face);  // length: twice the area
        const rl::dvec3 unit = rl::normalize(n);
        for (int k = 0; k < 3; ++k) {
            const rl::dvec3 add =
                weighting == Weighting::area ? n : unit * corner_angle(mesh, face, k);
            sum[static_cast<std::size_t>(face.corners[static_cast<std::size_t>(k)].position)] +=
                add;
        }
    }
    std::vector<rl::vec3> out;
    out.reserve(sum.size());
    for (const rl::dvec3& n : sum) out.push_back(rl::cast<float>(rl::normalize(n)));  // 0 stays 0
    return out;
}
// [/doc:vertex-normals]

std::vector<rl::vec3> corner_normals(const rl::Mesh& mesh, Weighting weighting,
                                     std::size_t* computed) {
    std::vector<rl::vec3> averaged;  // computed only if some corner needs it
    std::vector<rl::vec3> out;
    out.reserve(mesh.faces.size() * 3);
    std::size_t not_from_obj = 0;
    for (const rl::Face& face : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const rl::Corner& c = face.corners[static_cast<std::size_t>(k)];
            rl::vec3 n{};
            if (c.normal >= 0) n = rl::normalize(mesh.normals[static_cast<std::size_t>(c.normal)]);
            if (rl::length(n) == 0) {
                ++not_from_obj;
                if (averaged.empty()) averaged = vertex_normals(mesh, weighting);
                n = averaged[static_cast<std::size_t>(c.position)];
                if (rl::length(n) == 0) n = rl::cast<float>(rl::normalize(area_normal(mesh, face)));
            }
            out.push_back(n);
        }
    if (computed) *computed = not_from_obj;
    return out;
}

// [doc:normal-matrix]
std::optional<rl::mat3> normal_matrix(const rl::mat4& model) {
    const std::optional<rl::mat3> inverse = rl::inverse(rl::linear_part(model));
    if (!inverse) return std::nullopt;
    return rl::transpose(*inverse);
}
// [/doc:normal-matrix]

}  // namespace shading
