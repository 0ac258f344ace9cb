#include "globe_relief.hpp"

#include <cmath>
#include <numbers>

namespace assets {

SpherePoint sphere_point(double u, double v) {
    constexpr double kPi = std::numbers::pi;
    const double phi = 2 * kPi * (u - 0.5), theta = kPi * (v - 0.5);
    const double cp = std::cos(phi), sp = std::sin(phi), ct = std::cos(theta), st = std::sin(theta);
    return {{ct * sp, st, ct * cp}, {cp, 0, -sp}, {-st * sp, ct, -st * cp}};
}

double globe_terrain(dvec3 p) {
    return fbm(p * 1.7 + dvec3{3.1, 7.3, 1.9}, 7);
}

double globe_relief(dvec3 p) {
    return std::max(globe_terrain(p) - kGlobeSeaLevel, 0.0);
}

Slopes globe_slopes(const SpherePoint& s) {
    const double eps = 1e-3;  // step along the surface for the relief's gradient
    const dvec3 p = s.normal;
    // Slope of the relief along a direction, by central differences on the sphere.
    auto along = [&](dvec3 dir3) {
        return (globe_relief(rl::normalize(p + dir3 * eps)) -
                globe_relief(rl::normalize(p - dir3 * eps))) /
               (2 * eps);
    };
    return {kGlobeReliefScale * along(s.tangent), kGlobeReliefScale * along(s.bitangent)};
}

dvec3 globe_normal(double u, double v) {
    const SpherePoint s = sphere_point(u, v);
    const Slopes slope = globe_slopes(s);
    return rl::normalize(s.normal - s.tangent * slope.along_tangent -
                         s.bitangent * slope.along_bitangent);
}

dvec3 globe_tangent_space_normal(double u, double v) {
    const Slopes slope = globe_slopes(sphere_point(u, v));
    return rl::normalize(dvec3{-slope.along_tangent, -slope.along_bitangent, 1});
}

}  // namespace assets
