#include "zfight.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace zbuffer {
namespace {

// View distances of both planes along the ray through pixel (x, y).
struct Hit {
    double near_w, far_w;
};

Hit hit(const TwoPlanes& s, int x, int y) {
    const double half = std::tan(std::numbers::pi / 6);  // tan(30 degrees)
    (void)x;  // the planes are tilted about the x axis: depth varies with y only
    const double dy = half * (2.0 * (y + 0.5) / s.size - 1.0);
    const double c = std::cos(std::numbers::pi / 4), sn = std::sin(std::numbers::pi / 4);
    // Plane normal (0, sin, cos); the ray is t * (dx, dy, -1), so t is the view distance w.
    const double facing = sn * dy - c;  // normal . direction, negative: the plane faces the camera
    const double near_w = (-s.distance * c) / facing;
    const double far_w = (-s.distance * c - s.gap) / facing;
    return {near_w, far_w};
}

void for_each_pixel(const TwoPlanes& s, const std::function<void(int, int, Hit)>& visit) {
    for (int y = 0; y < s.size; ++y)
        for (int x = 0; x < s.size; ++x) visit(x, y, hit(s, x, y));
}

bool fights(DepthFormat format, DepthRange range, Hit h) {
    const double near_key = depth_key(format, static_cast<float>(h.near_w), range);
    const double far_key = depth_key(format, static_cast<float>(h.far_w), range);
    return !(near_key < far_key);
}

}  // namespace

Extent visible_extent(const TwoPlanes& scene) {
    Extent e{1e300, 0};
    for_each_pixel(scene, [&](int, int, Hit h) {
        e.nearest = std::min(e.nearest, h.near_w);
        e.farthest = std::max(e.farthest, h.far_w);
    });
    return e;
}

DepthRange fitted_range(const TwoPlanes& scene) {
    const Extent e = visible_extent(scene);
    return {static_cast<float>(e.nearest * 0.99), static_cast<float>(e.farthest * 1.01)};
}

// [doc:zfight-share]
double zfight_share(DepthFormat format, DepthRange range, const TwoPlanes& scene) {
    long counted = 0, fighting = 0;
    for_each_pixel(scene, [&](int, int, Hit h) {
        if (h.near_w < range.near_plane || h.far_w > range.far_plane) return;  // clipped away
        ++counted;
        fighting += fights(format, range, h);
    });
    return counted ? static_cast<double>(fighting) / static_cast<double>(counted) : 0.0;
}
// [/doc:zfight-share]

rl::Image zfight_map(DepthFormat format, DepthRange range, const TwoPlanes& scene) {
    rl::Image image(scene.size, scene.size, rl::kBackground);
    for_each_pixel(scene, [&](int x, int y, Hit h) {
        if (h.near_w < range.near_plane || h.far_w > range.far_plane) return;
        image.set(
            x, y,
            fights(format, range, h) ? rl::Rgba{220, 40, 30, 255} : rl::Rgba{200, 200, 190, 255});
    });
    return image;
}

}  // namespace zbuffer
