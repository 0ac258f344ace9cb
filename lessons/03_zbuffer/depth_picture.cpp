#include "depth_picture.hpp"

#include <algorithm>
#include <cmath>

namespace zbuffer {

rl::Image depth_picture(const rl::FloatImage& depth) {
    float nearest = 1.0f, farthest = 0.0f;
    for (float z : depth.pixels())
        if (z < 1.0f) nearest = std::min(nearest, z), farthest = std::max(farthest, z);
    rl::Image picture(depth.width(), depth.height(), rl::Rgba{0, 0, 0, 255});
    const float span = std::max(farthest - nearest, 1e-6f);
    for (int y = 0; y < depth.height(); ++y)
        for (int x = 0; x < depth.width(); ++x) {
            const float z = depth.get(x, y);
            if (z >= 1.0f) continue;
            const auto level =
                static_cast<std::uint8_t>(std::lround(255.0f - 200.0f * (z - nearest) / span));
            picture.set(x, y, {level, level, level, 255});
        }
    return picture;
}

}  // namespace zbuffer
