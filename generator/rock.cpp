// rock: an icosphere subdivided four times, jittered and displaced by noise,
// so its triangles are as irregular as a scanned model's. Spherical UVs, with
// the seam's triangles given their own texture coordinates past u = 1.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>

#include "model_builder.hpp"
#include "models.hpp"
#include "rasterlab/random.hpp"
#include "texture_maps.hpp"

namespace assets {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSubdivisions = 4;  // 20 * 4^4 = 5120 triangles
constexpr int kSize = 512;

struct Icosphere {
    std::vector<dvec3> points;              // on the unit sphere
    std::vector<std::array<int, 3>> faces;  // counter-clockwise from outside
};

Icosphere icosahedron() {
    const double g = (1 + std::sqrt(5.0)) / 2;
    Icosphere s;
    for (dvec3 p : {dvec3{-1, g, 0}, dvec3{1, g, 0}, dvec3{-1, -g, 0}, dvec3{1, -g, 0},
                    dvec3{0, -1, g}, dvec3{0, 1, g}, dvec3{0, -1, -g}, dvec3{0, 1, -g},
                    dvec3{g, 0, -1}, dvec3{g, 0, 1}, dvec3{-g, 0, -1}, dvec3{-g, 0, 1}})
        s.points.push_back(rl::normalize(p));
    s.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
               {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    return s;
}

// Splits every triangle into four, putting the new points on the sphere.
void subdivide(Icosphere& s) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
        const auto key = std::minmax(a, b);
        const auto found = midpoints.find(key);
        if (found != midpoints.end()) return found->second;
        s.points.push_back(rl::normalize(s.points[a] + s.points[b]));
        const int index = static_cast<int>(s.points.size()) - 1;
        midpoints.emplace(key, index);
        return index;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : s.faces) {
        const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        finer.push_back({a, ab, ca});
        finer.push_back({b, bc, ab});
        finer.push_back({c, ca, bc});
        finer.push_back({ab, bc, ca});
    }
    s.faces = std::move(finer);
}

dvec2 spherical_uv(dvec3 d) {
    return {std::atan2(d.x, d.z) / (2 * kPi) + 0.5,
            std::asin(std::clamp(d.y, -1.0, 1.0)) / kPi + 0.5};
}

Model rock_mesh() {
    Icosphere sphere = icosahedron();
    for (int i = 0; i < kSubdivisions; ++i) subdivide(sphere);

    rl::SplitMix64 random(20261122);
    Model m;
    m.name = "rock";
    m.comment =
        "# rock: icosphere (4 subdivisions) jittered and displaced by noise; "
        "spherical uv\n";
    m.mtl_lines = {"map_Kd rock_diffuse.png", "map_Bump rock_nm_tangent.png"};
    std::vector<dvec3> directions;
    for (const dvec3& p : sphere.points) {
        // Jitter along the surface by up to a third of an edge, then displace.
        const dvec3 jitter{random.uniform() - 0.5, random.uniform() - 0.5, random.uniform() - 0.5};
        const dvec3 d = rl::normalize(p + jitter * 0.04);
        const double radius =
            std::min(0.78 * (1 + 0.28 * fbm(d * 1.4 + dvec3{5.5, 1.2, 8.8}, 5)), 0.98);
        directions.push_back(d);
        m.add_position(d * radius);
    }
    // Texture coordinates per position, plus a copy shifted by u + 1 for the
    // triangles that straddle the seam (so that their u does not run backwards).
    for (const dvec3& d : directions) m.add_uv(spherical_uv(d));
    std::map<int, int> shifted;
    auto shifted_uv = [&](int p) {
        const auto found = shifted.find(p);
        if (found != shifted.end()) return found->second;
        const int t = m.add_uv(m.uvs[p] + dvec2{1, 0});
        shifted.emplace(p, t);
        return t;
    };
    for (const auto& f : sphere.faces) {
        std::array<int, 3> t = f;
        const double u[3] = {m.uvs[f[0]].x, m.uvs[f[1]].x, m.uvs[f[2]].x};
        if (std::max({u[0], u[1], u[2]}) - std::min({u[0], u[1], u[2]}) > 0.5)
            for (int k = 0; k < 3; ++k)
                if (u[k] < 0.5) t[k] = shifted_uv(f[k]);
        m.add_face(f, t, f);
    }
    compute_smooth_normals(m);
    return m;
}

}  // namespace

void make_rock(const std::filesystem::path& dir) {
    write_model(dir, rock_mesh());
    rl::Image diffuse(kSize, kSize);
    HeightField height(kSize, kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double u = (x + 0.5) / kSize, v = (y + 0.5) / kSize;
            const double coarse = tileable_fbm(u, v, 8, 6, 1);
            const double lichen = smoothstep(0.25, 0.35, tileable_fbm(u, v, 4, 4, 2));
            dvec3 stone = mix({0.36, 0.33, 0.30}, {0.58, 0.55, 0.50}, 0.5 + 0.6 * coarse);
            stone = mix(stone, {0.45, 0.50, 0.22}, 0.7 * lichen);
            diffuse.set(x, y, to_rgba(stone));
            height.set(x, y, 6 * coarse + 2 * tileable_fbm(u, v, 64, 3, 3));
        }
    write_texture(dir, "rock", "diffuse", ".png", diffuse);
    write_texture(dir, "rock", "nm_tangent", ".png", tangent_normal_map(height, 1.0, true));
}

}  // namespace assets
