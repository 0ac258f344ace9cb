// The fast path's coverage of one window-space triangle, read back from its
// tile kernels' triangle ids: the pixels whose centres it covers, for the
// tests to hold against lesson 02's edge rasterizer bit for bit, and, with
// one mistake made on purpose, for the page's failure pictures (12_failures).
//
//   const auto mine = fast::covered_pixels(t, 64, 64, 16, {});
//   const auto theirs = triangles::covered_pixels(triangles::RasterMethod::edge, t, 64, 64);
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "02_triangles/screen_triangle.hpp"
#include "12_fast/tile_kernels.hpp"
#include "rasterlab/named_enum.hpp"

namespace fast {

// What a tiled rasterizer can get wrong around its tiles, each made on
// purpose in the tile loop below (the kernels themselves stay right):
// - inclusive_ties: every edge owns the centres on it (E >= 0, no tie rule):
//   a centre on a shared edge is drawn by both triangles;
// - exclusive_ties: no edge owns them (E > 0): such a centre is drawn by none;
// - tile_origin: the tiles' origins stepped by tile_size - 1 (an off-by-one):
//   tile (i, j) covers what lies i pixels left and j below, so every tile
//   but the first is off, the more the further from it;
// - shared_buffer: two threads, one tile buffer: the second tile of each
//   pair clears and fills the buffer before the first one is copied out, so
//   the first tile shows the second's pixels (one interleaving of many).
enum class CoverageMistake { none, inclusive_ties, exclusive_ties, tile_origin, shared_buffer };
RASTERLAB_NAMED_ENUM(CoverageMistake, kCoverageMistakes, {CoverageMistake::none, "none"},
                     {CoverageMistake::inclusive_ties, "inclusive-ties"},
                     {CoverageMistake::exclusive_ties, "exclusive-ties"},
                     {CoverageMistake::tile_origin, "tile-origin"},
                     {CoverageMistake::shared_buffer, "shared-buffer"});

// Empty optional when the fast path refuses the triangle (as lesson 02 does
// beyond 2^22 pixels or with NaN); otherwise the pixels, row by row.
std::optional<std::vector<std::pair<int, int>>> covered_pixels(
    const triangles::ScreenTriangle& t, int width, int height, int tile_size,
    const Techniques& techniques, CoverageMistake mistake = CoverageMistake::none);

}  // namespace fast
