#include "texture_maps.hpp"

#include <stb_perlin.h>

#include <algorithm>
#include <cmath>

#include "rasterlab/image_io.hpp"

namespace assets {

double fbm(dvec3 p, int octaves) {
    return stb_perlin_fbm_noise3(static_cast<float>(p.x), static_cast<float>(p.y),
                                 static_cast<float>(p.z), 2.0f, 0.5f, octaves);
}

double tileable_fbm(double u, double v, int cells, int octaves, int seed) {
    double sum = 0, amplitude = 1;
    for (int o = 0; o < octaves && cells <= 256; ++o, cells *= 2, amplitude *= 0.5)
        sum += amplitude * stb_perlin_noise3_seed(static_cast<float>(u * cells),
                                                  static_cast<float>(v * cells), 0.5f, cells, cells,
                                                  0, seed);
    return sum;
}

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

dvec3 mix(dvec3 a, dvec3 b, double t) {
    return a * (1 - t) + b * t;
}

rl::Rgba to_rgba(dvec3 c) {
    auto byte = [](double x) {
        return static_cast<std::uint8_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255));
    };
    return {byte(c.x), byte(c.y), byte(c.z), 255};
}

rl::Rgba encode_normal(dvec3 n) {
    return to_rgba((rl::normalize(n) + dvec3{1, 1, 1}) * 0.5);
}

rl::Image tangent_normal_map(const HeightField& height, double strength, bool seamless) {
    const int w = height.width(), h = height.height();
    auto at = [&](int x, int y) {
        if (seamless) {
            x = (x % w + w) % w;
            y = (y % h + h) % h;
        } else {
            x = std::clamp(x, 0, w - 1);
            y = std::clamp(y, 0, h - 1);
        }
        return height.get(x, y);
    };
    rl::Image map(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = (at(x + 1, y) - at(x - 1, y)) * 0.5;  // central differences
            const double dy = (at(x, y + 1) - at(x, y - 1)) * 0.5;
            map.set(x, y, encode_normal({-strength * dx, -strength * dy, 1.0}));
        }
    return map;
}

rl::Image grey_image(const HeightField& height, double low, double high) {
    rl::Image image(height.width(), height.height());
    for (int y = 0; y < height.height(); ++y)
        for (int x = 0; x < height.width(); ++x) {
            const double t = (height.get(x, y) - low) / (high - low);
            image.set(x, y, to_rgba({t, t, t}));
        }
    return image;
}

void write_texture(const std::filesystem::path& dir, const std::string& model,
                   const std::string& suffix, const std::string& extension,
                   const rl::Image& image) {
    rl::save_image(dir / (model + "_" + suffix + extension), image);
}

}  // namespace assets
