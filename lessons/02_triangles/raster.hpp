// Lesson 02's three ways to fill a triangle, behind one enum. Each calls
// `shade(x, y, barycentric)` once for every pixel it covers; barycentric
// holds the weights of the three vertices at the pixel's centre. Later
// lessons pass their own `shade` (depth test, texturing, ...) instead of
// copying a rasterizer. Derivations: docs/02_triangles.md.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "raster_bbox.hpp"
#include "raster_edge.hpp"
#include "raster_scanline.hpp"

namespace triangles {

enum class RasterMethod { scanline, bbox, edge };

inline constexpr std::array<RasterMethod, 3> kRasterMethods = {
    RasterMethod::scanline, RasterMethod::bbox, RasterMethod::edge};

const char* name(RasterMethod method);

// Fills the triangle with the chosen method. Returns false when the method
// refused the triangle (a NaN or infinite vertex; for `edge`, a vertex
// beyond the fixed-point range, see kMaxFixedCoordinate).
template <class Shade>
bool rasterize(RasterMethod method, const Triangle2& t, int width, int height, Shade&& shade) {
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
