// The camera: where the eye is, what it looks at, and how wide it sees;
// from it the view and projection matrices of rl/transform.hpp, and a
// camera that frames a scene's bounding box when the user gives none.
// Derivations: docs/05_perspective.md#the-camera.
//
//   pipeline::Camera camera = pipeline::frame_box(bounds, 50.0f, 4.0f / 3);
//   pipeline::check(camera);  // throws std::invalid_argument naming the option
//   const rl::mat4 view_projection = pipeline::view_projection(camera, 4.0f / 3);
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "rasterlab/mat.hpp"
#include "rasterlab/mesh.hpp"

namespace pipeline {

struct Camera {
    rl::vec3 eye{0, 0, 3};
    rl::vec3 target{0, 0, 0};
    rl::vec3 up{0, 1, 0};
    float fov_y = 50.0f;  // vertical field of view, degrees
    float near = 0.1f;
    float far = 100.0f;
};

// How small near / far may be. The window depth of a point at distance z is
// (1/near - 1/z) / (1/near - 1/far): with near / far tiny, every point beyond
// a few times near lands within a float's last digit of 1, the clear value,
// and fails the depth test. Measured on the default scenes of lessons 05-07
// (fragments lost against near / far = 0.05): under 0.12% at 1e-5, 0.3-1.3%
// at 1e-6, 17-18% at 1e-7, and all of them at 1e-8 (--near 1e-7 with the
// framed far of 10.9 drew nothing). Below kSmallestNearOverFar the camera is
// refused; below kWarnedNearOverFar it is drawn with a warning.
inline constexpr double kSmallestNearOverFar = 1e-7, kWarnedNearOverFar = 1e-5;

// The farthest a point drawn may lie from the eye: the far plane's corners,
// far * sqrt(1 + tan^2(fov_y / 2) (1 + aspect^2)) away. Shading squares that
// distance in float, whose largest value (3.4e38) is the square of 1.8e19.
// Measured with the torus scaled to fill the view: lesson 12 matches lesson
// 07 with the eye 1.8e19 away, differs in 0.3% of pixels at 1.9e19 and in
// 15% at 2.2e19 (docs/robustness.md).
inline constexpr double kMaxReach = 1e19;

// Throws std::invalid_argument, naming the option to change, unless the
// camera defines a projection: 0 < fov_y < 180, 0 < near < far, near / far
// at least kSmallestNearOverFar, eye != target, and up not parallel to the
// viewing direction.
void check(const Camera& camera);

// Throws std::invalid_argument, naming --far and --fov, when the corners of
// the far plane of `camera` seen at `aspect` (width / height) lie farther
// than kMaxReach from the eye.
void check_reach(const Camera& camera, float aspect);

// The warning for a near / far below kWarnedNearOverFar, or empty.
std::string depth_precision_warning(const Camera& camera);

// projection * view, for an image of width / height = aspect.
rl::mat4 view_projection(const Camera& camera, float aspect);

// An axis-aligned box; `empty` until something is added.
struct Box {
    rl::vec3 min{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                 std::numeric_limits<float>::max()};
    rl::vec3 max{-std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
                 -std::numeric_limits<float>::max()};
    bool empty() const { return min.x > max.x; }
    void add(rl::vec3 p);
    void add(const Box& b);
    rl::vec3 centre() const { return (min + max) * 0.5f; }
    rl::vec3 corner(int i) const {  // i in 0..7: bit 0 picks x, bit 1 y, bit 2 z
        return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    }
};

// The box around a mesh's positions after the model matrix.
Box bounds(const rl::Mesh& mesh, const rl::mat4& model);

// The direction the framing camera looks from: above, right and in front,
// so that a floor recedes and three faces of a box show.
inline constexpr rl::vec3 kFramingDirection{0.45f, 0.4f, 1.0f};

// A camera looking at the box's centre from kFramingDirection, just far
// enough that all eight corners of the box are in view, with near and far
// planes just around the box.
Camera frame_box(const Box& box, float fov_y, float aspect);

// Near and far planes for a given eye: just around the box (near at least
// far / 10^4, so that an eye inside the box still gets a usable depth range).
void fit_depth_range(Camera& camera, const Box& box);

}  // namespace pipeline
