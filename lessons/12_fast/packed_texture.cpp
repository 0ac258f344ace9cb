#include "packed_texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace fast {

PackedTexture::PackedTexture(const textures::MipChain& chain, bool all_levels,
                             const textures::TexelEncoding* encoding)
    : decoded(encoding != nullptr), levels(all_levels ? chain.levels() : 1) {
    if (levels > kMaxLevels) throw std::invalid_argument("a texture with more than 32 mip levels");
    std::size_t total = 0;
    for (int i = 0; i < levels; ++i)
        total += static_cast<std::size_t>(chain.level(i).width()) *
                 static_cast<std::size_t>(chain.level(i).height());
    // Offsets are gathered as 32-bit integers: the whole chain must fit them.
    if (total > static_cast<std::size_t>(INT32_MAX))
        throw std::invalid_argument("a texture too large for 32-bit texel offsets");
    texels.resize(total);
    std::size_t at = 0;
    for (int i = 0; i < kMaxLevels; ++i) {
        const int level = std::min(i, levels - 1);
        const rl::Image& image = chain.level(level);
        if (i < levels) {
            level_offset[i] = static_cast<std::int32_t>(at);
            const std::vector<rl::Rgba>& pixels = image.pixels();
            static_assert(sizeof(rl::Rgba) == sizeof(std::uint32_t));
            if (!encoding) {
                std::memcpy(static_cast<void*>(texels.data() + at), pixels.data(),
                            pixels.size() * sizeof(rl::Rgba));
            } else {
                blue_words.resize(total);
                const auto wide = [&](std::uint8_t byte) {
                    return static_cast<std::uint32_t>(
                        std::lround(encoding->value[byte] * 65535.0f));
                };
                for (std::size_t p = 0; p < pixels.size(); ++p) {
                    texels[at + p] = wide(pixels[p].r) | wide(pixels[p].g) << 16;
                    blue_words[at + p] = wide(pixels[p].b);
                }
            }
            at += pixels.size();
        } else {
            level_offset[i] = level_offset[levels - 1];
        }
        level_width[i] = image.width();
        level_height[i] = image.height();
    }
}

}  // namespace fast
