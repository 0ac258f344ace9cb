// The command-line options every lesson from 05 on shares, spelled once:
// --model (repeatable), --eye, --target, --up, --fov, --near, --far and
// --light; and how they become a camera once the scene's box is known
// (without --eye the camera frames the box; without --near/--far the planes
// sit just around it).
//
//   perspective::ViewOptions view;
//   perspective::add_view_options(app, view, "floor, crate and globe from obj/");
//   CLI11_PARSE(app, argc, argv);
//   const perspective::Camera camera = perspective::resolve_camera(view, box, aspect);
#pragma once

#include <string>
#include <vector>

#include "camera.hpp"
#include "rasterlab/cli.hpp"

namespace perspective {

struct ViewOptions {
    std::vector<std::string> models;  // empty: the lesson's default scene
    std::vector<float> eye, target, up{0, 1, 0};
    Camera camera;  // fov_y as given; near and far as given when near_given / far_given
    CLI::Option* near_option = nullptr;
    CLI::Option* far_option = nullptr;
    std::vector<float> light{0.3f, 0.5f, 1.0f};  // towards the light, world space
};

// `default_scene` says in --help what runs without --model.
void add_view_options(CLI::App& app, ViewOptions& view, const std::string& default_scene);

// The camera the options ask for, framing `box` where they are silent.
// Throws std::invalid_argument naming the option when the camera is unusable.
Camera resolve_camera(const ViewOptions& view, const Box& box, float aspect);

// --light as a direction; throws std::invalid_argument for 0 0 0.
rl::vec3 light_direction(const ViewOptions& view);

}  // namespace perspective
