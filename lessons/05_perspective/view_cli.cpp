#include "view_cli.hpp"

#include <memory>

namespace pipeline {

namespace {

// --eye, --target, --up: three finite numbers each.
rl::Option* add_point_option(rl::CommandLine& app, const std::string& flag,
                             std::vector<float>& point, const std::string& what) {
    return app.add_option(flag, point, what + ", x y z")->expected(3)->check(rl::finite_number());
}

}  // namespace

void add_view_options(rl::CommandLine& app, ViewOptions& view, const std::string& default_scene) {
    app.add_option("-m,--model", view.models,
                   "OBJ file to draw, as stored (repeat for several, at most " +
                       std::to_string(kMaxModels) + "); default: " + default_scene)
        ->each([count = std::make_shared<std::size_t>(0)](const std::string&) {
            if (++*count > kMaxModels)
                throw rl::OptionError("at most " + std::to_string(kMaxModels) +
                                      " models, each loaded whole");
        });
    add_point_option(app, "--eye", view.eye, "Camera position (default: framing the scene)");
    add_point_option(app, "--target", view.target, "Point looked at (default: the scene's centre)");
    add_point_option(app, "--up", view.up, "Up direction")->capture_default_str();
    app.add_option("--fov", view.camera.fov_y, "Vertical field of view, degrees (0 to 180)")
        ->check(rl::finite_number())
        ->capture_default_str();
    app.add_option("--near", view.camera.near,
                   "Near plane distance (default: just in front of the scene)")
        ->check(rl::finite_number())
        ->each([&view](const std::string&) { view.near_given = true; });
    app.add_option("--far", view.camera.far, "Far plane distance (default: just behind the scene)")
        ->check(rl::finite_number())
        ->each([&view](const std::string&) { view.far_given = true; });
    rl::add_light_option(app, view.light);
}

}  // namespace pipeline
