#include "depth_formats.hpp"

#include <cmath>

namespace zbuffer {

namespace {

// OpenGL's perspective depth: NDC z = (f + n)/(f - n) - 2fn / ((f - n) w),
// then window depth = (z + 1) / 2. Half of float's precision near 1 is lost
// to the [-1, 1] detour, as on real OpenGL without glClipControl.
float opengl_window_depth(float w, DepthRange r) {
    const float n = r.near_plane, f = r.far_plane;
    const float ndc = (f + n) / (f - n) - (2.0f * f * n) / ((f - n) * w);
    return 0.5f * ndc + 0.5f;
}

double quantise(float depth, int bits) {
    const double levels = std::ldexp(1.0, bits) - 1.0;
    return std::round(static_cast<double>(depth) * levels);
}

}  // namespace

// [doc:depth-key]
double depth_key(DepthFormat format, float w, DepthRange r) {
    const float n = r.near_plane, f = r.far_plane;
    switch (format) {
        case DepthFormat::float_z:
            return opengl_window_depth(w, r);
        case DepthFormat::fixed24:
            return quantise(opengl_window_depth(w, r), 24);
        case DepthFormat::fixed16:
            return quantise(opengl_window_depth(w, r), 16);
        case DepthFormat::reverse_z:  // n (f - w) / (w (f - n)): 1 at the near plane, 0 at the far
                                      // one
            return -static_cast<double>((n * (f - w)) / (w * (f - n)));
        case DepthFormat::inverse_w:
            return -static_cast<double>(1.0f / w);
        case DepthFormat::linear_z:
            return w;
        case DepthFormat::logarithmic:
            return std::log(w / n) / std::log(f / n);
    }
    return 0;
}
// [/doc:depth-key]

}  // namespace zbuffer
