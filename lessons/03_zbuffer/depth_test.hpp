// The depth test of lesson 03, on its own so that the pipeline (lesson 05)
// can run it without the rest of the lesson: a fragment's window depth,
// interpolated and kept in range, against the nearest depth drawn so far.
//
//   const float z = zbuffer::interpolate_depth(weights, z0, z1, z2);
//   if (zbuffer::passes_depth_test(depth, x, y, z)) colour.at(x, y) = c;
#pragma once

#include <algorithm>

#include "02_triangles/screen_triangle.hpp"
#include "rasterlab/image.hpp"

namespace zbuffer {

// [doc:depth-test]
// The depth test `less`: when z is nearer than what the buffer holds at
// (x, y), store it and return true; otherwise leave the buffer alone.
inline bool passes_depth_test(rl::FloatImage& depth, int x, int y, float z) {
    float& nearest = depth.at(x, y);
    if (!(z < nearest)) return false;
    nearest = z;
    return true;
}

// The depth a fragment carries into the test: window depth interpolated
// with the rasterizer's weights, kept within the range of the triangle's
// three vertex depths. A convex combination never leaves that range, but
// float weights that sum to 1 - 2^-24 do: a triangle lying exactly on the far
// plane (z = 1 at every vertex) would pass `less` against a cleared buffer in
// about a fifth of its pixels. Clamped, it passes in none.
inline float interpolate_depth(rl::vec3 weights, float z0, float z1, float z2) {
    const float z = triangles::interpolate(weights, z0, z1, z2);
    return std::clamp(z, std::min({z0, z1, z2}), std::max({z0, z1, z2}));
}

// [/doc:depth-test]

}  // namespace zbuffer
