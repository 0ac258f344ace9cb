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
    // In double: a UV of 2.6e34 or an edge of 1e20 would overflow the
    // products in float and leave an infinite tangent.
    const auto position = [&](int k) { return rl::cast<double>(mesh.position(face, k)); };
    const auto uv = [&](int k) { return rl::cast<double>(uv_of(mesh, face, k)); };
    const rl::dvec3 e1 = position(1) - position(0), e2 = position(2) - position(0);
    const rl::dvec2 d1 = uv(1) - uv(0), d2 = uv(2) - uv(0);
    const double det = rl::cross(d1, d2);     // du1 dv2 - du2 dv1: twice the UV area, signed
    if (!(std::abs(det) > 1e-12)) return {};  // no UV area (or NaN): no frame fits
    const rl::dvec3 t = (e1 * d2.y - e2 * d1.y) / det, b = (e2 * d1.x - e1 * d2.x) / det;
    FaceFrame f{rl::cast<float>(rl::normalize(t)), rl::cast<float>(rl::normalize(b)), true};
    f.valid = finite(f.tangent) && finite(f.bitangent) && rl::length(f.tangent) > 0.5f &&
              rl::length(f.bitangent) > 0.5f;
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
    // at the vertex (in double: the weight of a face 1e19 across overflows a
    // float).
    // `split` opens a new slot for a face whose frame disagrees with every
    // slot's: opposite handedness (mirrored UVs), or a tangent more than 45
    // degrees from the slot's (UVs turned, as an island rotated 90 degrees
    // is). Past kMaxSlots slots at a position, a face that agrees with none
    // joins the nearest of its handedness (one more slot opens only if all
    // share the other handedness: at most kMaxSlots + 1), so the work stays
    // linear in the faces around a vertex however many there are.
    struct Slot {
        rl::dvec3 tangent, bitangent;
        bool right_handed;
    };
    constexpr std::size_t kMaxSlots = 8;
    constexpr double kSplitCosine = 0.70710678;  // cos 45 degrees
    const auto agreement = [](const Slot& slot, const rl::dvec3& t) {
        return rl::dot(rl::normalize(slot.tangent), t);  // (a zero slot agrees with nothing)
    };
    std::vector<std::vector<Slot>> slots(mesh.positions.size());
    std::vector<std::size_t> slot_of(mesh.faces.size() * 3, 0);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        if (!frames[f].valid) continue;
        const rl::Face& face = mesh.faces[f];
        const rl::dvec3 twice_area = shading::area_normal(mesh, face);
        const rl::dvec3 n = rl::normalize(twice_area);
        const double area = rl::length(twice_area) / 2;
        const rl::dvec3 t = rl::cast<double>(frames[f].tangent),
                        b = rl::cast<double>(frames[f].bitangent);
        const bool right_handed = rl::dot(rl::cross(t, b), n) > 0;
        for (int k = 0; k < 3; ++k) {
            auto& here =
                slots[static_cast<std::size_t>(face.corners[static_cast<std::size_t>(k)].position)];
            std::size_t s = 0;
            if (method == TangentMethod::split) {
                std::size_t nearest = here.size();
                double best = -2;
                for (s = 0; s < here.size(); ++s) {
                    if (here[s].right_handed != right_handed) continue;
                    const double a = agreement(here[s], t);
                    if (a > kSplitCosine) break;
                    if (nearest == here.size() || a > best) best = a, nearest = s;  // (a NaN a too)
                }
                if (s == here.size() && here.size() >= kMaxSlots && nearest < here.size())
                    s = nearest;
            }
            if (s == here.size()) here.push_back({{}, {}, right_handed});
            // The weight: the face's area (a big face counts more) times its
            // angle here (so that cutting a face in two does not count it twice).
            const double weight = shading::corner_angle(mesh, face, k) * area;
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
            out[3 * f + k] = orthonormal_frame(n, rl::cast<float>(rl::normalize(s.tangent)),
                                               rl::cast<float>(rl::normalize(s.bitangent)));
        }
    return out;
}
// [/doc:corner-tangents]

}  // namespace normal_mapping
