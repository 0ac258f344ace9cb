// The lab's truth for glossy light: one bounce of Cook-Torrance off a
// white metal (f0 = 1, so Fresnel is 1 at every angle) with normal n, seen
// from v, lit by an analytic environment: the integral of f(v, l) L(l) n.l
// over the hemisphere, in double, by importance sampling the facets v sees
// with 2^bits Hammersley points (each weighted G2 / G1, at most 1).
//
//   const rl::dvec3 exact = environment::exact_glossy(sky_function, n, v, 0.5, 18);
#pragma once

#include <functional>

#include "rasterlab/vec.hpp"

namespace environment {

rl::dvec3 exact_glossy(const std::function<rl::dvec3(rl::dvec3)>& radiance, rl::dvec3 normal,
                       rl::dvec3 to_eye, double roughness, int bits);

}  // namespace environment
