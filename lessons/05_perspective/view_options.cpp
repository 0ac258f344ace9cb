#include "view_options.hpp"

#include <sstream>
#include <stdexcept>

#include "rasterlab/direction.hpp"

namespace pipeline {

namespace {

rl::vec3 to_vec3(const std::vector<float>& v) {
    return {v[0], v[1], v[2]};
}

}  // namespace

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
    if (view.near_given) camera.near = view.camera.near;
    if (view.far_given) camera.far = view.camera.far;
    const bool derived =
        view.eye.empty() || view.target.empty() || !view.near_given || !view.far_given;
    try {
        check(camera);
        check_reach(camera, aspect);
    } catch (const std::invalid_argument& e) {
        if (!derived || box.empty()) throw;
        // The user gave only part of this camera: say where the rest came from.
        std::ostringstream out;
        out << "the camera framed to fit the models (their box spans " << box.min << " to "
            << box.max << ", seen with --fov " << camera.fov_y << ") does not work: " << e.what()
            << "; give the camera yourself (--eye, --target, --near, --far)";
        throw std::invalid_argument(out.str());
    }
    return camera;
}
// [/doc:resolve-camera]

rl::vec3 light_direction(const ViewOptions& view) {
    rl::check_direction("--light", view.light);
    return to_vec3(view.light);
}

}  // namespace pipeline
