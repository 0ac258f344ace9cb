#include "flat_shading.hpp"

#include <algorithm>
#include <cmath>

#include "01_lines/viewport.hpp"

namespace triangles {

float lambert(rl::vec3 normal, rl::vec3 to_light) {
    return std::max(0.0f, rl::dot(rl::normalize(normal), rl::normalize(to_light)));
}

rl::Rgba lit(rl::Rgba colour, float light) {
    const auto scale = [light](std::uint8_t c) {
        return static_cast<std::uint8_t>(std::lround(c * light));
    };
    return {scale(colour.r), scale(colour.g), scale(colour.b), 255};
}

// [doc:flat-shading]
DrawCounts draw_flat_shaded(rl::Image& image, const rl::Mesh& mesh, const FlatOptions& options) {
    DrawCounts stats;
    for (const rl::Triangle& face : mesh.triangles) {
        Triangle2 screen;
        rl::vec3 world[3];
        for (int k = 0; k < 3; ++k) {
            world[k] = mesh.position(face, k);
            screen.v[k] =
                lines::orthographic_to_window(world[k], image.width(), image.height()).xy();
        }
        // Counter-clockwise on screen means facing the viewer (who looks down -z).
        if (options.cull_back_faces && signed_area2(screen) <= 0) {
            ++stats.culled;
            continue;
        }
        const rl::vec3 normal = rl::cross(world[1] - world[0], world[2] - world[0]);
        const rl::Rgba colour = lit(options.colour, lambert(normal, options.light_direction));
        const bool ok = rasterize(options.method, screen, image.width(), image.height(),
                                  [&](int x, int y, rl::vec3) { image.at(x, y) = colour; });
        ++(ok ? stats.drawn : stats.refused);
    }
    return stats;
}
// [/doc:flat-shading]

rl::Image three_triangles(RasterMethod method) {
    rl::Image image(200, 200, rl::Rgba{0, 0, 0, 255});
    const Triangle2 triangles[3] = {{{{10, 70}, {50, 160}, {70, 80}}},
                                    {{{180, 50}, {150, 1}, {70, 180}}},
                                    {{{180, 150}, {120, 160}, {130, 180}}}};
    const rl::Rgba colours[3] = {{255, 0, 0, 255}, {255, 255, 255, 255}, {0, 255, 0, 255}};
    for (int i = 0; i < 3; ++i)
        rasterize(method, triangles[i], 200, 200,
                  [&](int x, int y, rl::vec3) { image.at(x, y) = colours[i]; });
    return image;
}

}  // namespace triangles
