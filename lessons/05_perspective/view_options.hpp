// The view every lesson from 05 on can be asked for: models, eye, target,
// up, field of view, near and far planes, light; and how it becomes a camera
// once the scene's box is known (without an eye the camera frames the box;
// without near/far the planes sit just around it). The programs fill it from
// their command line (view_cli.hpp); the Python module from keywords.
//
//   pipeline::ViewOptions view;
//   view.eye = {0, 1, 4};
//   const pipeline::Camera camera = pipeline::resolve_camera(view, box, aspect);
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "camera.hpp"

namespace pipeline {

// The most --model options a program takes: each copy is loaded whole (the
// globe with its maps adds about 8.5 MiB to lesson 07: 64 took 553 MiB),
// so their number is bounded
// like every other input.
inline constexpr std::size_t kMaxModels = 64;

struct ViewOptions {
    std::vector<std::string> models;              // empty: the lesson's default scene
    std::vector<float> eye, target, up{0, 1, 0};  // empty: framed; three numbers otherwise
    Camera camera;  // fov_y as given; near and far as given when near_given / far_given
    bool near_given = false, far_given = false;
    std::vector<float> light{0.3f, 0.5f, 1.0f};  // towards the light, world space
};

// The camera the options ask for, framing `box` where they are silent.
// Throws std::invalid_argument naming the option when the camera is unusable.
Camera resolve_camera(const ViewOptions& view, const Box& box, float aspect);

// The light direction the options give; throws std::invalid_argument naming
// --light for one that cannot be normalised (0 0 0).
rl::vec3 light_direction(const ViewOptions& view);

}  // namespace pipeline
