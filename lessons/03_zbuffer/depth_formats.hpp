// How a depth buffer stores depth, and what that costs in precision. The
// lab's perspective study uses these; the program's orthographic z-buffer
// stores window depth as a float (the first format). Derivations and the
// measured precision: docs/03_zbuffer.md.
//
//   const double key = zbuffer::depth_key(zbuffer::DepthFormat::fixed16, w, {0.1f, 1000});
#pragma once

#include "rasterlab/named_enum.hpp"

#include <array>

namespace zbuffer {

enum class DepthFormat {
    float_z,      // OpenGL window depth (via NDC in [-1, 1]) stored as a 32-bit float
    fixed24,      // the same window depth as a 24-bit integer
    fixed16,      // ... as a 16-bit integer
    reverse_z,    // window depth mapped near -> 1, far -> 0, computed directly in [0, 1], float
    inverse_w,    // 1/w as a float (larger = nearer)
    linear_z,     // the view distance w itself as a float
    logarithmic,  // log(w / near) / log(far / near) as a float
};

RASTERLAB_NAMED_ENUM(DepthFormat, kDepthFormats, {DepthFormat::float_z, "float-z"},
                     {DepthFormat::fixed24, "fixed24"}, {DepthFormat::fixed16, "fixed16"},
                     {DepthFormat::reverse_z, "reverse-z"}, {DepthFormat::inverse_w, "inverse-w"},
                     {DepthFormat::linear_z, "linear-w"}, {DepthFormat::logarithmic, "log"});

struct DepthRange {
    float near_plane, far_plane;
};

// The value the buffer holds for a surface at view distance w (w = -z in eye
// space, near <= w <= far), computed in float the way a pipeline would, then
// rounded to the format. Returned as a double that holds that stored value
// exactly, signed so that smaller always means nearer: the depth test is
// `key < stored`. Two surfaces whose keys are equal cannot be told apart.
double depth_key(DepthFormat format, float w, DepthRange range);

}  // namespace zbuffer
