// Lesson 03's depth buffer shown as an image.
//
//   rl::save_image("depth.png", zbuffer::depth_picture(frame.depth));
#pragma once

#include "rasterlab/image.hpp"

namespace zbuffer {

// The depth buffer as a picture: near is white, far is dark grey, scaled to
// the depths actually present; untouched pixels (depth 1) are black.
rl::Image depth_picture(const rl::FloatImage& depth);

}  // namespace zbuffer
