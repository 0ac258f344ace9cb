#include "sky.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace environment {

namespace {

// A direction made unit, or nothing for zero, NaN or infinite input.
bool unit(rl::dvec3& d) {
    const double length = rl::length(d);
    if (!(length > 0) || !std::isfinite(length)) return false;
    d = d / length;
    return true;
}

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

}  // namespace

Sky default_sky() {
    Sky sky;
    const double elevation = 35 * std::numbers::pi / 180, azimuth = 40 * std::numbers::pi / 180;
    sky.sun_direction = {std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                         std::cos(elevation) * std::cos(azimuth)};
    return sky;
}

rl::dvec3 radiance(const Sky& sky, rl::dvec3 d) {
    if (!unit(d)) return {0, 0, 0};
    // Above the horizon: from the horizon's colour at elevation 0 to the
    // zenith's, faster near the horizon (the square root), as a clear sky does.
    const double up = std::sqrt(std::max(d.y, 0.0));
    const rl::dvec3 air = sky.horizon * (1 - up) + sky.zenith * up;
    const double ground_share = 1 - smoothstep(-sky.horizon_band, 0.0, d.y);
    rl::dvec3 ground = sky.ground;
    if (sky.checker > 0 && d.y < 0) {
        // Where the ray meets the plane one unit below: (x, z) / -y.
        // Near the horizon (x, z) run off towards infinity: past 10^15 squares
        // the checker is averaged away anyway, and the integer square would
        // not fit a long long.
        const double x = d.x / -d.y / sky.checker, z = d.z / -d.y / sky.checker;
        if (std::fabs(x) < 1e15 && std::fabs(z) < 1e15 &&
            (static_cast<long long>(std::floor(x)) + static_cast<long long>(std::floor(z))) % 2 !=
                0)
            ground = sky.ground_dark;
    }
    rl::dvec3 out = air * (1 - ground_share) + ground * ground_share;
    // The sun and its corona, above the horizon only.
    const double cos_angle = std::clamp(rl::dot(d, sky.sun_direction), -1.0, 1.0);
    const double degrees = std::acos(cos_angle) * 180 / std::numbers::pi;
    const double above = 1 - ground_share;
    out += sky.corona * (std::exp(-degrees / sky.corona_degrees) * above);
    if (degrees <= sky.sun_radius_degrees) out += sky.sun * above;
    return out;
}

rl::dvec3 radiance(const Studio& studio, rl::dvec3 d) {
    if (!unit(d)) return {0, 0, 0};
    // Two softboxes: rectangles of the sky seen through windows high on the
    // left and the right, in front of the scene (+z) and behind it.
    auto in_box = [&](double azimuth_degrees, double elevation_degrees) {
        const double azimuth = std::atan2(d.x, d.z) * 180 / std::numbers::pi;
        const double elevation = std::asin(std::clamp(d.y, -1.0, 1.0)) * 180 / std::numbers::pi;
        double da = std::fabs(azimuth - azimuth_degrees);
        da = std::min(da, 360 - da);
        return da <= 18 && std::fabs(elevation - elevation_degrees) <= 12;
    };
    if (in_box(60, 35) || in_box(-120, 25)) return studio.softbox;
    return d.y < 0 ? studio.floor : studio.walls;
}

rl::dvec3 radiance(Analytic which, rl::dvec3 direction) {
    switch (which) {
        case Analytic::sky:
            return radiance(default_sky(), direction);
        case Analytic::studio:
            return radiance(Studio{}, direction);
        case Analytic::white:
            break;
    }
    return {1, 1, 1};
}

}  // namespace environment
