// Lesson 02's three ways to fill a triangle, behind one enum. Each calls
// `shade(x, y, barycentric)` once for every pixel it covers; barycentric
// holds the weights of the three vertices at the pixel's centre. Later
// lessons pass their own `shade` (depth test, texturing, ...) instead of
// copying a rasterizer. Derivations: docs/02_triangles.md.
//
//   triangles::rasterize(triangles::RasterMethod::edge, {{a, b, c}}, width, height,
//                        [&](int x, int y, rl::vec3 weights) { image.at(x, y) = colour; });
#pragma once

#include "rasterlab/named_enum.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "raster_bbox.hpp"
#include "raster_edge.hpp"
#include "raster_scanline.hpp"

namespace triangles {

// What became of a model's faces: drawn, culled as back faces, or refused by
// the rasterizer (see rasterize()). Every drawing lesson reports all three.
struct DrawCounts {
    std::size_t drawn = 0, culled = 0, refused = 0;
};

enum class RasterMethod { scanline, bbox, edge };

inline constexpr std::array<rl::Named<RasterMethod>, 3> kRasterMethodNames = {
    {{RasterMethod::scanline, "scanline"},
     {RasterMethod::bbox, "bbox"},
     {RasterMethod::edge, "edge"}}};
inline constexpr std::array<RasterMethod, 3> kRasterMethods = rl::values_of(kRasterMethodNames);

inline const char* name(RasterMethod value) {
    return rl::name_in(kRasterMethodNames, value);
}

// Fills the triangle with the chosen method. Returns false when the method
// refused the triangle: a NaN or infinite vertex, or one farther than
// kMaxCoordinate (2^22 pixels) from the origin. Every method keeps its
// calls to `shade` inside [0, width) x [0, height) for every input.
template <class Shade>
bool rasterize(RasterMethod method, const ScreenTriangle& t, int width, int height, Shade&& shade) {
    switch (method) {
        case RasterMethod::scanline:
            return rasterize_scanline(t, width, height, shade);
        case RasterMethod::bbox:
            return rasterize_bbox(t, width, height, shade);
        case RasterMethod::edge:
            return rasterize_edge(t, width, height, shade);
    }
    return false;
}

}  // namespace triangles
