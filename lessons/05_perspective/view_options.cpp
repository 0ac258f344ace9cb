#include "view_options.hpp"

namespace perspective {

namespace {

// --eye, --target, --up: three finite numbers each.
CLI::Option* add_point_option(CLI::App& app, const std::string& flag, std::vector<float>& point,
                              const std::string& what) {
    return app.add_option(flag, point, what + ", x y z")->expected(3)->check(rl::finite_number());
}

rl::vec3 to_vec3(const std::vector<float>& v) {
    return {v[0], v[1], v[2]};
}

}  // namespace

void add_view_options(CLI::App& app, ViewOptions& view, const std::string& default_scene) {
    app.add_option("-m,--model", view.models,
                   "OBJ file to draw, as stored (repeat for several); default: " + default_scene);
    add_point_option(app, "--eye", view.eye, "Camera position (default: framing the scene)");
    add_point_option(app, "--target", view.target, "Point looked at (default: the scene's centre)");
    add_point_option(app, "--up", view.up, "Up direction")->capture_default_str();
    app.add_option("--fov", view.camera.fov_y, "Vertical field of view, degrees (0 to 180)")
        ->check(rl::finite_number())
        ->capture_default_str();
    view.near_option = app.add_option("--near", view.camera.near,
                                      "Near plane distance (default: just in front of the scene)")
                           ->check(rl::finite_number());
    view.far_option = app.add_option("--far", view.camera.far,
                                     "Far plane distance (default: just behind the scene)")
                          ->check(rl::finite_number());
    rl::add_light_option(app, view.light);
}

// [doc:resolve-camera]
Camera resolve_camera(const ViewOptions& view, const Box& box, float aspect) {
    Camera camera = view.camera;
    const Camera framed = frame_box(box, camera.fov_y, aspect);
    camera.eye = view.eye.empty() ? framed.eye : to_vec3(view.eye);
    camera.target = !view.target.empty() ? to_vec3(view.target)
                    : box.empty()        ? rl::vec3{}
                                         : box.centre();
    camera.up = to_vec3(view.up);
    fit_depth_range(camera, box);  // the defaults: just around the scene
    if (view.near_option && view.near_option->count()) camera.near = view.camera.near;
    if (view.far_option && view.far_option->count()) camera.far = view.camera.far;
    check(camera);
    return camera;
}
// [/doc:resolve-camera]

rl::vec3 light_direction(const ViewOptions& view) {
    rl::check_direction("--light", view.light);
    return to_vec3(view.light);
}

}  // namespace perspective
