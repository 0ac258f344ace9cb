// Texture sampling: wrap modes, filters and mipmaps. Texture coordinates are
// as in OBJ files: (0, 0) is the bottom-left corner of the image, (1, 1) the
// top-right; texel (i, j) covers [i, i+1) x [j, j+1) in texel units and has
// its centre at (i + 0.5, j + 0.5), like a pixel. Derivations:
// docs/04_textures.md.
//
//   const textures::MipChain chain(image);
//   const rl::vec4 c = textures::sample(chain, uv, {du_dx, du_dy}, {textures::Filter::trilinear});
//   const textures::HdrMipChain sky(rl::load_hdr_image("sky.hdr"));   // float texels
//   const rl::vec4 radiance = textures::sample(sky, uv, {du_dx, du_dy}, {});
#pragma once

#include "rasterlab/named_enum.hpp"

#include <array>
#include <concepts>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "rasterlab/image.hpp"
#include "rasterlab/vec.hpp"

namespace textures {

enum class Filter { nearest, bilinear, trilinear };
RASTERLAB_NAMED_ENUM(Filter, kFilters, {Filter::nearest, "nearest"}, {Filter::bilinear, "bilinear"},
                     {Filter::trilinear, "trilinear"});

enum class Wrap { repeat, mirror, clamp, border };
RASTERLAB_NAMED_ENUM(Wrap, kWraps, {Wrap::repeat, "repeat"}, {Wrap::mirror, "mirror"},
                     {Wrap::clamp, "clamp"}, {Wrap::border, "border"});

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

// A texture's texels are 8-bit (rl::Rgba: colour maps, normal maps, their
// bytes standing for values through an encoding) or float (rl::vec4: linear
// high-dynamic-range values, such as the environment maps of lesson 09,
// which a byte cannot hold). Everything below works on either.
template <class T>
concept TexelType = std::same_as<T, rl::Rgba> || std::same_as<T, rl::vec4>;

template <TexelType Texel>
class BasicMipChain {
  public:
    using Level = rl::Grid<Texel>;
    // Each level averages the one before in the values of `encoding`
    // (nullptr: the bytes themselves; float texels have no encoding and
    // refuse one). The smaller levels are built the first time anything
    // asks for them (once, safely from several threads), so a texture only
    // ever sampled by `nearest` or `bilinear` costs no averaging; copies
    // share them. (The image is taken by value: a caller done with its image
    // moves it in rather than holding two copies.)
    explicit BasicMipChain(Level image, const TexelEncoding* encoding = nullptr);
    int levels() const { return 1 + static_cast<int>(smaller().size()); }
    const Level& level(int i) const {
        return i == 0 ? *base_ : smaller()[static_cast<std::size_t>(i - 1)];
    }

  private:
    struct Smaller {
        std::once_flag built;
        std::vector<Level> levels;
    };
    const std::vector<Level>& smaller() const;
    std::shared_ptr<const Level> base_;
    const TexelEncoding* encoding_;
    std::shared_ptr<Smaller> smaller_;
};

using MipChain = BasicMipChain<rl::Rgba>;     // 8-bit texels: lessons 04-08 and 12
using HdrMipChain = BasicMipChain<rl::vec4>;  // float texels, linear

// One level down: each output texel averages the input texels under it,
// weighted by how much of each it covers.
template <TexelType Texel>
rl::Grid<Texel> downsample(const rl::Grid<Texel>& image, const TexelEncoding* encoding = nullptr);

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

// The filtered value at uv (components 0..1 for 8-bit texels, any finite
// value for float ones). NaN or infinite coordinates give the border
// colour: a defined result, never a crash.
template <TexelType Texel>
rl::vec4 sample(const BasicMipChain<Texel>& texture, rl::vec2 uv, const UvDerivatives& derivatives,
                const SamplerState& state);

// Sampling one level: nearest or bilinear.
template <TexelType Texel>
rl::vec4 sample_level(const rl::Grid<Texel>& level, rl::vec2 uv, bool bilinear,
                      const SamplerState& state);

rl::vec4 to_vec4(rl::Rgba c);
rl::Rgba to_rgba(rl::vec4 c);

}  // namespace textures
