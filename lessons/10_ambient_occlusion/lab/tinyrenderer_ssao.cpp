#include "tinyrenderer_ssao.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "rasterlab/workers.hpp"

namespace occlusion {

namespace {

// tinyrenderer's numbers: the box's half side in device coordinates, and
// the range check's reach in those half sides.
constexpr float kBoxHalfSide = 0.1f;
constexpr float kRangeCheck = 5;
constexpr float kDarkening = 0.4f;

float smoothstep01(float x) {
    const float t = std::clamp(x, 0.0f, 1.0f);
    return t * t * (3 - 2 * t);
}

}  // namespace

rl::FloatImage tinyrenderer_ssao(const Surfaces& surfaces, int samples, std::uint32_t seed) {
    const Screen& screen = surfaces.screen;
    const int width = surfaces.g.width(), height = surfaces.g.height();
    // A tenth of the half screen, in pixels (its box is square in device
    // coordinates: the same reach across and down).
    const float box_pixels = kBoxHalfSide * 0.5f * static_cast<float>(width);
    rl::FloatImage ao(width, height, 1.0f);
    rl::parallel_for(0, height, [&](int y) {
        std::mt19937 random(seed * 2654435761u + static_cast<std::uint32_t>(y));
        std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
        for (int x = 0; x < width; ++x) {
            const float depth = surfaces.depth.get(x, y);
            if (std::isnan(depth)) continue;
            const rl::vec3 p = surfaces.position.get(x, y);
            const float half_side = box_pixels / screen.pixels_per_unit(depth);
            int voters = 0, votes = 0;
            for (int i = 0; i < samples; ++i) {
                const rl::vec3 s =
                    p + rl::vec3{unit(random), unit(random), unit(random)} * half_side;
                const rl::vec3 w = screen.project(s);
                if (!surfaces.inside(w.x, w.y)) continue;
                // No model there: its buffer holds the far clear value, which
                // hides nothing and passes the range check.
                const float buffer =
                    surfaces.depth.get(static_cast<int>(w.x), static_cast<int>(w.y));
                if (!std::isnan(buffer) && depth - buffer > kRangeCheck * half_side) continue;
                ++voters;
                if (!std::isnan(buffer) && buffer < w.z) ++votes;
            }
            if (voters > 0)
                ao.at(x, y) = smoothstep01(1 - kDarkening * static_cast<float>(votes) /
                                                   static_cast<float>(voters));
        }
    });
    return ao;
}

}  // namespace occlusion
