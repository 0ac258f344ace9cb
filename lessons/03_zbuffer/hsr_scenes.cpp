#include "hsr_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rasterlab/random.hpp"

namespace zbuffer {
namespace {

void add_quad(std::vector<SceneTriangle>& out, rl::vec3 a, rl::vec3 b, rl::vec3 c, rl::vec3 d,
              rl::Rgba colour, int id) {
    out.push_back({{a, b, c}, colour, id});
    out.push_back({{a, c, d}, colour, id});
}

}  // namespace

std::vector<SceneTriangle> cyclic_sticks(int size) {
    std::vector<SceneTriangle> out;
    const float s = static_cast<float>(size), r = 0.33f * s, half_width = 0.05f * s;
    const rl::vec2 centre{0.5f * s, 0.5f * s};
    rl::vec2 corner[3];
    for (int i = 0; i < 3; ++i) {
        const float angle = std::numbers::pi_v<float> * (0.5f + 2.0f * i / 3.0f);
        corner[i] = centre + rl::vec2{std::cos(angle), std::sin(angle)} * r;
    }
    const rl::Rgba colours[3] = {{220, 80, 60, 255}, {80, 180, 90, 255}, {70, 110, 220, 255}};
    for (int i = 0; i < 3; ++i) {
        // Stick i runs past corner i to past corner i+1, from near (0.3) to far (0.7).
        const rl::vec2 a = corner[i], b = corner[(i + 1) % 3], along = (b - a) * 0.25f;
        const rl::vec2 start = a - along, end = b + along;
        const rl::vec2 dir = rl::normalize(end - start),
                       across{-dir.y * half_width, dir.x * half_width};
        auto at = [](rl::vec2 p, float z) { return rl::vec3{p.x, p.y, z}; };
        add_quad(out, at(start - across, 0.3f), at(end - across, 0.7f), at(end + across, 0.7f),
                 at(start + across, 0.3f), colours[i], i);
    }
    return out;
}

std::vector<SceneTriangle> random_soup(int count, int size, std::uint64_t seed) {
    rl::SplitMix64 random(seed);
    std::vector<SceneTriangle> out;
    const double s = size;
    for (int i = 0; i < count; ++i) {
        SceneTriangle t;
        const rl::dvec2 c{random.uniform(0.2 * s, 0.8 * s), random.uniform(0.2 * s, 0.8 * s)};
        for (rl::vec3& v : t.v)
            v = {static_cast<float>(c.x + random.uniform(-0.25, 0.25) * s),
                 static_cast<float>(c.y + random.uniform(-0.25, 0.25) * s),
                 static_cast<float>(random.uniform(0.1, 0.9))};
        if (triangles::signed_area2(screen(t)) < 0) std::swap(t.v[1], t.v[2]);
        const auto shade = static_cast<std::uint8_t>(60 + (i * 37) % 190);
        t.colour = {shade, static_cast<std::uint8_t>(255 - shade), 128, 255};
        t.id = i;
        out.push_back(t);
    }
    return out;
}

std::vector<SceneTriangle> coplanar_pair(int size) {
    const float s = static_cast<float>(size);
    const rl::vec3 a{0.1f * s, 0.1f * s, 0.5f}, b{0.9f * s, 0.2f * s, 0.5f},
        c{0.4f * s, 0.9f * s, 0.5f};
    return {{{a, b, c}, {200, 60, 60, 255}, 0}, {{a, b, c}, {60, 60, 200, 255}, 1}};
}

double wrong_share(const Frame& frame, const Frame& reference) {
    long covered = 0, wrong = 0;
    const auto& mine = frame.ids.pixels();
    const auto& truth = reference.ids.pixels();
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (truth[i] < 0 && mine[i] < 0) continue;
        ++covered;
        wrong += mine[i] != truth[i];
    }
    return covered ? static_cast<double>(wrong) / static_cast<double>(covered) : 0.0;
}

std::vector<SceneTriangle> program_scene(const std::string& name,
                                         const std::vector<Placement>& placements, int width,
                                         int height, std::vector<std::string>& warnings,
                                         std::size_t& culled) {
    const int size = std::min(width, height);
    if (name == "sticks") return cyclic_sticks(size);
    if (name == "soup") return random_soup(60, size, 9);
    return build_scene(placements, width, height, &warnings, &culled);
}

}  // namespace zbuffer
