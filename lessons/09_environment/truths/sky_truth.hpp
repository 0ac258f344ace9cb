// The lab's truth for the sky behind the scene: each pixel's light as the
// mean of the analytic environment over the pixel (samples² rays spread
// evenly across it, in double), with no map in between. A map's skybox is
// scored against it after both go through the same tone map.
//
//   const auto sky = [](rl::dvec3 d) { return environment::radiance(environment::default_sky(), d);
//   }; const rl::Grid<rl::vec3> truth = environment::sky_truth(sky, camera, 800, 800, 4);
#pragma once

#include <functional>

#include "09_environment/scene.hpp"
#include "09_environment/tone_map.hpp"

namespace environment {

rl::Grid<rl::vec3> sky_truth(const std::function<rl::dvec3(rl::dvec3)>& radiance,
                             const pipeline::Camera& camera, int width, int height, int samples);

// How far a picture is from the truth, in 8-bit levels after the tone map
// and sRGB: the mean over pixels and channels, the 99th percentile of each
// pixel's largest channel difference, and the share of pixels off by more
// than 2 levels.
struct SkyError {
    double mean_levels = 0, p99_levels = 0, percent_over_2 = 0;
};
SkyError sky_error(const rl::Image& truth, const rl::Image& picture);

}  // namespace environment
