// Fans: triangles sharing a hub and their spokes, the shape where a
// rasterizer's rule for shared edges shows (each spoke is drawn twice or not
// at all when the rule is wrong). The program's overdraw pictures, the lab
// and the tests draw them.
//
//   const std::vector<triangles::ScreenTriangle> fan = triangles::disc_fan({32.5f, 32.5f}, 28, 24);
#pragma once

#include <vector>

#include "screen_triangle.hpp"

namespace triangles {

// (x, y) rounded to the 1/256-pixel grid: the fixed-point precision the
// exact coverage rule and real rasterizers work in, so the lab's triangles
// sit exactly on it.
rl::vec2 on_subpixel_grid(double x, double y);

// A disc cut into `slices` triangles meeting at a centre that lies on a pixel centre.
std::vector<ScreenTriangle> disc_fan(rl::vec2 centre, float radius, int slices);

}  // namespace triangles
