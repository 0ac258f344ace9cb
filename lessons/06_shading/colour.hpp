// Linear light and sRGB. Image bytes are sRGB-encoded: the byte 128 is not
// half of 255's light but about a fifth of it. Light adds and scales in
// linear units, so this lesson decodes textures to linear light, lights in
// linear light, and encodes the result to sRGB bytes; `naive` skips both
// conversions, as lessons 00-05 did. Derivation: docs/06_shading.md#linear-light.
//
//   const float light = shading::srgb_to_linear(128 / 255.0f);  // 0.216
//   const rl::Rgba out = shading::encode({0.5f, 0.5f, 0.5f}, shading::Output::srgb);  // 188
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "04_textures/sampling.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/named_enum.hpp"

namespace shading {

// The sRGB transfer functions (IEC 61966-2-1), for a value in [0, 1].
template <class T>
T srgb_to_linear(T c) {
    return c <= T(0.04045) ? c / T(12.92) : std::pow((c + T(0.055)) / T(1.055), T(2.4));
}

template <class T>
T linear_to_srgb(T c) {
    c = std::clamp(c, T(0), T(1));
    return c <= T(0.0031308) ? c * T(12.92) : T(1.055) * std::pow(c, T(1) / T(2.4)) - T(0.055);
}

// The tables that turn a linear value into its nearest sRGB byte without a
// pow: steps[k], the value where byte k + 1 begins (steps[255] infinite),
// and first[i], the byte at i / 4096, where the search up the steps starts
// (at most two steps away). Lesson 12's SIMD encoder gathers from them.
struct SrgbByteTables {
    std::array<float, 256> steps;
    std::array<std::uint8_t, 4097> first;
};
const SrgbByteTables& srgb_byte_tables();

// Texels as sRGB: each byte's linear value, and the nearest byte of a value.
const textures::TexelEncoding& srgb_texels();

// How the light computed for a pixel becomes bytes: encoded to sRGB (light
// was computed in linear units), or written as it is (naive: the light was
// computed on the bytes' own values).
enum class Output { srgb, naive };
RASTERLAB_NAMED_ENUM(Output, kOutputs, {Output::srgb, "srgb"}, {Output::naive, "naive"});

rl::Rgba encode(rl::vec3 colour, Output output);

}  // namespace shading
