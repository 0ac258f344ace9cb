#include "triangle_measure.hpp"

#include <cmath>
#include <numbers>

#include "rasterlab/random.hpp"

namespace triangles {
namespace {

__extension__ typedef __int128 Wide;  // exact products of 1/256-pixel coordinates

struct Exact {
    Wide x, y;
};

Exact exact_snap(rl::vec2 p) {
    return {static_cast<Wide>(std::llround(static_cast<double>(p.x) * 256.0)),
            static_cast<Wide>(std::llround(static_cast<double>(p.y) * 256.0))};
}

int sign(Wide v) {
    return (v > 0) - (v < 0);
}

// The sign of the edge function at p + (e, -e^2) for an infinitesimal e.
int perturbed_side(Exact a, Exact b, Exact p) {
    const Wide dx = b.x - a.x, dy = b.y - a.y;
    const Wide value = dx * (p.y - a.y) - dy * (p.x - a.x);
    if (value != 0) return sign(value);
    if (dy != 0) return sign(-dy);  // the e term: d/dx of the edge function is -dy
    return sign(-dx);               // the -e^2 term: d/dy is dx
}

}  // namespace

// [doc:reference-coverage]
bool reference_covers(const ScreenTriangle& t, int x, int y) {
    const Exact v[3] = {exact_snap(t.v[0]), exact_snap(t.v[1]), exact_snap(t.v[2])};
    const int orientation =
        sign((v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x));
    if (orientation == 0) return false;
    const Exact centre{Wide{x} * 256 + 128, Wide{y} * 256 + 128};
    for (int k = 0; k < 3; ++k)
        if (perturbed_side(v[k], v[(k + 1) % 3], centre) != orientation) return false;
    return true;
}
// [/doc:reference-coverage]

std::vector<std::pair<int, int>> covered_pixels(RasterMethod method, const ScreenTriangle& t,
                                                int width, int height) {
    std::vector<std::pair<int, int>> pixels;
    rasterize(method, t, width, height, [&](int x, int y, rl::vec3) { pixels.push_back({x, y}); });
    return pixels;
}

CoverageScore score_coverage(RasterMethod method, const std::vector<ScreenTriangle>& batch,
                             int width, int height) {
    CoverageScore score;
    rl::Grid<std::uint8_t> mine(width, height, 0);
    for (const ScreenTriangle& t : batch) {
        ++score.triangles;
        const auto pixels = covered_pixels(method, t, width, height);
        for (const auto& [x, y] : pixels) mine.at(x, y) = 1;
        // Compare over the bounding box (every pixel the rule could cover).
        const PixelRange xs = centres_between(std::min({t.v[0].x, t.v[1].x, t.v[2].x}) - 1,
                                              std::max({t.v[0].x, t.v[1].x, t.v[2].x}) + 1, width);
        const PixelRange ys = centres_between(std::min({t.v[0].y, t.v[1].y, t.v[2].y}) - 1,
                                              std::max({t.v[0].y, t.v[1].y, t.v[2].y}) + 1, height);
        for (int y = ys.first; y <= ys.last; ++y)
            for (int x = xs.first; x <= xs.last; ++x) {
                const bool exact = reference_covers(t, x, y), drawn = mine.at(x, y) != 0;
                score.reference_pixels += exact;
                score.wrongly_set += drawn && !exact;
                score.missed += exact && !drawn;
            }
        for (const auto& [x, y] : pixels) mine.at(x, y) = 0;
    }
    return score;
}

WatertightScore score_watertight(RasterMethod method, const std::vector<ScreenTriangle>& mesh,
                                 int width, int height) {
    rl::Grid<std::uint8_t> count(width, height, 0), inside(width, height, 0);
    for (const ScreenTriangle& t : mesh) {
        rasterize(method, t, width, height, [&](int x, int y, rl::vec3) {
            if (count.at(x, y) < 255) ++count.at(x, y);
        });
        const PixelRange xs = centres_between(std::min({t.v[0].x, t.v[1].x, t.v[2].x}),
                                              std::max({t.v[0].x, t.v[1].x, t.v[2].x}), width);
        const PixelRange ys = centres_between(std::min({t.v[0].y, t.v[1].y, t.v[2].y}),
                                              std::max({t.v[0].y, t.v[1].y, t.v[2].y}), height);
        for (int y = ys.first; y <= ys.last; ++y)
            for (int x = xs.first; x <= xs.last; ++x)
                if (reference_covers(t, x, y)) inside.at(x, y) = 1;
    }
    WatertightScore score;
    for (std::size_t i = 0; i < count.pixels().size(); ++i) {
        score.pixels += inside.pixels()[i];
        score.double_covered += count.pixels()[i] >= 2;
        score.holes += inside.pixels()[i] && count.pixels()[i] == 0;
    }
    return score;
}

std::vector<ScreenTriangle> random_triangles(int count, double area, int size, std::uint64_t seed) {
    rl::SplitMix64 random(seed);
    std::vector<ScreenTriangle> out;
    while (static_cast<int>(out.size()) < count) {
        rl::dvec2 p[3];
        for (rl::dvec2& q : p) q = {random.uniform(), random.uniform()};
        const double a = 0.5 * std::abs(rl::cross(p[1] - p[0], p[2] - p[0]));
        if (a < 1e-6) continue;
        bool thin = false;  // reject angles under 15 degrees: slivers have their own tests
        for (int k = 0; k < 3; ++k) {
            const rl::dvec2 u = rl::normalize(p[(k + 1) % 3] - p[k]),
                            w = rl::normalize(p[(k + 2) % 3] - p[k]);
            if (std::acos(std::clamp(rl::dot(u, w), -1.0, 1.0)) < 15.0 * std::numbers::pi / 180)
                thin = true;
        }
        if (thin) continue;
        const double scale = std::sqrt(area / a);
        rl::dvec2 lo{1e9, 1e9}, hi{-1e9, -1e9};
        for (rl::dvec2& q : p) {
            q = q * scale;
            lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
            hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
        }
        const rl::dvec2 extent = hi - lo;
        if (extent.x >= size || extent.y >= size) continue;
        const rl::dvec2 shift{random.uniform(0, size - extent.x) - lo.x,
                              random.uniform(0, size - extent.y) - lo.y};
        ScreenTriangle t{{on_subpixel_grid(p[0].x + shift.x, p[0].y + shift.y),
                          on_subpixel_grid(p[1].x + shift.x, p[1].y + shift.y),
                          on_subpixel_grid(p[2].x + shift.x, p[2].y + shift.y)}};
        if (random.uniform() < 0.5) std::swap(t.v[1], t.v[2]);
        out.push_back(t);
    }
    return out;
}

std::vector<ScreenTriangle> tie_triangles(int count, int size, std::uint64_t seed) {
    rl::SplitMix64 random(seed);
    std::vector<ScreenTriangle> out;
    while (static_cast<int>(out.size()) < count) {
        const double cx = std::floor(random.uniform(8, size - 8)),
                     cy = std::floor(random.uniform(8, size - 8));
        ScreenTriangle t;
        for (rl::vec2& v : t.v)  // offsets in half pixels: corners and centres
            v = {static_cast<float>(cx + std::floor(random.uniform(-12, 13)) * 0.5),
                 static_cast<float>(cy + std::floor(random.uniform(-12, 13)) * 0.5)};
        if (signed_area2(t) != 0) out.push_back(t);
    }
    return out;
}

std::vector<ScreenTriangle> jittered_grid(int cells, int size, float margin, std::uint64_t seed) {
    rl::SplitMix64 random(seed);
    const double step = (size - 2.0 * margin) / cells;
    std::vector<rl::vec2> points;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const bool inner = i > 0 && j > 0 && i < cells && j < cells;
            const double jx = inner ? std::floor(random.uniform(-4, 5)) * 0.5 : 0;
            const double jy = inner ? std::floor(random.uniform(-4, 5)) * 0.5 : 0;
            points.push_back(on_subpixel_grid(std::round(margin + i * step) + jx,
                                              std::round(margin + j * step) + jy));
        }
    auto at = [&](int i, int j) { return points[static_cast<std::size_t>(j * (cells + 1) + i)]; };
    std::vector<ScreenTriangle> out;
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            out.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
            out.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
        }
    return out;
}

}  // namespace triangles
