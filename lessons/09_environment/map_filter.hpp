// How an environment map is read between its texels. Cube maps and
// lat-long maps share the names; `bilinear` on a cube map filters each face
// alone (its edge texels clamp, so the faces' seams show), `seamless` reads
// across a face's edge from its neighbour, `trilinear` is seamless between
// two mip levels.
//
//   environment::MapFilter f = environment::MapFilter::seamless;
#pragma once

#include <array>

#include "rasterlab/named_enum.hpp"

namespace environment {

enum class MapFilter { nearest, bilinear, seamless, trilinear };
RASTERLAB_NAMED_ENUM(MapFilter, kMapFilters, {MapFilter::nearest, "nearest"},
                     {MapFilter::bilinear, "bilinear"}, {MapFilter::seamless, "seamless"},
                     {MapFilter::trilinear, "trilinear"});

}  // namespace environment
