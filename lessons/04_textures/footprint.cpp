#include "footprint.hpp"

#include <cmath>
#include <numbers>

namespace textures {

AffineScene magnification_scene(const rl::Image& texture, int size) {
    const double angle = 20.0 * std::numbers::pi / 180.0, texels_per_pixel = 1.0 / 8.0;
    const double u = texels_per_pixel / texture.width(), v = texels_per_pixel / texture.height();
    return {{0.1f, 0.05f},
            {static_cast<float>(u * std::cos(angle)), static_cast<float>(v * std::sin(angle))},
            {static_cast<float>(-u * std::sin(angle)), static_cast<float>(v * std::cos(angle))},
            size};
}

AffineScene minification_scene(const rl::Image& texture, int size) {
    const double u = 24.0 / texture.width(),
                 v = 24.0 / texture.height();  // 24 texels per pixel ...
    return {
        {0.3f, 0.7f},
        {static_cast<float>(u), static_cast<float>(0.25 * v)},
        {static_cast<float>(0.6 * u), static_cast<float>(1.3 * v)},  // ... sheared and stretched
        size};
}

// [doc:footprint-average]
rl::Image footprint_average(const rl::Image& texture, const AffineScene& scene, int n) {
    rl::Image out(scene.size, scene.size);
    const int w = texture.width(), h = texture.height();
    for (int y = 0; y < scene.size; ++y)
        for (int x = 0; x < scene.size; ++x) {
            double sum[3] = {0, 0, 0};
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const double px = x + (i + 0.5) / n, py = y + (j + 0.5) / n;
                    const double u = scene.origin.x + px * scene.du.x + py * scene.dv.x;
                    const double v = scene.origin.y + px * scene.du.y + py * scene.dv.y;
                    const int tx = static_cast<int>(std::floor((u - std::floor(u)) * w)) % w;
                    const int ty = static_cast<int>(std::floor((v - std::floor(v)) * h)) % h;
                    const rl::Rgba c = texture.get(tx, ty);
                    sum[0] += c.r, sum[1] += c.g, sum[2] += c.b;
                }
            const double count = double(n) * n;
            auto byte = [&](double s) { return static_cast<std::uint8_t>(std::lround(s / count)); };
            out.set(x, y, {byte(sum[0]), byte(sum[1]), byte(sum[2]), 255});
        }
    return out;
}
// [/doc:footprint-average]

rl::Image render_scene(const MipChain& texture, const AffineScene& scene,
                       const SamplerState& state) {
    rl::Image out(scene.size, scene.size);
    const UvDerivatives d = scene.derivatives();
    for (int y = 0; y < scene.size; ++y)
        for (int x = 0; x < scene.size; ++x)
            out.set(x, y, to_rgba(sample(texture, scene.uv_at(x + 0.5, y + 0.5), d, state)));
    return out;
}

}  // namespace textures
