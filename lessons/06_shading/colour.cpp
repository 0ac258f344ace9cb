#include "colour.hpp"

namespace shading {

namespace {

std::uint8_t srgb_byte(float value) {
    if (!(value > 0)) return 0;  // negative light, and NaN, write black
    return static_cast<std::uint8_t>(std::lround(linear_to_srgb(value) * 255.0f));
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
