#include "rasterlab/image_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace rl {
namespace {

void require_same_size(const Image& a, const Image& b) {
    if (a.width() != b.width() || a.height() != b.height())
        throw std::invalid_argument("images differ in size: " + std::to_string(a.width()) + "x" +
                                    std::to_string(a.height()) + " vs " +
                                    std::to_string(b.width()) + "x" + std::to_string(b.height()));
}

int largest_channel_difference(Rgba p, Rgba q) {
    return std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)});
}

}  // namespace

double psnr_from_rmse(double rmse) {
    if (rmse == 0) return std::numeric_limits<double>::infinity();
    return 20.0 * std::log10(255.0 / rmse);
}

ImageDiff compare_images(const Image& a, const Image& b, int threshold) {
    require_same_size(a, b);
    ImageDiff d;
    d.threshold = threshold;
    double sum_abs = 0, sum_sq = 0;
    std::size_t over = 0;
    const auto& pa = a.pixels();
    const auto& pb = b.pixels();
    for (std::size_t i = 0; i < pa.size(); ++i) {
        const int diffs[3] = {std::abs(pa[i].r - pb[i].r), std::abs(pa[i].g - pb[i].g),
                              std::abs(pa[i].b - pb[i].b)};
        for (int diff : diffs) {
            sum_abs += diff;
            sum_sq += static_cast<double>(diff) * diff;
        }
        const int largest = std::max({diffs[0], diffs[1], diffs[2]});
        d.max_abs = std::max(d.max_abs, largest);
        if (largest > threshold) ++over;
    }
    const double samples = 3.0 * static_cast<double>(pa.size());
    d.mean_abs = sum_abs / samples;
    d.rmse = std::sqrt(sum_sq / samples);
    d.psnr = psnr_from_rmse(d.rmse);
    d.share_over = static_cast<double>(over) / static_cast<double>(pa.size());
    return d;
}

Image difference_image(const Image& a, const Image& b, int threshold) {
    require_same_size(a, b);
    const int worst = std::max(1, compare_images(a, b).max_abs);
    Image out(a.width(), a.height());
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const int diff = largest_channel_difference(a.get(x, y), b.get(x, y));
            const auto level = static_cast<std::uint8_t>(diff * 255 / worst);
            out.set(x, y, diff > threshold ? Rgba{255, 0, 0, 255} : Rgba{level, level, level, 255});
        }
    return out;
}

Image difference_overlay(const Image& expected, const Image& actual, int threshold) {
    require_same_size(expected, actual);
    Image out(actual.width(), actual.height());
    for (int y = 0; y < actual.height(); ++y)
        for (int x = 0; x < actual.width(); ++x) {
            const Rgba a = actual.get(x, y);
            const bool wrong = largest_channel_difference(expected.get(x, y), a) > threshold;
            const auto dim = [](std::uint8_t c) { return static_cast<std::uint8_t>(c / 3); };
            out.set(x, y, wrong ? Rgba{255, 0, 255, 255} : Rgba{dim(a.r), dim(a.g), dim(a.b), 255});
        }
    return out;
}

}  // namespace rl
