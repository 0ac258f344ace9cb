#include "sky_truth.hpp"

#include <algorithm>
#include <cstdlib>

namespace environment {

rl::Grid<rl::vec3> sky_truth(const std::function<rl::dvec3(rl::dvec3)>& radiance,
                             const pipeline::Camera& camera, int width, int height, int samples) {
    rl::Grid<rl::vec3> out(width, height);
    const PixelRays rays(camera, width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            rl::dvec3 sum{0, 0, 0};
            for (int b = 0; b < samples; ++b)
                for (int a = 0; a < samples; ++a) {
                    const rl::vec3 ray =
                        rays.ray(x + (a + 0.5f) / samples, y + (b + 0.5f) / samples);
                    sum += radiance(rl::cast<double>(ray));
                }
            out.set(x, y, rl::cast<float>(sum / static_cast<double>(samples * samples)));
        }
    return out;
}

SkyError sky_error(const rl::Image& truth, const rl::Image& picture) {
    SkyError e;
    std::vector<int> worst;
    worst.reserve(static_cast<std::size_t>(truth.width()) * truth.height());
    double sum = 0;
    long over = 0;
    for (int y = 0; y < truth.height(); ++y)
        for (int x = 0; x < truth.width(); ++x) {
            const rl::Rgba a = truth.get(x, y), b = picture.get(x, y);
            const int d[3] = {std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)};
            sum += d[0] + d[1] + d[2];
            const int most = std::max({d[0], d[1], d[2]});
            worst.push_back(most);
            over += most > 2;
        }
    if (worst.empty()) return e;
    e.mean_levels = sum / (3.0 * static_cast<double>(worst.size()));
    const std::size_t k = (worst.size() * 99) / 100;
    std::nth_element(worst.begin(), worst.begin() + static_cast<long>(k), worst.end());
    e.p99_levels = worst[k];
    e.percent_over_2 = 100.0 * static_cast<double>(over) / static_cast<double>(worst.size());
    return e;
}

}  // namespace environment
