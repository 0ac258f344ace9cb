#include "draw_line.hpp"

#include <algorithm>
#include <cmath>

namespace lines {

void blend_pixel(rl::Image& image, int x, int y, rl::Rgba colour, float coverage) {
    if (!image.contains(x, y)) return;
    const float c = std::clamp(coverage, 0.0f, 1.0f);
    rl::Rgba& p = image.at(x, y);
    auto mix = [c](std::uint8_t under, std::uint8_t over) {
        return static_cast<std::uint8_t>(std::lround(under + (over - under) * c));
    };
    p = {mix(p.r, colour.r), mix(p.g, colour.g), mix(p.b, colour.b), p.a};
}

ClipResult draw_line(rl::Image& image, rl::vec2 a, rl::vec2 b, rl::Rgba colour, LineMethod method) {
    const ClippedSegment s = clip_segment(a, b, pixel_centres(image.width(), image.height()));
    if (s.result == ClipResult::refused || s.result == ClipResult::outside) return s.result;
    if (method == LineMethod::wu) {
        line_wu(s.a, s.b, [&](int x, int y, float c) { blend_pixel(image, x, y, colour, c); });
    } else {
        rasterize_line(method, s.a, s.b, [&](int x, int y, float) {
            if (image.contains(x, y)) image.at(x, y) = colour;
        });
    }
    return s.result;
}

}  // namespace lines
