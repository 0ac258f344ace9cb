// A picture of how often each pixel is drawn when triangles share edges:
// the fan of lesson 02's "where it breaks" section.
#pragma once

#include "raster.hpp"
#include "rasterlab/image.hpp"

namespace triangles {

// Draws a fan of `slices` triangles around a hub on a pixel centre, in a
// size x size image, counting draws per pixel: black 0, grey 1, red 2 or
// more. A watertight rasterizer leaves no red and no black inside the disc.
rl::Image overdraw_fan(RasterMethod method, int size, int slices);

}  // namespace triangles
