#include "line_clip.hpp"

#include <cmath>

namespace lines {

Rect pixel_centres(int width, int height) {
    return {0.5, 0.5, width - 0.5, height - 0.5};
}

// [doc:liang-barsky]
ClippedSegment clip_segment(rl::vec2 a, rl::vec2 b, const Rect& r) {
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y))
        return {ClipResult::refused, a, b};
    const double dx = double(b.x) - a.x, dy = double(b.y) - a.y;
    // The segment is a + t (b - a), 0 <= t <= 1. Each side of the rectangle
    // is an inequality p * t <= q; entering sides raise t_in, leaving sides
    // lower t_out.
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - r.x_min, r.x_max - a.x, a.y - r.y_min, r.y_max - a.y};
    double t_in = 0, t_out = 1;
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return {ClipResult::outside, a, b};  // parallel and outside
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0)
            t_in = std::max(t_in, t);
        else
            t_out = std::min(t_out, t);
    }
    if (t_in > t_out) return {ClipResult::outside, a, b};
    if (t_in == 0 && t_out == 1) return {ClipResult::inside, a, b};
    auto at = [&](double t) {
        return rl::vec2{static_cast<float>(a.x + t * dx), static_cast<float>(a.y + t * dy)};
    };
    return {ClipResult::clipped, at(t_in), at(t_out)};
}
// [/doc:liang-barsky]

}  // namespace lines
