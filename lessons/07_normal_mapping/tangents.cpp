#include "tangents.hpp"

#include "06_shading/normals.hpp"

#include <cmath>

namespace normal_mapping {

namespace {

bool finite(rl::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

rl::vec2 uv_of(const rl::Mesh& mesh, const rl::Face& face, int k) {
    const int t = face.corners[static_cast<std::size_t>(k)].uv;
    return t >= 0 ? mesh.uvs[static_cast<std::size_t>(t)] : rl::vec2{};
}

// T orthogonalised against n (Gram-Schmidt), with the handedness of B.
rl::vec4 orthonormal_frame(rl::vec3 n, rl::vec3 t, rl::vec3 b) {
    rl::vec3 tangent = rl::normalize(t - n * rl::dot(n, t));
    if (!(rl::length(tangent) > 0.5f)) tangent = any_tangent(n);  // t was zero or along n
    const float w = rl::dot(rl::cross(n, tangent), b) < 0 ? -1.0f : 1.0f;
    return {tangent.x, tangent.y, tangent.z, w};
}

}  // namespace

// [doc:face-frame]
FaceFrame face_frame(const rl::Mesh& mesh, const rl::Face& face) {
    const rl::vec3 e1 = mesh.position(face, 1) - mesh.position(face, 0);
    const rl::vec3 e2 = mesh.position(face, 2) - mesh.position(face, 0);
    const rl::vec2 d1 = uv_of(mesh, face, 1) - uv_of(mesh, face, 0);
    const rl::vec2 d2 = uv_of(mesh, face, 2) - uv_of(mesh, face, 0);
    const float det = rl::cross(d1, d2);       // du1 dv2 - du2 dv1: twice the UV area, signed
    if (!(std::abs(det) > 1e-12f)) return {};  // no UV area (or NaN): no frame fits
    const float inverse = 1 / det;
    FaceFrame f{(e1 * d2.y - e2 * d1.y) * inverse, (e2 * d1.x - e1 * d2.x) * inverse, true};
    f.valid = finite(f.tangent) && finite(f.bitangent);
    return f;
}
// [/doc:face-frame]

rl::vec3 any_tangent(rl::vec3 n) {
    // Cross n with the axis it is least aligned with.
    const rl::vec3 a =
        std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z)
            ? rl::vec3{1, 0, 0}
            : (std::abs(n.y) <= std::abs(n.z) ? rl::vec3{0, 1, 0} : rl::vec3{0, 0, 1});
    const rl::vec3 t = rl::normalize(rl::cross(a, n));
    return rl::length(t) > 0 ? t : rl::vec3{1, 0, 0};
}

// [doc:corner-tangents]
std::vector<rl::vec4> corner_tangents(const rl::Mesh& mesh, const std::vector<rl::vec3>& normals,
                                      TangentMethod method) {
    std::vector<rl::vec4> out(mesh.faces.size() * 3);
    std::vector<FaceFrame> frames;
    frames.reserve(mesh.faces.size());
    for (const rl::Face& face : mesh.faces) frames.push_back(face_frame(mesh, face));
    if (method == TangentMethod::face) {
        for (std::size_t f = 0; f < mesh.faces.size(); ++f)
            for (std::size_t k = 0; k < 3; ++k)
                out[3 * f + k] =
                    orthonormal_frame(normals[3 * f + k], frames[f].tangent, frames[f].bitangent);
        return out;
    }
    // Per vertex: each position holds one or more slots, each summing the
    // unit T and B of its faces weighted by the face's area times its angle
    // at the vertex.
    // `split` opens a new slot for a face whose UVs run the other way
    // (opposite handedness) or turn away (T + B against the slot's).
    struct Slot {
        rl::vec3 tangent, bitangent;
        bool right_handed;
    };
    std::vector<std::vector<Slot>> slots(mesh.positions.size());
    std::vector<std::size_t> slot_of(mesh.faces.size() * 3, 0);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        if (!frames[f].valid) continue;
        const rl::Face& face = mesh.faces[f];
        const rl::vec3 twice_area = rl::cross(mesh.position(face, 1) - mesh.position(face, 0),
                                              mesh.position(face, 2) - mesh.position(face, 0));
        const rl::vec3 n = rl::normalize(twice_area);
        const float area = rl::length(twice_area) / 2;
        const rl::vec3 t = rl::normalize(frames[f].tangent), b = rl::normalize(frames[f].bitangent);
        const bool right_handed = rl::dot(rl::cross(t, b), n) > 0;
        for (int k = 0; k < 3; ++k) {
            auto& here =
                slots[static_cast<std::size_t>(face.corners[static_cast<std::size_t>(k)].position)];
            std::size_t s = 0;
            if (method == TangentMethod::split)
                for (; s < here.size(); ++s) {
                    const rl::vec3 half = here[s].tangent + here[s].bitangent;
                    if (here[s].right_handed == right_handed &&
                        rl::dot(t + b, half - n * rl::dot(half, n)) >= 0)
                        break;
                }
            if (s == here.size()) here.push_back({{}, {}, right_handed});
            // The seed notes' weight: the face's area times its angle here.
            const float weight = shading::corner_angle(mesh, face, k) * area;
            here[s].tangent += t * weight;
            here[s].bitangent += b * weight;
            slot_of[3 * f + static_cast<std::size_t>(k)] = s;
        }
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (std::size_t k = 0; k < 3; ++k) {
            const auto& here = slots[static_cast<std::size_t>(mesh.faces[f].corners[k].position)];
            const rl::vec3 n = normals[3 * f + k];
            if (!frames[f].valid || here.empty()) {  // no UVs here: any frame will do
                out[3 * f + k] = orthonormal_frame(n, any_tangent(n), rl::cross(n, any_tangent(n)));
                continue;
            }
            const Slot& s = here[slot_of[3 * f + k]];
            out[3 * f + k] = orthonormal_frame(n, s.tangent, s.bitangent);
        }
    return out;
}
// [/doc:corner-tangents]

}  // namespace normal_mapping
