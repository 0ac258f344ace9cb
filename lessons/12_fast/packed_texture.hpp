// A texture's mip levels laid out for SIMD lookups: every level's texels in
// one array of 32-bit RGBA words (a lane gathers a texel with one load), and
// a small table of where each level starts and how big it is (a lane gathers
// its level's row length). The levels are lesson 04's own, so a lookup reads
// the very texels lesson 07 reads.
//
//   const fast::PackedTexture packed(chain);   // once, outside the frame loop
//   // texel (x, y) of level 2 (each row ends with a copy of its first texel: stride = width + 1)
//   packed.texels[packed.level_offset[2] + y * packed.level_stride[2] + x]
//   normals.take_alpha_from(specular_chain);  // the specular map rides in the alpha byte
#pragma once

#include <cstdint>
#include <vector>

#include "04_textures/sampling.hpp"

namespace fast {

struct PackedTexture {
    static constexpr int kMaxLevels = 32;  // a 2^31-texel side has 32 levels
    // Every level, or level 0 alone (for the filters that read no other).
    // With an encoding (sRGB colour textures), the texels are stored decoded
    // instead, so that a lookup needs no table: each channel's value in 16
    // bits, red and green in one word and blue in another (within 1/131070
    // of the encoding's values); or, with one_word, the square root of each
    // value in 11, 11 and 10 bits of one word, so that a lookup gathers half
    // the words and squares what it reads (within 0.16 of an output level:
    // docs/12_fast.md, "The albedo in one word").
    explicit PackedTexture(const textures::MipChain& chain, bool all_levels = true,
                           const textures::TexelEncoding* encoding = nullptr,
                           bool one_word = false);
    std::vector<std::uint32_t> texels;  // level 0, then 1, ...; rows bottom first
    bool decoded = false;               // texels hold red | green << 16, blue_words blue
    bool one_word = false;  // decoded: texels hold sqrt'd red | green << 11 | blue << 22
    std::vector<std::uint32_t> blue_words;  // decoded in two words only; empty otherwise
    // Per level (padded to kMaxLevels with the last level, so that a gather
    // with a clamped index never reads past the table):
    std::int32_t level_offset[kMaxLevels], level_width[kMaxLevels], level_height[kMaxLevels],
        level_stride[kMaxLevels];
    int levels = 0;

    // Puts `other`'s red channel in this texture's alpha bytes, level by
    // level, so that one lookup of four channels reads both (the fourth is
    // the other map's, to the bit: the same texels, weights and level).
    // Only where the two chains have the same levels, sizes and filter use,
    // and this texture is not decoded; returns whether it did.
    bool take_alpha_from(const textures::MipChain& other);
    bool alpha_holds_other = false;
};

}  // namespace fast
