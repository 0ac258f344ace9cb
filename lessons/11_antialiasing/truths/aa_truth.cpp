#include "aa_truth.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "06_shading/colour.hpp"

namespace antialiasing {

// [doc:truth]
rl::Grid<rl::vec3> truth_light(const std::vector<normal_mapping::MappedModel>& models,
                               const pipeline::Camera& camera, const shadows::ShadowOptions& shadow,
                               int width, int height, int side, const AaOptions& tone) {
    if (side < 4 || side % 4 != 0)
        throw std::invalid_argument("the truth's grid side must be a multiple of 4");
    // The fine grid's offsets, cut into 4 x 4 blocks: one frame each.
    const float step = 1.0f / static_cast<float>(side);
    std::vector<double> sum(static_cast<std::size_t>(width) * height * 3, 0.0);
    const int blocks = side / 4;
    for (int bj = 0; bj < blocks; ++bj)
        for (int bi = 0; bi < blocks; ++bi) {
            std::vector<rl::vec2> offsets;
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i)
                    offsets.push_back({(static_cast<float>(bi * 4 + i) + 0.5f) * step - 0.5f,
                                       (static_cast<float>(bj * 4 + j) + 0.5f) * step - 0.5f});
            const SampleTarget frame = draw_samples(models, camera, shadow, Method::ssaa, offsets,
                                                    ShadeAt::centre, width, height);
            // Per sample (tone map before the mean) or linear (after it).
            AaOptions per_frame;
            per_frame.tone = tone.tone == ToneOrder::before_resolve ? ToneOrder::before_resolve
                                                                    : ToneOrder::none;
            per_frame.exposure_stops =
                tone.tone == ToneOrder::before_resolve ? tone.exposure_stops : 0;
            const rl::Grid<rl::vec3> light = shown_light(frame.colour(), offsets, per_frame);
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x) {
                    const rl::vec3 c = light.get(x, y);
                    double* s = &sum[(static_cast<std::size_t>(y) * width + x) * 3];
                    s[0] += c.x, s[1] += c.y, s[2] += c.z;
                }
        }
    rl::Grid<rl::vec3> out(width, height);
    const double frames = blocks * blocks;
    // The mean's own exposure and tone map, when they come after it.
    AaOptions after;
    after.tone = tone.tone == ToneOrder::before_resolve ? ToneOrder::none : tone.tone;
    after.exposure_stops = tone.tone == ToneOrder::before_resolve ? 0 : tone.exposure_stops;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double* s = &sum[(static_cast<std::size_t>(y) * width + x) * 3];
            out.at(x, y) = {static_cast<float>(s[0] / frames), static_cast<float>(s[1] / frames),
                            static_cast<float>(s[2] / frames)};
        }
    return shown_light(out, {{0, 0}}, after);
}
// [/doc:truth]

rl::Grid<std::uint8_t> depth_edges(const std::vector<normal_mapping::MappedModel>& models,
                                   const pipeline::Camera& camera,
                                   const shadows::ShadowOptions& shadow, int width, int height) {
    const SampleTarget frame = draw_samples(models, camera, shadow, Method::none, {{0, 0}},
                                            ShadeAt::centre, width, height);
    const rl::FloatImage& z = *frame.depth();
    const float clear = frame.depth_state.clear;
    // View depth from window depth: the inverse of (1/n - 1/d) / (1/n - 1/f).
    const double n = camera.near, f = camera.far;
    const auto view = [&](float w) { return 1 / (1 / n - w * (1 / n - 1 / f)); };
    rl::Grid<std::uint8_t> edges(width, height, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int j = std::max(0, y - 1); j <= std::min(height - 1, y + 1); ++j)
                for (int i = std::max(0, x - 1); i <= std::min(width - 1, x + 1); ++i) {
                    const bool here = z.get(x, y) < clear, there = z.get(i, j) < clear;
                    if (here != there || (here && std::abs(view(z.get(x, y)) - view(z.get(i, j))) >
                                                      0.02 * view(z.get(x, y))))
                        edges.at(x, y) = 1;
                }
    return edges;
}

namespace {

// A linear value as the eye compares it: sRGB in [0, 1].
double srgb(float v) {
    return shading::linear_to_srgb(std::clamp(static_cast<double>(v), 0.0, 1.0));
}

// The mean over channels of the sRGB difference, in [0, 1].
double difference(rl::vec3 a, rl::vec3 b) {
    return (std::abs(srgb(a.x) - srgb(b.x)) + std::abs(srgb(a.y) - srgb(b.y)) +
            std::abs(srgb(a.z) - srgb(b.z))) /
           3;
}

}  // namespace

AaError compare(const rl::Grid<rl::vec3>& truth, const rl::Grid<rl::vec3>& light,
                const rl::Grid<std::uint8_t>& edges) {
    AaError e;
    std::vector<double> all;
    for (int y = 0; y < truth.height(); ++y)
        for (int x = 0; x < truth.width(); ++x) {
            const double d = difference(truth.get(x, y), light.get(x, y));
            all.push_back(d);
            if (edges.get(x, y)) {
                e.edges += d, ++e.edge_pixels;
            } else {
                e.shading += d, ++e.other_pixels;
            }
        }
    if (e.edge_pixels) e.edges /= static_cast<double>(e.edge_pixels);
    if (e.other_pixels) e.shading /= static_cast<double>(e.other_pixels);
    if (!all.empty()) {
        const std::size_t k = all.size() * 95 / 100;
        std::nth_element(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(k), all.end());
        e.p95 = all[k];
    }
    return e;
}

double flicker(const rl::Grid<rl::vec3>& truth_before, const rl::Grid<rl::vec3>& truth_now,
               const rl::Grid<rl::vec3>& before, const rl::Grid<rl::vec3>& now,
               const rl::Grid<std::uint8_t>& edges_before,
               const rl::Grid<std::uint8_t>& edges_now) {
    double sum = 0;
    long count = 0;
    for (int y = 0; y < now.height(); ++y)
        for (int x = 0; x < now.width(); ++x) {
            if (!edges_before.get(x, y) && !edges_now.get(x, y)) continue;
            const rl::vec3 m0 = before.get(x, y), m1 = now.get(x, y), t0 = truth_before.get(x, y),
                           t1 = truth_now.get(x, y);
            sum += (std::abs((srgb(m1.x) - srgb(m0.x)) - (srgb(t1.x) - srgb(t0.x))) +
                    std::abs((srgb(m1.y) - srgb(m0.y)) - (srgb(t1.y) - srgb(t0.y))) +
                    std::abs((srgb(m1.z) - srgb(m0.z)) - (srgb(t1.z) - srgb(t0.z)))) /
                   3;
            ++count;
        }
    return count ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace antialiasing
