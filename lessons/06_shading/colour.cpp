#include "colour.hpp"

#include <limits>

namespace shading {

namespace {

// The linear values at which the sRGB byte steps up: between byte k and k + 1
// lies the value whose encoding is (k + 0.5) / 255. (The 256th is infinite:
// no value steps past 255.)
std::array<float, 256> make_byte_steps() {
    std::array<float, 256> steps{};
    for (std::size_t k = 0; k < 255; ++k)
        steps[k] = static_cast<float>(srgb_to_linear((static_cast<double>(k) + 0.5) / 255.0));
    steps[255] = std::numeric_limits<float>::infinity();
    return steps;
}

// Where to start looking for a value's byte: for each of 4096 equal slices
// of [0, 1], the byte of the slice's lower end. No slice spans more than one
// step (the steepest part of the curve, near black, rises 0.8 of a byte per
// slice), so one or two comparisons finish the search.
std::array<std::uint8_t, 4097> make_first_bytes(const std::array<float, 256>& steps) {
    std::array<std::uint8_t, 4097> first{};
    std::size_t b = 0;
    for (std::size_t i = 0; i < first.size(); ++i) {
        const float v = static_cast<float>(i) / 4096.0f;
        while (v >= steps[b]) ++b;
        first[i] = static_cast<std::uint8_t>(b);
    }
    return first;
}

// The nearest sRGB byte of a linear value: the number of steps below it (the
// same byte as rounding linear_to_srgb(value) * 255, without a pow per
// channel and pixel).
std::uint8_t srgb_byte(float value) {
    const SrgbByteTables& tables = srgb_byte_tables();
    if (!(value > 0)) return 0;  // negative light, and NaN, write black
    if (value >= 1) return 255;
    std::size_t b = tables.first[static_cast<std::size_t>(value * 4096.0f)];
    while (value >= tables.steps[b]) ++b;
    return static_cast<std::uint8_t>(b);
}

textures::TexelEncoding make_srgb_texels() {
    textures::TexelEncoding encoding{};
    for (int i = 0; i < 256; ++i)
        encoding.value[static_cast<std::size_t>(i)] =
            static_cast<float>(srgb_to_linear(static_cast<double>(i) / 255.0));
    encoding.to_byte = srgb_byte;
    return encoding;
}

}  // namespace

const SrgbByteTables& srgb_byte_tables() {
    static const SrgbByteTables tables = [] {
        SrgbByteTables t;
        t.steps = make_byte_steps();
        t.first = make_first_bytes(t.steps);
        return t;
    }();
    return tables;
}

const textures::TexelEncoding& srgb_texels() {
    static const textures::TexelEncoding encoding = make_srgb_texels();
    return encoding;
}

rl::Rgba encode(rl::vec3 colour, Output output) {
    if (output == Output::srgb)
        return {srgb_byte(colour.x), srgb_byte(colour.y), srgb_byte(colour.z), 255};
    return textures::to_rgba({colour.x, colour.y, colour.z, 1.0f});
}

}  // namespace shading
