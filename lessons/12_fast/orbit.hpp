// The camera path of lesson 12's timed frames: `frames` views orbiting the
// target about the up axis, once round, ending on the camera as given (so
// the last frame is lesson 07's image for the same options); and the median
// frame time, the first frame (caches cold, maps paged in) left out.
//
//   for (int i = 0; i < frames; ++i) renderer.render(fast::orbit(camera, i, frames));
#pragma once

#include <vector>

#include "05_perspective/camera.hpp"

namespace fast {

perspective::Camera orbit(const perspective::Camera& camera, int frame, int frames);

// The median of times (0 for none).
double median(std::vector<double> times);

// The median of times[1..], or times[0] when there is only one.
double median_after_first(std::vector<double> times);

}  // namespace fast
