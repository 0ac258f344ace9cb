// torus: a ring about the z axis, smooth everywhere, with a tile texture
// repeated 6 times around the ring and 3 times around the tube.
#include <cmath>
#include <numbers>

#include "model_builder.hpp"
#include "models.hpp"
#include "texture_maps.hpp"

namespace assets {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRing = 0.62, kTube = 0.3;  // outer radius 0.92
constexpr int kAround = 96, kTubeSegments = 36;
constexpr double kRepeatsU = 6, kRepeatsV = 3;
constexpr int kSize = 512;
constexpr int kTiles = 2;     // tiles along each side of the texture
constexpr double kGrout = 6;  // half the grout line's width, texels

Model torus_mesh() {
    Model m;
    m.name = "torus";
    m.comment =
        "# torus: ring radius 0.62, tube radius 0.3, about the z axis; "
        "uv tiled 6 x 3\n";
    m.mtl_lines = {"map_Kd torus_diffuse.png", "map_Bump torus_nm_tangent.png",
                   "map_Ks torus_spec.png"};
    for (int j = 0; j < kTubeSegments; ++j)
        for (int i = 0; i < kAround; ++i) {
            const double a = 2 * kPi * i / kAround, b = 2 * kPi * j / kTubeSegments;
            const dvec3 radial{std::cos(a), std::sin(a), 0};
            const dvec3 normal = radial * std::cos(b) + dvec3{0, 0, 1} * std::sin(b);
            m.add_position(radial * kRing + normal * kTube);
            m.add_normal(normal);
        }
    for (int j = 0; j <= kTubeSegments; ++j)
        for (int i = 0; i <= kAround; ++i)
            m.add_uv({kRepeatsU * i / kAround, kRepeatsV * j / kTubeSegments});
    auto vertex = [](int i, int j) { return (j % kTubeSegments) * kAround + i % kAround; };
    auto uv = [](int i, int j) { return j * (kAround + 1) + i; };
    for (int j = 0; j < kTubeSegments; ++j)
        for (int i = 0; i < kAround; ++i) {
            const int a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1),
                      d = vertex(i, j + 1);
            m.add_face({a, b, c}, {uv(i, j), uv(i + 1, j), uv(i + 1, j + 1)}, {a, b, c});
            m.add_face({a, c, d}, {uv(i, j), uv(i + 1, j + 1), uv(i, j + 1)}, {a, c, d});
        }
    return m;
}

}  // namespace

void make_torus(const std::filesystem::path& dir) {
    write_model(dir, torus_mesh());
    rl::Image diffuse(kSize, kSize), specular(kSize, kSize);
    HeightField height(kSize, kSize);
    const double tile = double(kSize) / kTiles;
    const dvec3 glazes[kTiles * kTiles] = {
        {0.12, 0.36, 0.52}, {0.80, 0.62, 0.22}, {0.78, 0.76, 0.70}, {0.20, 0.45, 0.30}};
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double cx = x + 0.5, cy = y + 0.5;
            // Distance to the nearest grout line; lines lie on the tile borders,
            // including the texture's edges, so the texture repeats seamlessly.
            const double gx = std::abs(std::remainder(cx, tile)),
                         gy = std::abs(std::remainder(cy, tile));
            const double grout_distance = std::min(gx, gy);
            const double glaze = smoothstep(kGrout, kGrout + 3, grout_distance);
            const int index = static_cast<int>(cy / tile) * kTiles + static_cast<int>(cx / tile);
            const double mottle = tileable_fbm(cx / kSize, cy / kSize, 16, 4, 5);
            const dvec3 tile_colour = glazes[index] * (0.92 + 0.15 * mottle);
            diffuse.set(x, y, to_rgba(mix({0.55, 0.53, 0.5}, tile_colour, glaze)));
            const double shine = 0.05 + 0.8 * glaze;
            specular.set(x, y, to_rgba({shine, shine, shine}));
            height.set(x, y, 3 * glaze + 0.3 * mottle);
        }
    write_texture(dir, "torus", "diffuse", ".png", diffuse);
    write_texture(dir, "torus", "spec", ".png", specular);
    write_texture(dir, "torus", "nm_tangent", ".png", tangent_normal_map(height, 1.0, true));
}

}  // namespace assets
