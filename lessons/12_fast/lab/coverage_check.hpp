// The fast path's coverage of one window-space triangle, read back from its
// tile kernels' triangle ids: the pixels whose centres it covers, for the
// tests to hold against lesson 02's edge rasterizer bit for bit.
//
//   const auto mine = fast::covered_pixels(t, 64, 64, 16, {});
//   const auto theirs = triangles::covered_pixels(triangles::RasterMethod::edge, t, 64, 64);
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "02_triangles/screen_triangle.hpp"
#include "12_fast/tile_kernels.hpp"

namespace fast {

// Empty optional when the fast path refuses the triangle (as lesson 02 does
// beyond 2^22 pixels or with NaN); otherwise the pixels, row by row.
std::optional<std::vector<std::pair<int, int>>> covered_pixels(const triangles::ScreenTriangle& t,
                                                               int width, int height, int tile_size,
                                                               const Techniques& techniques);

}  // namespace fast
