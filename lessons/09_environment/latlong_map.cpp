#include "latlong_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rasterlab/checkpoint.hpp"

namespace environment {

namespace {

constexpr double kPi = std::numbers::pi;

rl::vec3 rgb(rl::vec4 texel) {
    return {texel.x, texel.y, texel.z};
}

}  // namespace

rl::dvec2 latlong_point(rl::dvec3 d) {
    const double length = rl::length(d);
    if (!(length > 0) || !std::isfinite(length)) return {0.5, 0.5};
    d = d / length;
    const double longitude = std::atan2(d.x, -d.z);                 // -pi..pi, 0 along -z
    const double latitude = std::asin(std::clamp(d.y, -1.0, 1.0));  // -pi/2..pi/2
    return {0.5 + longitude / (2 * kPi), 0.5 + latitude / kPi};
}

rl::dvec3 latlong_direction(double u, double v) {
    const double longitude = (u - 0.5) * 2 * kPi, latitude = (v - 0.5) * kPi;
    return {std::cos(latitude) * std::sin(longitude), std::sin(latitude),
            -std::cos(latitude) * std::cos(longitude)};
}

LatLongMap::LatLongMap(rl::HdrImage image) : map_(std::move(image)) {
    if (width() < 1 || height() < 1) throw std::invalid_argument("an empty lat-long map");
}

rl::vec3 LatLongMap::bilinear(int level, double u, double v) const {
    const rl::HdrImage& image = map_.level(level);
    const int w = image.width(), h = image.height();
    const double x = u * w - 0.5, y = v * h - 0.5;
    const double fx = x - std::floor(x), fy = y - std::floor(y);
    const long i0 = static_cast<long>(std::floor(x)), j0 = static_cast<long>(std::floor(y));
    rl::dvec3 sum{0, 0, 0};
    for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di) {
            const int i = static_cast<int>(((i0 + di) % w + w) % w);              // around the seam
            const int j = static_cast<int>(std::clamp<long>(j0 + dj, 0, h - 1));  // not over a pole
            sum +=
                rl::cast<double>(rgb(image.get(i, j))) * ((di ? fx : 1 - fx) * (dj ? fy : 1 - fy));
        }
    return rl::cast<float>(sum);
}

rl::vec3 LatLongMap::sample(rl::vec3 direction, MapFilter filter, float level) const {
    const rl::dvec2 p = latlong_point(rl::cast<double>(direction));
    switch (filter) {
        case MapFilter::nearest: {
            const rl::HdrImage& image = map_.level(0);
            const int i =
                std::clamp(static_cast<int>(std::floor(p.x * image.width())), 0, image.width() - 1);
            const int j = std::clamp(static_cast<int>(std::floor(p.y * image.height())), 0,
                                     image.height() - 1);
            return rgb(image.get(i, j));
        }
        case MapFilter::bilinear:
        case MapFilter::seamless:
            return bilinear(0, p.x, p.y);
        case MapFilter::trilinear: {
            const float top = static_cast<float>(map_.levels() - 1);
            const float l = std::isfinite(level) ? std::clamp(level, 0.0f, top) : 0.0f;
            const int l0 = static_cast<int>(l);
            const float t = l - static_cast<float>(l0);
            const rl::vec3 a = bilinear(l0, p.x, p.y);
            if (t == 0) return a;
            return a * (1 - t) + bilinear(l0 + 1, p.x, p.y) * t;
        }
    }
    return {0, 0, 0};
}

LatLongMap latlong_map(const std::function<rl::dvec3(rl::dvec3)>& radiance, int height,
                       int samples) {
    if (height < 1 || height > 8192 || samples < 1 || samples > 64)
        throw std::invalid_argument("a lat-long map of " + std::to_string(height) +
                                    " rows (1 to 8192), " + std::to_string(samples) +
                                    " samples a side (1 to 64)");
    const int width = 2 * height;
    rl::HdrImage image(width, height);
    for (int j = 0; j < height; ++j) {
        rl::checkpoint();  // a host's Ctrl-C, between rows
        for (int i = 0; i < width; ++i) {
            rl::dvec3 sum{0, 0, 0};
            for (int b = 0; b < samples; ++b)
                for (int a = 0; a < samples; ++a)
                    sum += radiance(latlong_direction((i + (a + 0.5) / samples) / width,
                                                      (j + (b + 0.5) / samples) / height));
            const rl::vec3 mean = rl::cast<float>(sum / static_cast<double>(samples * samples));
            image.set(i, j, {mean.x, mean.y, mean.z, 1});
        }
    }
    return LatLongMap(std::move(image));
}

LatLongMap latlong_map(Analytic which, int height, int samples) {
    return latlong_map([which](rl::dvec3 d) { return radiance(which, d); }, height, samples);
}

}  // namespace environment
