#include "clipping_scenes.hpp"

namespace pipeline {

ClippingScene around_eye_scene(int count) {
    ClippingScene s{std::to_string(count) + " triangles around the eye", {}, {}};
    s.camera.eye = {0, 0, 0};
    s.camera.target = {0, 0, -1};
    s.camera.fov_y = 60;
    s.camera.near = 0.1f;
    s.camera.far = 50;
    s.triangles = triangles_around(s.camera, count, 5, 3.0);
    return s;
}

// The cells around the eye cross the near plane, and, cut at it, reach
// window coordinates far past the rasterizer's 2^22.
ClippingScene floor_scene() {
    ClippingScene s{"floor from 0.3 above", {}, {}};
    s.camera.eye = {0, 0.3f, 0};
    s.camera.target = {0, 0.2f, -1};
    s.camera.fov_y = 60;
    s.camera.near = 0.02f;
    s.camera.far = 600;
    const int n = 20;
    const double extent = 500;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x0 = -extent + 2 * extent * i / n, x1 = -extent + 2 * extent * (i + 1) / n;
            const double z0 = extent - 2 * extent * j / n, z1 = extent - 2 * extent * (j + 1) / n;
            const rl::dvec3 a{x0, 0, z0}, b{x1, 0, z0}, c{x1, 0, z1}, d{x0, 0, z1};
            s.triangles.push_back({{a, b, c}, {}});
            s.triangles.push_back({{a, c, d}, {}});
        }
    return s;
}

}  // namespace pipeline
