// Drawing a line into an image: clip it to the image, then run one method.
//
//   lines::draw_line(image, {10.5f, 20.5f}, {300.5f, 90.5f}, {255, 255, 255, 255},
//                    lines::LineMethod::bresenham);
#pragma once

#include "line_clip.hpp"
#include "line_methods.hpp"
#include "rasterlab/image.hpp"

namespace lines {

// Mixes `colour` over the pixel by `coverage` (0..1); outside pixels are ignored.
void blend_pixel(rl::Image& image, int x, int y, rl::Rgba colour, float coverage);

// Clips ab to the image's pixel centres and draws what is left. Returns how
// the clip went: `refused` for NaN or infinite endpoints (nothing is drawn),
// `outside` when no part of the line is in the image.
ClipResult draw_line(rl::Image& image, rl::vec2 a, rl::vec2 b, rl::Rgba colour, LineMethod method);

}  // namespace lines
