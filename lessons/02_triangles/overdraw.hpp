// A picture of how often each pixel is drawn when triangles share edges:
// the fan of lesson 02's "where it breaks" section.
//
//   const rl::Image fan = triangles::overdraw_fan(triangles::RasterMethod::bbox, 48, 12);
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "raster.hpp"
#include "rasterlab/image.hpp"

namespace triangles {

// Draws a fan of `slices` triangles around a hub on a pixel centre, in a
// size x size image, counting draws per pixel: black 0, grey 1, red 2 or
// more. A watertight rasterizer leaves no red and no black inside the disc.
rl::Image overdraw_fan(RasterMethod method, int size, int slices);

// Who owns the pixels on shared edges: a fan of four triangles around a hub
// on a pixel centre, its spokes horizontal and vertical through pixel
// centres, each pixel coloured by the triangle that drew it (right, top,
// left, bottom: blue, green, orange, purple), red where two did, black where
// none did. The top-left rule gives a horizontal spoke's pixels to the
// triangles below it, a vertical spoke's to those on its right; scanline's
// half-open rows give the horizontal spoke to the triangles above.
rl::Image edge_owners(RasterMethod method, int size);

// The pixels some rasterizer covers of one triangle, in any order.
using CoveredPixels =
    std::function<std::vector<std::pair<int, int>>(const ScreenTriangle& triangle)>;

// Those of one of this lesson's rasterizers, in a width x height image.
CoveredPixels covered_by(RasterMethod method, int width, int height);

// edge_owners' picture for a fan of `slices` triangles drawn by any
// rasterizer (lesson 12 draws its tile kernels' coverage with it): each
// pixel in the colour of the triangle that drew it (four colours in turn
// round the fan), red where two or more did, black where none did.
rl::Image fan_owners(const CoveredPixels& covered, int size, int slices);

}  // namespace triangles
