// Lesson 02's three ways to fill a triangle, behind one enum. Each calls
// `fragment_stage(x, y, barycentric)` once for every pixel it covers; barycentric
// holds the weights of the three vertices at the pixel's centre. Later
// lessons pass their own fragment stage (depth test, texturing, ...) instead of
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

RASTERLAB_NAMED_ENUM(RasterMethod, kRasterMethods, {RasterMethod::scanline, "scanline"},
                     {RasterMethod::bbox, "bbox"}, {RasterMethod::edge, "edge"});

// Fills the triangle with the chosen method. Returns false when the method
// refused the triangle: a NaN or infinite vertex, or one farther than
// kMaxCoordinate (2^22 pixels) from the origin. Every method keeps its
// calls to `fragment_stage` inside `rect` for every input, and gives a pixel the same
// weights whatever rectangle it is drawn through (so tiles add up to the
// whole image, bit for bit).
template <class FragmentStage>
bool rasterize(RasterMethod method, const ScreenTriangle& t, const PixelRect& rect,
               FragmentStage&& fragment_stage) {
    switch (method) {
        case RasterMethod::scanline:
            return rasterize_scanline(t, rect, fragment_stage);
        case RasterMethod::bbox:
            return rasterize_bbox(t, rect, fragment_stage);
        case RasterMethod::edge:
            return rasterize_edge(t, rect, fragment_stage);
    }
    return false;
}

// The weights `method` gives pixel (x, y) of the triangle (wherever the
// pixel lies, inside or not): exactly those it hands to its fragment stage.
// Set up once per triangle; at() per pixel.
class PixelWeights {
  public:
    PixelWeights(RasterMethod method, const ScreenTriangle& t)
        : method_(method), t_(t), area_(signed_area2(t)), edge_(t) {}
    rl::vec3 at(int x, int y) const {
        if (method_ == RasterMethod::edge) return edge_.at(x, y);
        return barycentric(t_, {x + 0.5f, y + 0.5f}, area_);
    }

  private:
    RasterMethod method_;
    ScreenTriangle t_;
    float area_;
    EdgeWeights edge_;
};
// The whole image: {0, 0, width, height}.
template <class FragmentStage>
bool rasterize(RasterMethod method, const ScreenTriangle& t, int width, int height,
               FragmentStage&& fragment_stage) {
    return rasterize(method, t, PixelRect{0, 0, width, height}, fragment_stage);
}

}  // namespace triangles
