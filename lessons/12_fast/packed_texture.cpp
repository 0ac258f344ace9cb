#include "packed_texture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace fast {

PackedTexture::PackedTexture(const textures::MipChain& chain, bool all_levels,
                             const textures::TexelEncoding* encoding, bool one_word_)
    : decoded(encoding != nullptr),
      one_word(encoding != nullptr && one_word_),
      levels(all_levels ? chain.levels() : 1) {
    if (levels > kMaxLevels) throw std::invalid_argument("a texture with more than 32 mip levels");
    // Each row is stored with one texel more, a copy of its first: with the
    // wrap `repeat`, a bilinear lookup's two texels of a row are then always
    // side by side, and one 64-bit load fetches both.
    std::size_t total = 0;
    for (int i = 0; i < levels; ++i)
        total += static_cast<std::size_t>(chain.level(i).width() + 1) *
                 static_cast<std::size_t>(chain.level(i).height());
    // Offsets are gathered as 32-bit integers: the whole chain must fit them.
    if (total > static_cast<std::size_t>(INT32_MAX))
        throw std::invalid_argument("a texture too large for 32-bit texel offsets");
    texels.resize(total);
    if (decoded && !one_word) blue_words.resize(total);
    // What each byte packs to, worked out once for the 256 bytes rather than
    // three times at every texel (the rounding is a call into libm).
    std::array<std::uint32_t, 256> wide{}, root_11_bits{}, root_10_bits{};
    if (encoding)
        for (int byte = 0; byte < 256; ++byte) {
            const float value = encoding->value[byte];
            wide[byte] = static_cast<std::uint32_t>(std::lround(value * 65535.0f));
            // The square root spends the bits where the eye (and sRGB) tells
            // levels apart: near black, where a level is a small step of light.
            root_11_bits[byte] =
                static_cast<std::uint32_t>(std::lround(std::sqrt(value) * 2047.0f));
            root_10_bits[byte] =
                static_cast<std::uint32_t>(std::lround(std::sqrt(value) * 1023.0f));
        }
    std::size_t at = 0;
    for (int i = 0; i < kMaxLevels; ++i) {
        const int level = std::min(i, levels - 1);
        const rl::Image& image = chain.level(level);
        const int w = image.width(), h = image.height();
        if (i < levels) {
            level_offset[i] = static_cast<std::int32_t>(at);
            static_assert(sizeof(rl::Rgba) == sizeof(std::uint32_t));
            for (int y = 0; y < h; ++y)
                for (int x = 0; x <= w; ++x) {
                    const rl::Rgba texel = image.at(x == w ? 0 : x, y);
                    if (!encoding) {
                        std::memcpy(&texels[at], &texel, sizeof texel);
                    } else if (one_word) {
                        texels[at] = root_11_bits[texel.r] | root_11_bits[texel.g] << 11 |
                                     root_10_bits[texel.b] << 22;
                    } else {
                        texels[at] = wide[texel.r] | wide[texel.g] << 16;
                        blue_words[at] = wide[texel.b];
                    }
                    ++at;
                }
        } else {
            level_offset[i] = level_offset[levels - 1];
        }
        level_width[i] = w;
        level_height[i] = h;
        level_stride[i] = w + 1;
    }
}

bool PackedTexture::take_alpha_from(const textures::MipChain& other) {
    if (decoded || other.levels() < levels) return false;
    for (int i = 0; i < levels; ++i)
        if (other.level(i).width() != level_width[i] || other.level(i).height() != level_height[i])
            return false;
    for (int i = 0; i < levels; ++i) {
        const rl::Image& image = other.level(i);
        const int w = image.width(), h = image.height();
        std::size_t at = static_cast<std::size_t>(level_offset[i]);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x <= w; ++x, ++at)  // the row's extra texel too
                texels[at] = (texels[at] & 0x00ffffffu) |
                             static_cast<std::uint32_t>(image.at(x == w ? 0 : x, y).r) << 24;
    }
    alpha_holds_other = true;
    return true;
}

}  // namespace fast
