// The depth test of lesson 03, on its own so that the pipeline (lesson 05)
// can run it without the rest of the lesson: a fragment's window depth,
// interpolated and kept in range, against the nearest depth drawn so far.
//
//   const float z = zbuffer::interpolate_depth(weights, z0, z1, z2);
//   if (zbuffer::test_and_store_depth(depth, x, y, z)) colour.at(x, y) = c;  // stored if nearer
#pragma once

#include "rasterlab/named_enum.hpp"

#include <algorithm>
#include <array>

#include "02_triangles/screen_triangle.hpp"
#include "rasterlab/image.hpp"

namespace zbuffer {

// [doc:depth-test]
// The depth test `less`: when z is nearer than what the buffer holds at
// (x, y), store it and return true; otherwise leave the buffer alone.
inline bool test_and_store_depth(rl::FloatImage& depth, int x, int y, float z) {
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

// The comparisons a depth attachment may use (OpenGL's glDepthFunc names):
// `less` is this lesson's; `greater` with the buffer cleared to 0 is
// reverse-Z, where the near plane maps to 1; `always` draws in order, as
// with no depth test.
enum class DepthCompare { less, less_equal, greater, greater_equal, always };
RASTERLAB_NAMED_ENUM(DepthCompare, kDepthCompares, {DepthCompare::less, "less"},
                     {DepthCompare::less_equal, "less-equal"}, {DepthCompare::greater, "greater"},
                     {DepthCompare::greater_equal, "greater-equal"},
                     {DepthCompare::always, "always"});

// Whether a fragment at depth z passes against the stored depth. A NaN z
// passes nothing but `always`.
inline bool depth_passes(DepthCompare compare, float z, float stored) {
    switch (compare) {
        case DepthCompare::less:
            return z < stored;
        case DepthCompare::less_equal:
            return z <= stored;
        case DepthCompare::greater:
            return z > stored;
        case DepthCompare::greater_equal:
            return z >= stored;
        case DepthCompare::always:
            return true;
    }
    return false;
}

// Everything a depth attachment does besides storing: how it compares,
// whether a passing fragment writes its depth, what a clear stores, and the
// bias added to every fragment's depth before the test: `constant` in depth
// units plus `slope` times the triangle's steepest depth change per pixel,
// max(|dz/dx|, |dz/dy|), as OpenGL's polygon offset (glPolygonOffset's
// factor and units, with units in depth itself rather than in steps of a
// fixed-point format). Shadow maps use the bias against shadow acne.
struct DepthState {
    DepthCompare compare = DepthCompare::less;
    bool write = true;
    float clear = 1.0f;
    float constant_bias = 0.0f, slope_bias = 0.0f;
};

}  // namespace zbuffer
