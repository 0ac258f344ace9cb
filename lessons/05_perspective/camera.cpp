#include "camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "rasterlab/transform.hpp"

namespace pipeline {
namespace {

// The box's longest side: its size, without squares that would overflow a
// float at 1e20 or vanish at 1e-20.
float longest_side(const Box& box) {
    const rl::vec3 d = box.max - box.min;
    return std::max({d.x, d.y, d.z});
}

}  // namespace

void check(const Camera& camera) {
    if (!(camera.fov_y > 0 && camera.fov_y < 180))
        throw std::invalid_argument(
            "--fov: the vertical field of view must be in (0, 180) degrees");
    if (!(camera.near > 0))
        throw std::invalid_argument("--near: the near plane must be in front of the eye (> 0)");
    if (!(camera.near < camera.far)) throw std::invalid_argument("--near/--far: need near < far");
    if (const double ratio = static_cast<double>(camera.near) / camera.far;
        ratio < kSmallestNearOverFar) {
        char text[320];
        std::snprintf(text, sizeof text,
                      "--near/--far: near / far is %.2g, below 1e-7: a float depth buffer rounds "
                      "the depth of nearly every point to the clear value and draws almost "
                      "nothing; raise --near or lower --far",
                      ratio);
        throw std::invalid_argument(text);
    }
    if (!rl::look_at(camera.eye, camera.target, camera.up))
        throw std::invalid_argument(
            "--eye/--target/--up: the eye must differ from the target, and up must not be "
            "parallel to the viewing direction");
    // Below the smallest normal float, near * far (which the projection
    // holds) loses its digits and then becomes 0: depth would no longer
    // depend on distance. A model 1e-20 across is framed with near * far
    // about 1e-40; one 1e-15 across draws as a unit one does.
    if (static_cast<double>(camera.near) * camera.far < std::numeric_limits<float>::min()) {
        char text[320];
        std::snprintf(text, sizeof text,
                      "--near/--far: near * far is %.2g, below a float's smallest normal number "
                      "(1.2e-38): the camera's matrices would lose the depth; scale the scene up "
                      "(a model framed automatically must be at least about 1e-19 across)",
                      static_cast<double>(camera.near) * camera.far);
        throw std::invalid_argument(text);
    }
    // Far * near and the eye's distance enter the matrices: past about 1e19
    // they overflow a float, and every vertex would become infinite or NaN.
    const rl::mat4 m = view_projection(camera, 1.0f);
    for (const rl::vec4& row : m.rows)
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(row[static_cast<std::size_t>(i)]))
                throw std::invalid_argument(
                    "--eye/--near/--far: the camera's matrices overflow a float (near * far "
                    "or the eye's distance from the origin is beyond about 1e38); scale the "
                    "scene down");
}

void check_reach(const Camera& camera, float aspect) {
    // Within the matrices' range, a distance's square can still overflow.
    const double t = std::tan(static_cast<double>(camera.fov_y) * std::numbers::pi / 360);
    const double a = aspect;
    const double reach = camera.far * std::sqrt(1 + t * t * (1 + a * a));
    if (!(reach <= kMaxReach)) {
        char text[400];
        std::snprintf(text, sizeof text,
                      "--far/--fov: the far plane's corners lie %.2g from the eye, past 1e19: a "
                      "point drawn there has a squared distance near a float's largest (3.4e38), "
                      "and the shading goes wrong; bring the eye nearer, lower --far or --fov, "
                      "or scale the scene down",
                      reach);
        throw std::invalid_argument(text);
    }
}

std::string depth_precision_warning(const Camera& camera) {
    const double ratio = static_cast<double>(camera.near) / camera.far;
    if (ratio >= kWarnedNearOverFar) return {};
    char text[320];
    std::snprintf(text, sizeof text,
                  "--near/--far: near / far is %.2g, below 1e-5: depths near the far plane round "
                  "to the clear value and some pixels are lost (0.3-1.3%% of the default scenes' "
                  "at 1e-6); raise "
                  "--near or lower --far",
                  ratio);
    return text;
}

rl::mat4 view_projection(const Camera& camera, float aspect) {
    const std::optional<rl::mat4> view = rl::look_at(camera.eye, camera.target, camera.up);
    if (!view) throw std::invalid_argument("--eye/--target/--up: no view for this camera");
    return rl::perspective(camera.fov_y, aspect, camera.near, camera.far) * *view;
}

void Box::add(rl::vec3 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
}

void Box::add(const Box& b) {
    if (b.empty()) return;
    add(b.min);
    add(b.max);
}

Box bounds(const rl::Mesh& mesh, const rl::mat4& model) {
    Box box;
    for (const rl::vec3& p : mesh.positions) box.add((model * rl::extend(p, 1.0f)).xyz());
    return box;
}

Camera frame_box(const Box& box, float fov_y, float aspect) {
    Camera camera;
    camera.fov_y = fov_y;
    if (box.empty()) return camera;
    camera.target = box.centre();
    // In the camera's frame (right, up, back towards the eye), a corner c at
    // (x, y, z) from the target is seen at x / (d - z) across: it fits when
    // d >= z + |x| / tan(half fov x), and likewise in y. The nearest eye
    // that fits all eight corners frames the box tightly.
    const rl::vec3 back = rl::normalize(kFramingDirection);
    const rl::vec3 right = rl::normalize(rl::cross(camera.up, back));
    const rl::vec3 up = rl::cross(back, right);
    const float tan_y = std::tan(rl::radians(fov_y) * 0.5f), tan_x = tan_y * aspect;
    // Floors relative to the box, so that a model a billionth of a unit
    // across is framed as a large one is (a point, of no size, gets any camera).
    const float size = longest_side(box);
    float distance = size > 0 ? size * 1e-6f : 1e-6f;
    for (int i = 0; i < 8; ++i) {
        const rl::vec3 c = box.corner(i) - camera.target;
        const float z = rl::dot(c, back);
        distance = std::max({distance, z + std::abs(rl::dot(c, right)) / tan_x,
                             z + std::abs(rl::dot(c, up)) / tan_y});
    }
    camera.eye = camera.target + back * (distance * 1.02f);  // a 2% margin
    fit_depth_range(camera, box);
    return camera;
}

void fit_depth_range(Camera& camera, const Box& box) {
    if (box.empty()) return;
    // Along the view axis, the box's corners span [nearest, farthest].
    const rl::vec3 forward = rl::normalize(camera.target - camera.eye);
    float nearest = std::numeric_limits<float>::max(), farthest = 0;
    for (int i = 0; i < 8; ++i) {
        const float d = rl::dot(box.corner(i) - camera.eye, forward);
        nearest = std::min(nearest, d);
        farthest = std::max(farthest, d);
    }
    const float size = longest_side(box);
    camera.far = std::max(farthest * 1.01f, size > 0 ? size * 1e-3f : 1e-3f);
    camera.near = std::max(nearest * 0.99f, camera.far * 1e-4f);
}

}  // namespace pipeline
