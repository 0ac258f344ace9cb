// Lesson 00: the framebuffer. Make an image, set its pixels, write it as TGA
// (raw and RLE), read both back, check them, and export a PNG.
// Read docs/00_framebuffer.md beside this file.
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "rasterlab/cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/tga.hpp"
#include "test_card.hpp"

namespace {

struct Options {
    rl::ImageOptions image{"00_framebuffer.tga", 256, 256};
    std::string png;
    bool raw = false;
    lesson00::Misreading misread = lesson00::Misreading::none;
};

bool is_png(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".png";
}

// Encodes `image` in one TGA variant, decodes the bytes again and checks that
// every pixel came back. Returns the encoded size.
std::size_t round_trip(const rl::Image& image, const rl::TgaWriteOptions& options,
                       const char* label) {
    const std::vector<std::uint8_t> bytes = rl::encode_tga(image, options);
    const rl::Image back = rl::decode_tga(bytes, label);
    if (back != image) throw std::runtime_error(std::string(label) + " round trip changed pixels");
    return bytes.size();
}

int run(const Options& options) {
    const auto& [output, width, height] = options.image;
    // Both outputs are checked before any work and written only when both are
    // ready: a bad --png path must not cost the TGA, nor replace it.
    rl::ImageOutputs outputs;
    outputs.check(output);
    if (!options.png.empty()) outputs.check(options.png);
    // [doc:lesson00-main]
    const rl::Image card = lesson00::make_test_card(width, height);
    // [/doc:lesson00-main]
    if (options.misread != lesson00::Misreading::none) {
        outputs.stage(output, lesson00::misread(card, options.misread));
        outputs.commit();
        std::printf("wrote %s: the test card as a decoder that gets the %s wrong shows it\n",
                    output.c_str(), lesson00::name(options.misread));
        return 0;
    }
    // [doc:lesson00-round-trip]

    rl::TgaWriteOptions raw;
    raw.rle = false;
    rl::TgaWriteOptions rle;  // the defaults: 24-bit, RLE, bottom row first
    const std::size_t raw_size = round_trip(card, raw, "raw TGA");
    const std::size_t rle_size = round_trip(card, rle, "RLE TGA");
    std::printf(
        "%dx%d test card: raw TGA %zu bytes, RLE TGA %zu bytes (%.1f%%); both read back "
        "identical\n",
        width, height, raw_size, rle_size,
        100.0 * static_cast<double>(rle_size) / static_cast<double>(raw_size));

    if (is_png(output))  // the extension decides the format, as in every lesson
        outputs.stage(output, card);
    else
        outputs.stage_bytes(output, rl::encode_tga(card, options.raw ? raw : rle));
    if (!options.png.empty()) outputs.stage(options.png, card);
    outputs.commit();
    const rl::Image from_disk = rl::load_image(output);  // and check what landed on disk
    if (from_disk != card) throw std::runtime_error(output + " does not read back identical");
    // [/doc:lesson00-round-trip]
    std::printf("wrote %s\n", output.c_str());
    if (!options.png.empty()) std::printf("wrote %s\n", options.png.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 00, the framebuffer: draws a test card pixel by pixel, writes it as TGA "
        "(raw and RLE), reads it back and checks it."};
    Options o;
    rl::add_image_options(app, o.image);
    app.add_option("--png", o.png, "Also export the image as PNG to this path");
    app.add_flag("--raw", o.raw,
                 "Write the TGA output uncompressed (type 2) instead of RLE (type 10)");
    rl::add_method_option(app, "--misread", o.misread, lesson00::kMisreadings,
                          "Instead, write the card as a decoder with this mistake would show it");
    return app.run(argc, argv, "00_framebuffer", [&] { return run(o); });
}
