// The scanline method: sort the vertices by height, split the triangle at the
// middle vertex into a part with a flat top and a part with a flat bottom,
// and fill each row between its left and right edge.
//
//   triangles::rasterize_scanline(t, width, height, [&](int x, int y, rl::vec3 bary) {
//       image.set(x, y, colour);  // row by row, bottom up, each row left to right
//   });
//   const float area = triangles::signed_area2(t);
//   const rl::vec3 bary = triangles::barycentric(t, {x + 0.5f, y + 0.5f}, area);
#pragma once

#include <utility>

#include "screen_triangle.hpp"

namespace triangles {

// Barycentric weights at p, from float edge functions (for the shading).
inline rl::vec3 barycentric(const ScreenTriangle& t, rl::vec2 p, float area) {
    return {rl::cross(t.v[2] - t.v[1], p - t.v[1]) / area,
            rl::cross(t.v[0] - t.v[2], p - t.v[2]) / area,
            rl::cross(t.v[1] - t.v[0], p - t.v[0]) / area};
}

// [doc:raster-scanline]
template <class FragmentStage>
bool rasterize_scanline(const ScreenTriangle& t, const PixelRect& rect,
                        FragmentStage&& fragment_stage) {
    if (!within_raster_range(t)) return false;
    const float area = signed_area2(t);
    if (area == 0.0f) return true;
    rl::vec2 lo = t.v[0], mid = t.v[1], hi = t.v[2];  // sorted by y
    if (lo.y > mid.y) std::swap(lo, mid);
    if (mid.y > hi.y) std::swap(mid, hi);
    if (lo.y > mid.y) std::swap(lo, mid);

    // x where the edge a-b crosses height y.
    auto x_at = [](rl::vec2 a, rl::vec2 b, float y) {
        return a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y);
    };
    // Rows whose centres lie in [y0, y1): the lower part owns its bottom edge,
    // the upper part gets the row through the middle vertex.
    auto fill_rows = [&](float y0, float y1, rl::vec2 a, rl::vec2 b) {  // a-b: the short edge
        const PixelRange rows = centres_between(y0, y1, rect.y0, rect.y1);
        for (int y = rows.first; y <= rows.last; ++y) {
            const float yc = y + 0.5f;
            if (yc >= y1) break;  // half-open at the top
            float left = x_at(lo, hi, yc), right = x_at(a, b, yc);
            if (left > right) std::swap(left, right);
            const PixelRange columns = centres_between(left, right, rect.x0, rect.x1);
            for (int x = columns.first; x <= columns.last; ++x)
                if (x + 0.5f < right)  // half-open at the right
                    fragment_stage(x, y, barycentric(t, {x + 0.5f, yc}, area));
        }
    };
    if (mid.y > lo.y) fill_rows(lo.y, mid.y, lo, mid);  // flat top (or the whole, if mid = hi)
    if (hi.y > mid.y) fill_rows(mid.y, hi.y, mid, hi);  // flat bottom
    return true;
}
// [/doc:raster-scanline]

// The whole image: {0, 0, width, height}.
template <class FragmentStage>
bool rasterize_scanline(const ScreenTriangle& t, int width, int height,
                        FragmentStage&& fragment_stage) {
    return rasterize_scanline(t, PixelRect{0, 0, width, height}, fragment_stage);
}

}  // namespace triangles
