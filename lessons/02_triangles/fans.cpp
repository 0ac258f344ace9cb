#include "fans.hpp"

#include <cmath>
#include <numbers>

namespace triangles {

rl::vec2 on_subpixel_grid(double x, double y) {
    return {static_cast<float>(std::round(x * 256.0) / 256.0),
            static_cast<float>(std::round(y * 256.0) / 256.0)};
}

std::vector<ScreenTriangle> disc_fan(rl::vec2 centre, float radius, int slices) {
    std::vector<ScreenTriangle> out;
    auto rim = [&](int i) {
        const double angle = 2 * std::numbers::pi * i / slices;
        return on_subpixel_grid(centre.x + radius * std::cos(angle),
                                centre.y + radius * std::sin(angle));
    };
    for (int i = 0; i < slices; ++i) out.push_back({{centre, rim(i), rim(i + 1)}});
    return out;
}

}  // namespace triangles
