// Surfaces that show where tangent frames go wrong, for the lab, the tests
// and 07_failures:
//   mirrored_plane  the square [-1, 1]^2 in 8 x 8 cells whose u runs |x|
//                   (mirrored at x = 0, as symmetric models are painted),
//                   positions shared along the mirror line, with the crate's
//                   texture and maps. Its faces are planar with affine UVs,
//                   so each face's own frame is exact: the reference for the
//                   frames averaged across the mirror line;
//   low_poly_globe  the globe's texture and maps on a UV sphere of few
//                   segments, where each face's own frame turns sharply from
//                   its neighbours'.
//
//   const normal_mapping::MappedModel plane =
//       normal_mapping::mirrored_plane(TangentMethod::split, warnings);
#pragma once

#include "07_normal_mapping/scene.hpp"

namespace normal_mapping {

MappedModel mirrored_plane(TangentMethod method, std::vector<std::string>& warnings);
MappedModel low_poly_globe(int segments, TangentMethod method, std::vector<std::string>& warnings);

}  // namespace normal_mapping
