#include "line_measure.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "01_lines/line_clip.hpp"
#include "rasterlab/random.hpp"

namespace lines {

std::vector<Segment> random_segments(int count, int size, std::uint64_t seed) {
    rl::SplitMix64 random(seed);
    std::vector<Segment> segments;
    const double longest = 0.9 * size;
    while (static_cast<int>(segments.size()) < count) {
        const double length = 2.0 * std::pow(longest / 2.0, random.uniform());
        const double angle = random.uniform(0, 2 * std::numbers::pi);
        const int dx = static_cast<int>(std::lround(length * std::cos(angle)));
        const int dy = static_cast<int>(std::lround(length * std::sin(angle)));
        const int x0 = static_cast<int>(random.uniform(std::max(0, -dx), size - std::max(0, dx)));
        const int y0 = static_cast<int>(random.uniform(std::max(0, -dy), size - std::max(0, dy)));
        if (x0 + dx < 0 || x0 + dx >= size || y0 + dy < 0 || y0 + dy >= size) continue;
        segments.push_back({{x0 + 0.5f, y0 + 0.5f}, {x0 + dx + 0.5f, y0 + dy + 0.5f}});
    }
    return segments;
}

std::vector<Segment> moved_segments(std::vector<Segment> segments, int size, double spread,
                                    std::uint64_t seed) {
    rl::SplitMix64 random(seed);
    const double centre = 0.5 * size;
    auto move = [&](rl::vec2 p) {
        const double x = p.x + random.uniform(-0.49, 0.49), y = p.y + random.uniform(-0.49, 0.49);
        return rl::vec2{static_cast<float>(centre + (x - centre) * spread),
                        static_cast<float>(centre + (y - centre) * spread)};
    };
    for (Segment& s : segments) s = {move(s.a), move(s.b)};
    return segments;
}

std::vector<PlottedPixel> plotted_pixels(LineMethod method, Segment s, int width, int height) {
    std::vector<PlottedPixel> pixels;
    const ClippedSegment c = clip_segment(s.a, s.b, pixel_centres(width, height));
    if (c.result == ClipResult::refused || c.result == ClipResult::outside) return pixels;
    rasterize_line(method, c.a, c.b, [&](int x, int y, float coverage) {
        pixels.push_back({x, y, coverage});
    });
    return pixels;
}

double distance_to_segment(rl::dvec2 p, Segment s) {
    const rl::dvec2 a = rl::cast<double>(s.a), b = rl::cast<double>(s.b);
    const rl::dvec2 d = b - a;
    const double length_squared = rl::dot(d, d);
    const double t =
        length_squared > 0 ? std::clamp(rl::dot(p - a, d) / length_squared, 0.0, 1.0) : 0.0;
    return rl::length(p - (a + d * t));
}

// [doc:exact-coverage]
double exact_coverage(int x, int y, Segment s) {
    const rl::dvec2 a = rl::cast<double>(s.a), b = rl::cast<double>(s.b);
    const double length = rl::length(b - a);
    if (length == 0) return 0;
    const rl::dvec2 along = (b - a) / length, across{-along.y, along.x};
    constexpr int n = 16;
    int inside = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const rl::dvec2 p{x + (i + 0.5) / n, y + (j + 0.5) / n};
            const double t = rl::dot(p - a, along), d = rl::dot(p - a, across);
            if (t >= 0 && t <= length && std::abs(d) <= 0.5) ++inside;
        }
    return static_cast<double>(inside) / (n * n);
}
// [/doc:exact-coverage]

void score_segment(LineMethod method, Segment whole, int width, int height, LineScore& score) {
    const ClippedSegment visible = clip_segment(whole.a, whole.b, pixel_centres(width, height));
    if (visible.result == ClipResult::refused || visible.result == ClipResult::outside) return;
    const Segment s{visible.a, visible.b};
    const std::vector<PlottedPixel> pixels = plotted_pixels(method, whole, width, height);
    ++score.segments;
    score.length += rl::length(rl::cast<double>(s.b - s.a));
    score.plot_calls += static_cast<long>(pixels.size());

    // Coverage drawn per pixel (repeated plots add up, as blending would, capped at 1).
    std::map<std::pair<int, int>, double> drawn;
    for (const PlottedPixel& p : pixels)
        drawn[{p.x, p.y}] = std::min(1.0, drawn[{p.x, p.y}] + p.coverage);

    // Distances, gaps and duplicates: for every major-axis column, one pixel is ideal.
    const bool x_major = std::abs(s.b.x - s.a.x) >= std::abs(s.b.y - s.a.y);
    const int first = pixel_of(x_major ? s.a.x : s.a.y), last = pixel_of(x_major ? s.b.x : s.b.y);
    std::map<int, int> per_column;
    for (const PlottedPixel& p : pixels) {
        if (p.coverage <= 0) continue;
        ++per_column[x_major ? p.x : p.y];
    }
    for (int c = std::min(first, last); c <= std::max(first, last); ++c) {
        const auto found = per_column.find(c);
        const int n = found == per_column.end() ? 0 : found->second;
        if (n == 0) ++score.gaps;
        score.duplicates += std::max(0, n - 1);
    }
    for (const auto& [pixel, coverage] : drawn) {
        const double d = distance_to_segment({pixel.first + 0.5, pixel.second + 0.5}, s);
        score.max_distance = std::max(score.max_distance, d);
        score.sum_distance += d;
        ++score.lit_pixels;
    }

    // Coverage error over every pixel near the segment or drawn.
    const int x0 = pixel_of(std::min(s.a.x, s.b.x)) - 2, x1 = pixel_of(std::max(s.a.x, s.b.x)) + 2;
    const int y0 = pixel_of(std::min(s.a.y, s.b.y)) - 2, y1 = pixel_of(std::max(s.a.y, s.b.y)) + 2;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const auto found = drawn.find({x, y});
            const double mine = found == drawn.end() ? 0.0 : found->second;
            if (found == drawn.end() && distance_to_segment({x + 0.5, y + 0.5}, s) > 1.5) continue;
            score.coverage_error += std::abs(mine - exact_coverage(x, y, s));
        }
}

}  // namespace lines
