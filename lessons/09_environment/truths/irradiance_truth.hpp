// The lab's truth for diffuse light: the irradiance E(n) = integral of
// L(w) max(0, n.w) dw of an analytic environment, by the midpoint rule over
// the hemisphere around n in double (steps rings of 4 * steps cells; the
// sun's disc, 2 degrees in radius, spans about 22 rings at 1024).
//
//   const rl::dvec3 e = environment::exact_irradiance(sky_function, {0, 1, 0}, 1024);
#pragma once

#include <functional>

#include "rasterlab/vec.hpp"

namespace environment {

rl::dvec3 exact_irradiance(const std::function<rl::dvec3(rl::dvec3)>& radiance, rl::dvec3 normal,
                           int steps);

}  // namespace environment
