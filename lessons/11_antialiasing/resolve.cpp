#include "resolve.hpp"

#include <algorithm>
#include <cmath>

#include "06_shading/colour.hpp"

namespace antialiasing {

namespace {

// [doc:box]
// The mean of a pixel's own samples, summed in double (so that equal
// samples give back exactly their value).
rl::vec3 box_at(const rl::Grid<rl::vec3>& samples, int n, int x, int y) {
    double sum[3] = {0, 0, 0};
    for (int s = 0; s < n; ++s) {
        const rl::vec3 c = samples.get(x * n + s, y);
        sum[0] += c.x, sum[1] += c.y, sum[2] += c.z;
    }
    return {static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n),
            static_cast<float>(sum[2] / n)};
}
// [/doc:box]

// [doc:tent]
// The tent's weight of a sample at (dx, dy) pixels from a pixel's centre.
double tent(double dx, double dy) {
    return std::max(0.0, 1 - std::abs(dx)) * std::max(0.0, 1 - std::abs(dy));
}

rl::vec3 tent_at(const rl::Grid<rl::vec3>& samples, const std::vector<rl::vec2>& offsets, int x,
                 int y) {
    const int n = static_cast<int>(offsets.size());
    const int width = samples.width() / n;
    double sum[3] = {0, 0, 0}, weights = 0;
    for (int j = y - 1; j <= y + 1; ++j)
        for (int i = x - 1; i <= x + 1; ++i) {
            if (i < 0 || j < 0 || i >= width || j >= samples.height()) continue;
            for (int s = 0; s < n; ++s) {
                const rl::vec2 o = offsets[static_cast<std::size_t>(s)];
                const double w = tent(i - x + o.x, j - y + o.y);
                if (w == 0) continue;
                const rl::vec3 c = samples.get(i * n + s, j);
                sum[0] += w * c.x, sum[1] += w * c.y, sum[2] += w * c.z;
                weights += w;
            }
        }
    return {static_cast<float>(sum[0] / weights), static_cast<float>(sum[1] / weights),
            static_cast<float>(sum[2] / weights)};
}
// [/doc:tent]

}  // namespace

rl::Grid<rl::vec3> resolve(const rl::Grid<rl::vec3>& samples, const std::vector<rl::vec2>& offsets,
                           Resolve filter) {
    const int n = static_cast<int>(offsets.size());
    rl::Grid<rl::vec3> out(samples.width() / n, samples.height());
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x)
            out.at(x, y) =
                filter == Resolve::box ? box_at(samples, n, x, y) : tent_at(samples, offsets, x, y);
    return out;
}

rl::Image encoded(const rl::Grid<rl::vec3>& light) {
    rl::Image out(light.width(), light.height());
    for (int y = 0; y < light.height(); ++y)
        for (int x = 0; x < light.width(); ++x)
            out.set(x, y, shading::encode(light.get(x, y), shading::Output::srgb));
    return out;
}

}  // namespace antialiasing
