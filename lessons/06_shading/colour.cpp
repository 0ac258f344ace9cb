#include "colour.hpp"

namespace shading {

namespace {

// The linear values at which the sRGB byte steps up: between byte k and k + 1
// lies the value whose encoding is (k + 0.5) / 255.
std::array<float, 255> make_byte_steps() {
    std::array<float, 255> steps{};
    for (std::size_t k = 0; k < steps.size(); ++k)
        steps[k] = static_cast<float>(srgb_to_linear((static_cast<double>(k) + 0.5) / 255.0));
    return steps;
}

// Where to start looking for a value's byte: for each of 4096 equal slices
// of [0, 1], the byte of the slice's lower end. No slice spans more than one
// step (the steepest part of the curve, near black, rises 0.8 of a byte per
// slice), so one or two comparisons finish the search.
std::array<std::uint8_t, 4097> make_first_bytes(const std::array<float, 255>& steps) {
    std::array<std::uint8_t, 4097> first{};
    std::size_t b = 0;
    for (std::size_t i = 0; i < first.size(); ++i) {
        const float v = static_cast<float>(i) / 4096.0f;
        while (b < steps.size() && v >= steps[b]) ++b;
        first[i] = static_cast<std::uint8_t>(b);
    }
    return first;
}

// The nearest sRGB byte of a linear value: the number of steps below it (the
// same byte as rounding linear_to_srgb(value) * 255, without a pow per
// channel and pixel).
std::uint8_t srgb_byte(float value) {
    static const std::array<float, 255> steps = make_byte_steps();
    static const std::array<std::uint8_t, 4097> first = make_first_bytes(steps);
    if (!(value > 0)) return 0;  // negative light, and NaN, write black
    if (value >= 1) return 255;
    std::size_t b = first[static_cast<std::size_t>(value * 4096.0f)];
    while (b < steps.size() && value >= steps[b]) ++b;
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
