// Bounding box + barycentric coordinates, in float: test every pixel centre
// in the triangle's bounding box. The simplest correct-looking method, and
// the one whose failures lesson 02 measures: a pixel centre exactly on an
// edge shared by two triangles is drawn by both.
//
//   const triangles::ScreenTriangle t{{{10, 10}, {90, 20}, {40, 80}}};
//   const bool drawn = triangles::rasterize_bbox(t, width, height, [&](int x, int y, rl::vec3 b) {
//       image.set(x, y, shade(b));  // b: the weights of t.v[0], t.v[1], t.v[2]
//   });  // false: refused, a vertex beyond triangles::kMaxCoordinate
//   triangles::rasterize_bbox(t, triangles::PixelRect{0, 0, 64, 64}, fragment_stage);  // one tile
#pragma once

#include "screen_triangle.hpp"

namespace triangles {

// [doc:raster-bbox]
template <class FragmentStage>
bool rasterize_bbox(const ScreenTriangle& t, const PixelRect& rect,
                    FragmentStage&& fragment_stage) {
    if (!within_raster_range(t)) return false;
    const float area = signed_area2(t);
    if (area == 0.0f) return true;  // degenerate: covers nothing
    const auto [xs, ys] = centres_in_box(t, rect);
    for (int y = ys.first; y <= ys.last; ++y)
        for (int x = xs.first; x <= xs.last; ++x) {
            const rl::vec2 p{x + 0.5f, y + 0.5f};
            // Each weight is the area of the sub-triangle opposite its vertex.
            const rl::vec3 bary{rl::cross(t.v[2] - t.v[1], p - t.v[1]) / area,
                                rl::cross(t.v[0] - t.v[2], p - t.v[2]) / area,
                                rl::cross(t.v[1] - t.v[0], p - t.v[0]) / area};
            if (bary.x >= 0 && bary.y >= 0 && bary.z >= 0) fragment_stage(x, y, bary);
        }
    return true;
}
// [/doc:raster-bbox]

// The whole image: {0, 0, width, height}.
template <class FragmentStage>
bool rasterize_bbox(const ScreenTriangle& t, int width, int height,
                    FragmentStage&& fragment_stage) {
    return rasterize_bbox(t, PixelRect{0, 0, width, height}, fragment_stage);
}

}  // namespace triangles
