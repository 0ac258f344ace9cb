// Clipping a segment to a rectangle (Liang-Barsky), so that endpoints far
// outside the image cost nothing and cannot overflow a pixel counter.
//
//   const lines::ClippedSegment c =
//       lines::clip_segment(a, b, lines::pixel_centres(image.width(), image.height()));
#pragma once

#include <optional>
#include <utility>

#include "rasterlab/vec.hpp"

namespace lines {

struct Rect {
    double x_min, y_min, x_max, y_max;
};

// The rectangle of pixel centres of a width x height image: a line clipped
// to it only ever lands on pixels inside the image.
Rect pixel_centres(int width, int height);

enum class ClipResult { inside, clipped, outside, refused };

struct ClippedSegment {
    ClipResult result;
    rl::vec2 a, b;  // valid for inside and clipped
};

// Liang-Barsky: the part of segment ab inside `rect`. Computed in double, so
// that endpoints as far out as 1e9 still give the right crossing points.
// Endpoints that are NaN or infinite are refused.
ClippedSegment clip_segment(rl::vec2 a, rl::vec2 b, const Rect& rect);

}  // namespace lines
