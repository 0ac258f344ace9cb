#include "flat_shading.hpp"

#include <algorithm>
#include <cmath>

#include "01_lines/viewport.hpp"
#include "draw_faces.hpp"

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

rl::Rgba face_colour(const rl::Mesh& mesh, const rl::Face& face, const FlatOptions& options) {
    const rl::vec3 p0 = mesh.position(face, 0), p1 = mesh.position(face, 1),
                   p2 = mesh.position(face, 2);
    return lit(options.colour, lambert(rl::cross(p1 - p0, p2 - p0), options.light_direction));
}

// [doc:flat-shading]
DrawCounts draw_flat_shaded(rl::Image& image, const rl::Mesh& mesh, const FlatOptions& options) {
    std::vector<rl::Rgba> colours;  // one per face: flat shading
    for (const rl::Face& face : mesh.faces) colours.push_back(face_colour(mesh, face, options));
    const int width = image.width(), height = image.height();
    return draw_faces(
        mesh, width, height, {options.method, options.cull_back_faces},
        [&](const rl::Face& face, int corner) {  // the vertex stage: where the corner goes
            return lines::orthographic_to_window(mesh.position(face, corner), width, height);
        },
        [&](const WindowTriangle& t, int x, int y, rl::vec3) {  // the fragment stage: its colour
            image.at(x, y) = colours[static_cast<std::size_t>(t.face)];
        });
}
// [/doc:flat-shading]

rl::Image three_triangles(RasterMethod method) {
    rl::Image image(200, 200, rl::Rgba{0, 0, 0, 255});
    const ScreenTriangle shapes[3] = {{{{10, 70}, {50, 160}, {70, 80}}},
                                      {{{180, 50}, {150, 1}, {70, 180}}},
                                      {{{180, 150}, {120, 160}, {130, 180}}}};
    const rl::Rgba colours[3] = {{255, 0, 0, 255}, {255, 255, 255, 255}, {0, 255, 0, 255}};
    for (int i = 0; i < 3; ++i)
        rasterize(method, shapes[i], 200, 200,
                  [&](int x, int y, rl::vec3) { image.at(x, y) = colours[i]; });
    return image;
}

}  // namespace triangles
