#include "glossy_truth.hpp"

#include <algorithm>
#include <cmath>

#include "09_environment/brdf.hpp"
#include "09_environment/sphere_sampling.hpp"

namespace environment {

rl::dvec3 exact_glossy(const std::function<rl::dvec3(rl::dvec3)>& radiance, rl::dvec3 normal,
                       rl::dvec3 to_eye, double roughness, int bits) {
    const Frame frame(rl::normalize(normal));
    const rl::dvec3 v = rl::normalize(to_eye);
    const double alpha = ggx_alpha(roughness);
    const double n_dot_v = std::max(rl::dot(frame.n, v), 1e-4);
    const std::uint32_t count = 1u << std::clamp(bits, 0, 30);
    rl::dvec3 sum{0, 0, 0};
    const rl::dvec3 local_v = frame.to_local(v);
    const double g1 = smith_masking_one(n_dot_v, alpha);
    for (std::uint32_t i = 0; i < count; ++i) {
        const rl::dvec3 h =
            frame.to_world(ggx_visible_normal(local_v, hammersley(i, count), alpha));
        const double v_dot_h = rl::dot(v, h);
        const rl::dvec3 l = h * (2 * v_dot_h) - v;
        const double n_dot_l = rl::dot(frame.n, l);
        if (n_dot_l <= 0 || v_dot_h <= 0) continue;
        sum += radiance(l) * (smith_masking(n_dot_v, n_dot_l, alpha) / g1);
    }
    return sum / static_cast<double>(count);
}

}  // namespace environment
