// A triangle drawn through bands of rows, with a checkpoint before each
// (rasterlab/checkpoint.hpp): a host such as the Python module can then stop
// even a frame-filling triangle within one band's time. Drawing through the
// bands gives the same pixels, with the same weights, as drawing through the
// whole rectangle: every method's weights at a pixel do not depend on the
// rectangle (rasterize() in raster.hpp).
//
//   bool ok = true;
//   for (const triangles::PixelRect band : triangles::Bands(t, rect, 0)) {
//       rl::checkpoint();  // a host may stop here
//       ok &= triangles::rasterize(method, t, band, fragment_stage);
//   }
#pragma once

#include "rasterlab/checkpoint.hpp"

#include <algorithm>

#include "screen_triangle.hpp"

namespace triangles {

// Rows of a band.
inline constexpr int kCheckpointRows = 64;

// The bands of the rows of `rect` that t's box (grown by `margin` pixels up
// and down) covers, bottom first, each at most kCheckpointRows high; a
// triangle of fewer rows, or one out of the rasterizer's range (NaN, or
// farther than kMaxCoordinate, for the rasterizer to refuse), is one band:
// the whole of `rect`.
class Bands {
  public:
    Bands(const ScreenTriangle& t, const PixelRect& rect, float margin) : rect_(rect) {
        if (!within_raster_range(t)) return;
        const auto [low, high] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
        const PixelRange rows = centres_between(low - margin, high + margin, rect.y0, rect.y1);
        if (rows.last - rows.first < kCheckpointRows) return;
        first_ = rows.first;
        count_ = (rows.last - rows.first) / kCheckpointRows + 1;
        end_row_ = rows.last + 1;
    }
    PixelRect operator[](int i) const {
        if (count_ == 1) return rect_;
        const int y = first_ + i * kCheckpointRows;
        return {rect_.x0, y, rect_.x1, std::min(y + kCheckpointRows, end_row_)};
    }

    struct Iterator {
        const Bands* bands;
        int i;
        PixelRect operator*() const { return (*bands)[i]; }
        Iterator& operator++() { return ++i, *this; }
        bool operator!=(const Iterator& other) const { return i != other.i; }
    };
    Iterator begin() const { return {this, 0}; }
    Iterator end() const { return {this, count_}; }

  private:
    PixelRect rect_;
    int first_ = 0, count_ = 1, end_row_ = 0;
};

}  // namespace triangles
