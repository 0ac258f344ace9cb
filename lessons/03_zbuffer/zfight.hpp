// The depth-precision experiment: two parallel planes `gap` apart, the near
// one through (0, 0, -distance) and tilted 45 degrees, seen through a
// perspective camera (60 degree field of view). At each pixel both planes'
// view distances are computed exactly; the farther plane "wins" the depth
// test wrongly when its stored depth is not larger than the near plane's.
//
//   const double share = zbuffer::zfight_share(zbuffer::DepthFormat::float_z,
//                                              {0.1f, 1000}, scene);
#pragma once

#include "depth_formats.hpp"
#include "rasterlab/image.hpp"

namespace zbuffer {

struct TwoPlanes {
    double distance = 100;  // along the view axis to the near plane
    double gap = 0.01;      // between the planes, along their normal
    int size = 256;         // pixels across the (square) image
};

// The smallest and largest view distance of the near plane over the image:
// what a tightly fitted near/far range must cover.
struct Extent {
    double nearest, farthest;
};
Extent visible_extent(const TwoPlanes& scene);

// A range fitted to the scene: 1% margin on each side.
DepthRange fitted_range(const TwoPlanes& scene);

// The share of pixels (0..1) where the far plane is not behind the near one
// in the stored depth: z-fighting.
double zfight_share(DepthFormat format, DepthRange range, const TwoPlanes& scene);

// The same as a picture: the near plane light grey, the pixels that the far
// plane wrongly wins red.
rl::Image zfight_map(DepthFormat format, DepthRange range, const TwoPlanes& scene);

}  // namespace zbuffer
