// A surface's two answers to light arriving along a direction: the mirror
// direction, the bent (refracted) one by Snell's law, and how much of the
// light takes each (Fresnel, in Schlick's approximation). Derivation and
// pictures: docs/09_environment.md#mirrors-and-glass.
//
//   const rl::vec3 r = environment::reflect(-to_eye, n);
//   const std::optional<rl::vec3> t = environment::refract(-to_eye, n, 1 / 1.5f);
//   const float f = environment::schlick(rl::dot(n, to_eye),
//   environment::reflectance_at_normal(1.5f));
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "rasterlab/vec.hpp"

namespace environment {

// The mirror image of the incoming direction `d` (pointing at the surface)
// about the unit normal n: d - 2 (d.n) n.
inline rl::vec3 reflect(rl::vec3 d, rl::vec3 n) {
    return d - n * (2 * rl::dot(d, n));
}

// The direction `d` (unit, pointing at the surface) takes through it, with
// eta = n1 / n2 (the index of refraction it leaves over the one it enters)
// and n the unit normal on d's side. Nothing when sin(theta_t) would exceed
// 1: total internal reflection.
inline std::optional<rl::vec3> refract(rl::vec3 d, rl::vec3 n, float eta) {
    const float cos_i = -rl::dot(d, n);
    const float sin2_t = eta * eta * std::max(0.0f, 1 - cos_i * cos_i);
    if (sin2_t > 1) return std::nullopt;
    const float cos_t = std::sqrt(1 - sin2_t);
    return d * eta + n * (eta * cos_i - cos_t);
}

// The share of light reflected head-on between indices 1 and `ior`:
// ((ior - 1) / (ior + 1))², 0.04 for glass.
inline float reflectance_at_normal(float ior) {
    const float r = (ior - 1) / (ior + 1);
    return r * r;
}

// Schlick's approximation of the share reflected at angle theta (cos_theta
// between the normal and the direction to the eye): f0 head-on, rising to 1
// at grazing.
inline float schlick(float cos_theta, float f0) {
    const float m = 1 - std::clamp(cos_theta, 0.0f, 1.0f);
    return f0 + (1 - f0) * (m * m) * (m * m) * m;
}

}  // namespace environment
