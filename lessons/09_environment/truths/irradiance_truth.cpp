#include "irradiance_truth.hpp"

#include <cmath>
#include <numbers>

namespace environment {

rl::dvec3 exact_irradiance(const std::function<rl::dvec3(rl::dvec3)>& radiance, rl::dvec3 normal,
                           int steps) {
    const rl::dvec3 n = rl::normalize(normal);
    const rl::dvec3 helper = std::fabs(n.y) < 0.9 ? rl::dvec3{0, 1, 0} : rl::dvec3{1, 0, 0};
    const rl::dvec3 t = rl::normalize(rl::cross(helper, n)), b = rl::cross(n, t);
    const double d_theta = 0.5 * std::numbers::pi / steps;
    const int rings = 4 * steps;
    const double d_phi = 2 * std::numbers::pi / rings;
    rl::dvec3 sum{0, 0, 0};
    for (int i = 0; i < steps; ++i) {
        const double theta = (i + 0.5) * d_theta;
        // cos(theta) for the window, sin(theta) d_theta d_phi for the solid angle.
        const double weight = std::cos(theta) * std::sin(theta) * d_theta * d_phi;
        for (int k = 0; k < rings; ++k) {
            const double phi = (k + 0.5) * d_phi;
            const rl::dvec3 w = t * (std::sin(theta) * std::cos(phi)) +
                                b * (std::sin(theta) * std::sin(phi)) + n * std::cos(theta);
            sum += radiance(w) * weight;
        }
    }
    return sum;
}

}  // namespace environment
