// Tangent frames: at every corner, the directions in which the texture's u
// and v grow on the surface (tangent T and bitangent B) beside the normal N,
// so that a tangent-space normal map's (r, g, b) = (T, B, N) components can
// be turned into a direction. Three ways, compared in the lab:
//   face    each face's own frame, from its UV edges;
//   vertex  frames averaged over the faces around each vertex (weighted by
//           each face's area times its angle at the vertex);
//   split   the same, but a vertex's faces whose frames disagree (UVs
//           mirrored, or turned more than 45 degrees from each other) get
//           separate frames, as a seam needs.
// Each frame is orthogonalised against the corner's normal and stored as
// (T, w): B = w * cross(N, T), w = +1 or -1 (the UVs' handedness).
// Derivations: docs/07_normal_mapping.md#tangent-frames.
//
//   const std::vector<rl::vec4> t =
//       normal_mapping::corner_tangents(mesh, normals, normal_mapping::TangentMethod::split);
#pragma once

#include <vector>

#include "rasterlab/mesh.hpp"
#include "rasterlab/named_enum.hpp"

namespace normal_mapping {

enum class TangentMethod { face, vertex, split };
RASTERLAB_NAMED_ENUM(TangentMethod, kTangentMethods, {TangentMethod::face, "face"},
                     {TangentMethod::vertex, "vertex"}, {TangentMethod::split, "split"});

// A face's T and B, as unit vectors: the directions of the solution of
// [e1; e2] = [du1 dv1; du2 dv2] [T; B] for its edges e1, e2 and their UV
// differences. `valid` is false when the UV triangle has no area (or a
// coordinate is not finite): then no T and B fit, and the face takes a frame
// built from its normal alone.
struct FaceFrame {
    rl::vec3 tangent, bitangent;
    bool valid = false;
};
FaceFrame face_frame(const rl::Mesh& mesh, const rl::Face& face);

// Any unit tangent perpendicular to n (for faces without usable UVs).
rl::vec3 any_tangent(rl::vec3 n);

// (T, w) at every corner (index 3 * face + corner), for the given corner
// normals (shading::corner_normals).
std::vector<rl::vec4> corner_tangents(const rl::Mesh& mesh, const std::vector<rl::vec3>& normals,
                                      TangentMethod method);

}  // namespace normal_mapping
