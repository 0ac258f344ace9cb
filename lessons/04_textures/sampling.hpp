// Texture sampling: wrap modes, filters and mipmaps. Texture coordinates are
// as in OBJ files: (0, 0) is the bottom-left corner of the image, (1, 1) the
// top-right; texel (i, j) covers [i, i+1) x [j, j+1) in texel units and has
// its centre at (i + 0.5, j + 0.5), like a pixel. Derivations:
// docs/04_textures.md.
//
//   const textures::MipChain chain(image);
//   const rl::vec4 c = textures::sample(chain, uv, {du_dx, du_dy}, {textures::Filter::trilinear});
#pragma once

#include "rasterlab/named_enum.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "rasterlab/image.hpp"
#include "rasterlab/vec.hpp"

namespace textures {

enum class Filter { nearest, bilinear, trilinear };
inline constexpr std::array<rl::Named<Filter>, 3> kFilterNames = {
    {{Filter::nearest, "nearest"},
     {Filter::bilinear, "bilinear"},
     {Filter::trilinear, "trilinear"}}};
inline constexpr std::array<Filter, 3> kFilters = rl::values_of(kFilterNames);
inline const char* name(Filter value) {
    return rl::name_in(kFilterNames, value);
}

enum class Wrap { repeat, mirror, clamp, border };
inline constexpr std::array<rl::Named<Wrap>, 4> kWrapNames = {{{Wrap::repeat, "repeat"},
                                                               {Wrap::mirror, "mirror"},
                                                               {Wrap::clamp, "clamp"},
                                                               {Wrap::border, "border"}}};
inline constexpr std::array<Wrap, 4> kWraps = rl::values_of(kWrapNames);
inline const char* name(Wrap value) {
    return rl::name_in(kWrapNames, value);
}

// A texture and its mipmap chain: level 0 is the image; each next level
// halves the size (rounding down, never below 1) and is the exact area
// average of the level before, so odd sizes lose nothing.
// How texel bytes stand for values: filtering and mipmapping average values,
// not bytes. Lesson 04 takes bytes as they are (value = byte / 255); lesson
// 06 passes sRGB's transfer function, so that colour textures are decoded to
// linear light before any averaging, as GPUs do for sRGB textures.
struct TexelEncoding {
    std::array<float, 256> value;          // byte -> value in [0, 1]
    std::uint8_t (*to_byte)(float value);  // value in [0, 1] -> nearest byte
};

class MipChain {
  public:
    // Each level averages the one before in the values of `encoding`
    // (nullptr: the bytes themselves). The smaller levels are built the
    // first time anything asks for them (once, safely from several threads),
    // so a texture only ever sampled by `nearest` or `bilinear` costs no
    // averaging; copies share them. (The image is taken by value: a caller
    // done with its image moves it in rather than holding two copies.)
    explicit MipChain(rl::Image image, const TexelEncoding* encoding = nullptr);
    int levels() const { return 1 + static_cast<int>(smaller().size()); }
    const rl::Image& level(int i) const {
        return i == 0 ? *base_ : smaller()[static_cast<std::size_t>(i - 1)];
    }

  private:
    struct Smaller {
        std::once_flag built;
        std::vector<rl::Image> levels;
    };
    const std::vector<rl::Image>& smaller() const;
    std::shared_ptr<const rl::Image> base_;
    const TexelEncoding* encoding_;
    std::shared_ptr<Smaller> smaller_;
};

// One level down: each output texel averages the input texels under it,
// weighted by how much of each it covers.
rl::Image downsample(const rl::Image& image, const TexelEncoding* encoding = nullptr);

struct SamplerState {
    Filter filter = Filter::bilinear;
    Wrap wrap = Wrap::repeat;
    rl::vec4 border{0, 0, 0, 1};
    const TexelEncoding* encoding = nullptr;  // colour texels through it (alpha never)
};

// How the texture coordinates change from one pixel to the next, in UV units:
// d(u, v)/dx and d(u, v)/dy. They choose the mip level.
struct UvDerivatives {
    rl::vec2 dx{}, dy{};
};

// The mip level for a footprint: log2 of the longer side of the pixel's
// image in texels of level 0 (0 or less: magnification).
float level_of_detail(const UvDerivatives& d, int width, int height);

// An integer texel coordinate wrapped into [0, size) (or -1 for `border`
// outside). Exposed for the tests.
int wrap_texel(int i, int size, Wrap wrap);

// The filtered colour at uv (components 0..1). NaN or infinite coordinates
// give the border colour: a defined result, never a crash.
rl::vec4 sample(const MipChain& texture, rl::vec2 uv, const UvDerivatives& derivatives,
                const SamplerState& state);

// Sampling one level: nearest or bilinear.
rl::vec4 sample_level(const rl::Image& level, rl::vec2 uv, bool bilinear,
                      const SamplerState& state);

rl::vec4 to_vec4(rl::Rgba c);
rl::Rgba to_rgba(rl::vec4 c);

}  // namespace textures
