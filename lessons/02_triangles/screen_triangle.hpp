// A triangle in window coordinates (pixel (i, j) has its centre at
// (i + 0.5, j + 0.5)), with the helpers every rasterizer shares.
//
//   const triangles::ScreenTriangle t{{{10, 10}, {90, 20}, {40, 80}}};
//   if (triangles::signed_area2(t) > 0) { /* counter-clockwise: a front face */ }
#pragma once

#include <algorithm>
#include <cmath>

#include "rasterlab/vec.hpp"

namespace triangles {

struct ScreenTriangle {
    rl::vec2 v[3];
};

// Twice the signed area: positive when the vertices run counter-clockwise
// (window y points up), which is what a front face looks like.
inline float signed_area2(const ScreenTriangle& t) {
    return rl::cross(t.v[1] - t.v[0], t.v[2] - t.v[0]);
}

// How far from the origin a vertex may lie, in pixels, for any of the
// rasterizers: 2^22 (4,194,304). Within it the fixed-point edge functions fit
// 64-bit integers (every difference fits 31 bits, every product 62), and the
// float methods, whose spacing there is half a pixel, still get only about
// one pixel in a thousand wrong (tests/lessons/02_triangles/triangles_test.cpp); beyond it
// their errors grow with the coordinates, and from 10^19 a float edge
// function overflows. A triangle reaching beyond is
// refused (drawn not at all, and counted): lesson 05 clips real scenes to a
// guard band far inside it. NaN and infinity are refused the same way.
inline constexpr float kMaxCoordinate = 4194304.0f;

inline bool within_raster_range(const ScreenTriangle& t) {
    for (const rl::vec2& p : t.v)
        if (!(std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate)) return false;
    return true;  // (the negated test is false for NaN, so NaN is refused too)
}

// A vertex attribute (depth, texture coordinates, ...) at a pixel, from the
// barycentric weights the rasterizers hand to the fragment stage.
template <class T>
T interpolate(rl::vec3 weights, const T& a0, const T& a1, const T& a2) {
    return a0 * weights.x + a1 * weights.y + a2 * weights.z;
}

// The pixels a rasterizer may write: columns [x0, x1) and rows [y0, y1).
// The whole image is {0, 0, width, height}; a tile is a smaller rectangle,
// and drawing every tile of an image gives exactly the whole image's pixels.
struct PixelRect {
    int x0, y0, x1, y1;
};

// The range of pixel indices whose centres lie in [low, high], clamped to
// [first, end - 1]; empty (first > last) when none do. Safe for any finite input.
struct PixelRange {
    int first, last;
};

inline PixelRange centres_between(float low, float high, int first, int end) {
    // Centre i + 0.5 >= low  <=>  i >= low - 0.5; clamp in float before converting.
    const float from =
        std::clamp(std::ceil(low - 0.5f), static_cast<float>(first), static_cast<float>(end));
    const float to = std::clamp(std::floor(high - 0.5f), static_cast<float>(first - 1),
                                static_cast<float>(end - 1));
    return {static_cast<int>(from), static_cast<int>(to)};
}

inline PixelRange centres_between(float low, float high, int size) {
    return centres_between(low, high, 0, size);
}

// The pixels a rasterizer visits for a triangle: those of `rect` whose
// centres lie in the triangle's bounding box, as columns and rows (each
// empty when first > last).
struct PixelBox {
    PixelRange xs, ys;
    bool empty() const { return xs.first > xs.last || ys.first > ys.last; }
};
inline PixelBox centres_in_box(const ScreenTriangle& t, const PixelRect& rect) {
    const auto [x0, x1] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
    const auto [y0, y1] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    return {centres_between(x0, x1, rect.x0, rect.x1), centres_between(y0, y1, rect.y0, rect.y1)};
}

}  // namespace triangles
