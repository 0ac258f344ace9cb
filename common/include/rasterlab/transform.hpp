// The transforms every lesson from 03 on needs, in OpenGL's conventions
// (right-handed, column vectors, the camera looking down -z, NDC in [-1, 1]):
// rotations, quaternions, translate-rotate-scale models and their
// decomposition, the look-at view, the perspective projection, and the
// viewport. tests/unit/transform_test.cpp checks each against the property
// that defines it (look_at puts the eye at the origin, perspective sends the
// near plane to NDC z = -1, ...).
//
//   const rl::mat4 model = rl::compose({.translation = {0, 1, 0},
//                                       .rotation = rl::axis_angle({0, 1, 0}, 30),
//                                       .scale = {2, 2, 2}});
//   const rl::mat4 view = rl::look_at({0, 2, 5}, {0, 0, 0}, {0, 1, 0});
//   const rl::mat4 projection = rl::perspective(60, 4.0f / 3, 0.1f, 100);
//   const rl::vec4 clip = projection * view * model * rl::vec4{p.x, p.y, p.z, 1};
#pragma once

#include <cmath>
#include <numbers>
#include <optional>

#include "rasterlab/mat.hpp"

namespace rl {

inline float radians(float degrees) {
    return degrees * std::numbers::pi_v<float> / 180.0f;
}

// Rotations by `degrees` about one axis, counter-clockwise seen from the
// axis's positive end (the right-hand rule).
mat3 rotation_x(float degrees);
mat3 rotation_y(float degrees);
mat3 rotation_z(float degrees);

// A rotation as a unit quaternion w + xi + yj + zk.
struct Quaternion {
    float w = 1, x = 0, y = 0, z = 0;
};

// The rotation by `degrees` about `axis` (any non-zero length).
Quaternion axis_angle(vec3 axis, float degrees);
// The rotation `a` after `b` (as matrices: a * b).
Quaternion operator*(const Quaternion& a, const Quaternion& b);
mat3 to_matrix(const Quaternion& q);
// The quaternion of a rotation matrix (orthonormal, determinant +1).
Quaternion to_quaternion(const mat3& rotation);

// A model transform: scale, then rotate, then translate. A negative scale
// mirrors; decompose() puts a reflection into the x scale.
struct Trs {
    vec3 translation{};
    Quaternion rotation{};
    vec3 scale{1, 1, 1};
};

mat4 compose(const Trs& trs);
// The TRS a matrix is made of; empty when its upper 3x3 is singular or
// sheared (not a rotation times a scale, to within `tolerance`).
std::optional<Trs> decompose(const mat4& m, float tolerance = 1e-4f);

// The view transform: the eye at the origin looking down -z, `up` towards
// +y. Empty when eye == target or up is parallel to the viewing direction.
std::optional<mat4> look_at(vec3 eye, vec3 target, vec3 up);

// OpenGL's perspective projection: a vertical field of view in degrees,
// width / height, and near and far distances (0 < near < far). A point at
// view distance near maps to NDC z = -1, at far to +1; clip w is the view
// distance.
mat4 perspective(float fov_y_degrees, float aspect, float near, float far);

// NDC to window: x, y in [-1, 1] to [0, width] x [0, height] (pixel (i, j)
// has its centre at (i + 0.5, j + 0.5)), z in [-1, 1] to depth [0, 1].
vec3 ndc_to_window(vec3 ndc, int width, int height);

// The upper-left 3x3 of an affine transform: how it moves directions.
inline mat3 linear_part(const mat4& m) {
    mat3 out;
    for (std::size_t r = 0; r < 3; ++r) out[r] = m[r].xyz();
    return out;
}

}  // namespace rl
