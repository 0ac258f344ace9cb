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

pipeline::Camera orbit(const pipeline::Camera& camera, int frame, int frames);

// The most pixels a run of frames may draw in all, frames x width x height:
// 2^32, 256 frames at 4096² or 16 at 16384² (1000 frames at 16384² asked
// for 62 times that).
inline constexpr double kMaxPixelFrames = 4294967296.0;

// Throws std::invalid_argument naming --frames and the cap for a run over it.
void check_frames(int frames, int width, int height);

// The median of times (0 for none).
double median(std::vector<double> times);

// The median of times[1..], or times[0] when there is only one.
double median_after_first(std::vector<double> times);

}  // namespace fast
