#include "tone_map.hpp"

#include <algorithm>
#include <cmath>

namespace environment {

// [doc:tone-map]
float tone_map(float light, const Exposure& exposure) {
    float c = light * std::exp2(exposure.stops);
    if (!(c > 0) || !std::isfinite(c)) return 0;
    if (exposure.store == FrameStore::bytes) c = std::round(std::min(c, 1.0f) * 255) / 255;
    switch (exposure.curve) {
        case ToneMap::clamp:
            return std::min(c, 1.0f);
        case ToneMap::reinhard:
            return c / (1 + c);
        case ToneMap::aces:
            return std::clamp(aces_curve(c), 0.0f, 1.0f);
    }
    return 0;
}

float aces_curve(float c) {
    return (c * (2.51f * c + 0.03f)) / (c * (2.43f * c + 0.59f) + 0.14f);
}
// [/doc:tone-map]

rl::vec3 tone_map(rl::vec3 light, const Exposure& exposure) {
    return {tone_map(light.x, exposure), tone_map(light.y, exposure), tone_map(light.z, exposure)};
}

rl::Image tone_mapped(const rl::Grid<rl::vec3>& light, const Exposure& exposure) {
    rl::Image out(light.width(), light.height());
    for (int y = 0; y < light.height(); ++y)
        for (int x = 0; x < light.width(); ++x)
            out.set(x, y,
                    shading::encode(tone_map(light.get(x, y), exposure), shading::Output::srgb));
    return out;
}

}  // namespace environment
