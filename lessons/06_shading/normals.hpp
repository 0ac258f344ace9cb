// Normals: of a face (from its edges), of a vertex (averaged over the faces
// around it, by area or by angle, when the OBJ gives none), and how they
// transform (the normal matrix: the inverse transpose of the model's 3x3).
// Derivations: docs/06_shading.md#normals.
//
//   const std::vector<rl::vec3> n = shading::corner_normals(mesh, shading::Weighting::angle);
//   const rl::mat3 to_world = shading::normal_matrix(model);  // then normalize(to_world * n)
#pragma once

#include <optional>
#include <vector>

#include "rasterlab/mat.hpp"
#include "rasterlab/mesh.hpp"
#include "rasterlab/named_enum.hpp"
#include "rasterlab/transform.hpp"

namespace shading {

// Twice the face's area times its unit normal: counter-clockwise faces point
// towards the side they are seen counter-clockwise from. In double: the
// cross product of float edges longer than about 1.9e19 overflows a float,
// and one such face would make every vertex normal it touches infinite.
rl::dvec3 area_normal(const rl::Mesh& mesh, const rl::Face& face);

// The angle of the face at its corner k, in radians (0 when an edge there
// has no length), in double for the same reason.
double corner_angle(const rl::Mesh& mesh, const rl::Face& face, int k);

// How a vertex's faces are weighted when its normal is their average: by
// area (a big face counts more), or by the angle the face makes at the
// vertex (independent of how the surface was cut into triangles).
enum class Weighting { area, angle };
RASTERLAB_NAMED_ENUM(Weighting, kWeightings, {Weighting::area, "area"},
                     {Weighting::angle, "angle"});

// One unit normal per vertex position, averaged over the faces that use it.
// A degenerate face (zero area, or a zero-length edge at the vertex) adds
// nothing; a vertex whose faces cancel out or are all degenerate gets zero.
std::vector<rl::vec3> vertex_normals(const rl::Mesh& mesh, Weighting weighting);

// The normal at every corner of every face (index 3 * face + corner): the
// OBJ's own where it gives one of non-zero length, else the averaged vertex
// normal, else the face's normal. `computed` counts the corners not from the OBJ.
std::vector<rl::vec3> corner_normals(const rl::Mesh& mesh, Weighting weighting,
                                     std::size_t* computed = nullptr);

// The matrix that takes normals to world space for a model matrix M: the
// inverse transpose of M's upper 3x3 (equal to it for rotations; different
// under non-uniform scale). Empty when M's 3x3 is singular.
std::optional<rl::mat3> normal_matrix(const rl::mat4& model);

}  // namespace shading
