// globe: a UV sphere with continents from noise. Its relief exists only as
// texture: a height map, the tangent-space and object-space normal maps
// derived from it analytically, and a specular map (oceans shine).
#include <cmath>
#include <numbers>

#include "globe_relief.hpp"
#include "model_builder.hpp"
#include "models.hpp"
#include "texture_maps.hpp"

namespace assets {
namespace {

constexpr double kRadius = kGlobeRadius;
constexpr int kSlices = 64, kStacks = 32;                  // about 4k triangles
constexpr int kTextureWidth = 1024, kTextureHeight = 512;  // equirectangular

Model globe_mesh() {
    Model m;
    m.name = "globe";
    m.comment = "# globe: UV sphere, radius 0.9, 64 slices x 32 stacks; u east, v north\n";
    m.mtl_lines = {"map_Kd globe_diffuse.png", "map_Bump globe_nm_tangent.png",
                   "map_Ks globe_spec.png"};
    const int south = m.add_position({0, -kRadius, 0});
    m.add_normal({0, -1, 0});
    const int north = m.add_position({0, kRadius, 0});
    m.add_normal({0, 1, 0});
    for (int j = 1; j < kStacks; ++j)
        for (int i = 0; i < kSlices; ++i) {
            const dvec3 n = sphere_point(double(i) / kSlices, double(j) / kStacks).normal;
            m.add_position(n * kRadius);
            m.add_normal(n);
        }
    auto position = [&](int i, int j) {
        if (j == 0) return south;
        if (j == kStacks) return north;
        return 2 + (j - 1) * kSlices + i % kSlices;  // the seam shares positions
    };
    const int first_uv = static_cast<int>(m.uvs.size());
    for (int j = 0; j <= kStacks; ++j)
        for (int i = 0; i <= kSlices; ++i) m.add_uv({double(i) / kSlices, double(j) / kStacks});
    auto uv = [&](int i, int j) { return first_uv + j * (kSlices + 1) + i; };
    for (int j = 0; j < kStacks; ++j)
        for (int i = 0; i < kSlices; ++i) {
            const int a = position(i, j), b = position(i + 1, j), c = position(i + 1, j + 1),
                      d = position(i, j + 1);
            if (j == 0) {  // south cap: the pole's u is the middle of the slice
                const int pole_uv = m.add_uv({(i + 0.5) / kSlices, 0.0});
                m.add_face({a, c, d}, {pole_uv, uv(i + 1, 1), uv(i, 1)}, {a, c, d});
            } else if (j == kStacks - 1) {
                const int pole_uv = m.add_uv({(i + 0.5) / kSlices, 1.0});
                m.add_face({a, b, c}, {uv(i, j), uv(i + 1, j), pole_uv}, {a, b, c});
            } else {
                m.add_face({a, b, c}, {uv(i, j), uv(i + 1, j), uv(i + 1, j + 1)}, {a, b, c});
                m.add_face({a, c, d}, {uv(i, j), uv(i + 1, j + 1), uv(i, j + 1)}, {a, c, d});
            }
        }
    return m;
}

// The colour of the ground at a point of the unit sphere.
dvec3 surface_colour(dvec3 p) {
    const double h = globe_terrain(p) - kGlobeSeaLevel;
    if (h < 0) return mix({0.02, 0.07, 0.24}, {0.08, 0.32, 0.55}, smoothstep(-0.35, 0.0, h));
    const double ice = smoothstep(0.95, 0.98, std::abs(p.y) + 0.05 * fbm(p * 9.0, 3));
    dvec3 land = mix({0.18, 0.42, 0.13}, {0.52, 0.42, 0.26}, smoothstep(0.05, 0.4, h));
    land = mix(land, {0.92, 0.93, 0.95}, std::max(ice, smoothstep(0.5, 0.62, h)));
    return land;
}

}  // namespace

void make_globe(const std::filesystem::path& dir) {
    write_model(dir, globe_mesh());

    rl::Image diffuse(kTextureWidth, kTextureHeight), specular(kTextureWidth, kTextureHeight);
    rl::Image tangent_space(kTextureWidth, kTextureHeight),
        object_space(kTextureWidth, kTextureHeight);
    HeightField height(kTextureWidth, kTextureHeight);
    for (int y = 0; y < kTextureHeight; ++y)
        for (int x = 0; x < kTextureWidth; ++x) {
            const SpherePoint s =
                sphere_point((x + 0.5) / kTextureWidth, (y + 0.5) / kTextureHeight);
            const dvec3 p = s.normal;
            height.set(x, y, globe_relief(p));
            diffuse.set(x, y, to_rgba(surface_colour(p)));
            const bool ocean = globe_terrain(p) < kGlobeSeaLevel;
            const double shine = ocean ? 0.9 : 0.1;
            specular.set(x, y, to_rgba({shine, shine, shine}));

            const Slopes slope = globe_slopes(s);
            const double slope_t = slope.along_tangent, slope_b = slope.along_bitangent;
            // The bumped normal, in tangent space (T, B, N) and in object space.
            tangent_space.set(x, y, encode_normal({-slope_t, -slope_b, 1}));
            object_space.set(x, y,
                             encode_normal(s.normal - s.tangent * slope_t - s.bitangent * slope_b));
        }
    write_texture(dir, "globe", "diffuse", ".png", diffuse);
    write_texture(dir, "globe", "spec", ".png", specular);
    write_texture(dir, "globe", "nm_tangent", ".png", tangent_space);
    write_texture(dir, "globe", "nm", ".png", object_space);
    write_texture(dir, "globe", "height", ".png", grey_image(height, 0.0, 0.6));
}

}  // namespace assets
