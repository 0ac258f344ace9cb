// A triangle drawn through bands of rows, with a checkpoint before each
// (rasterlab/checkpoint.hpp): a host such as the Python module can then stop
// even a frame-filling triangle within one band's time. Drawing through the
// bands gives the same pixels, with the same weights, as drawing through the
// whole rectangle: every method's weights at a pixel do not depend on the
// rectangle (rasterize() in raster.hpp).
//
//   const bool ok = triangles::for_each_band(t, rect, 0, [&](const triangles::PixelRect& band) {
//       return triangles::rasterize(method, t, band, fragment_stage);
//   });
#pragma once

#include "rasterlab/checkpoint.hpp"

#include <algorithm>

#include "screen_triangle.hpp"

namespace triangles {

// Rows of a band.
inline constexpr int kCheckpointRows = 64;

// Calls rl::checkpoint() and then draw(band) for each band of the rows of
// `rect` that t's box (grown by `margin` pixels up and down) covers; returns
// whether every call returned true. A triangle out of the rasterizer's range
// (NaN, or farther than kMaxCoordinate) is handed over whole, for draw to
// refuse.
template <class Draw>
bool for_each_band(const ScreenTriangle& t, const PixelRect& rect, float margin, Draw&& draw) {
    rl::checkpoint();
    if (!within_raster_range(t)) return draw(rect);
    const auto [low, high] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    const PixelRange rows = centres_between(low - margin, high + margin, rect.y0, rect.y1);
    if (rows.last - rows.first < kCheckpointRows) return draw(rect);
    bool ok = true;
    for (int y = rows.first; y <= rows.last; y += kCheckpointRows) {
        if (y != rows.first) rl::checkpoint();
        ok &= draw(PixelRect{rect.x0, y, rect.x1, std::min(y + kCheckpointRows, rows.last + 1)});
    }
    return ok;
}

}  // namespace triangles
