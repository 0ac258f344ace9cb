#include "ao_truth.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "05_perspective/truths/ray_truth.hpp"
#include "rasterlab/workers.hpp"

namespace occlusion {

// [doc:truth-frame]
TruthFrame truth_frame(const RayTracedAo& rays, const pipeline::Camera& camera, int width,
                       int height, double radius, int count) {
    TruthFrame out{rl::FloatImage(width, height, NAN), rl::FloatImage(width, height, NAN)};
    const pipeline::RayCamera eye(camera, width, height);
    rl::parallel_for(0, height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            const rl::dvec3 d = eye.direction(x + 0.5, y + 0.5);  // t along it is view depth
            const std::optional<RayTracedAo::Hit> hit =
                rays.first_hit(eye.eye(), d, eye.near(), eye.far());
            if (!hit) continue;
            out.depth.at(x, y) = static_cast<float>(hit->t);
            out.ao.at(x, y) =
                static_cast<float>(rays.at(eye.eye() + d * hit->t, hit->normal, radius, count,
                                           static_cast<std::uint32_t>(y * width + x)));
        }
    });
    return out;
}
// [/doc:truth-frame]

AoError compare(const TruthFrame& truth, const rl::FloatImage& ao, const GBuffer& g,
                const Screen& screen, double radius) {
    const int w = g.width(), h = g.height();
    // Depth edges: a neighbour (4-connected) with no model, or nearer or
    // farther by more than half the radius; then every pixel within 3 of one.
    rl::Grid<int> edge(w, h, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float d = truth.depth.get(x, y);
            for (auto [i, j] : {std::pair{x + 1, y}, {x, y + 1}}) {
                if (i >= w || j >= h) continue;
                const float e = truth.depth.get(i, j);
                if (std::isnan(d) != std::isnan(e) ||
                    (!std::isnan(d) && std::fabs(d - e) > 0.5 * radius)) {
                    for (int b = std::max(0, y - 3); b <= std::min(h - 1, j + 3); ++b)
                        for (int a = std::max(0, x - 3); a <= std::min(w - 1, i + 3); ++a)
                            edge.at(a, b) = 1;
                }
            }
        }
    std::vector<double> inner;
    AoError out;
    double edge_sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float t = truth.ao.get(x, y), d = truth.depth.get(x, y);
            const float z = g.depth()->get(x, y);
            if (std::isnan(t) || !(z < g.depth_state.clear)) continue;
            if (std::fabs(screen.view_depth(z) - d) > 0.01f * d) continue;  // another surface
            const double e = std::fabs(static_cast<double>(ao.get(x, y)) - t);
            if (edge.get(x, y)) {
                edge_sum += e;
                ++out.edge_pixels;
            } else {
                inner.push_back(e);
            }
        }
    out.pixels = static_cast<long>(inner.size());
    if (!inner.empty()) {
        double sum = 0;
        for (double e : inner) sum += e;
        out.mean = sum / static_cast<double>(inner.size());
        const auto at95 = inner.begin() +
                          static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(inner.size() - 1));
        std::nth_element(inner.begin(), at95, inner.end());
        out.p95 = *at95;
    }
    if (out.edge_pixels > 0) out.edge_mean = edge_sum / static_cast<double>(out.edge_pixels);
    return out;
}

}  // namespace occlusion
