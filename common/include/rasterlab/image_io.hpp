// Reading and writing images by file extension: .tga through our own codec,
// JPEG through libjpeg-turbo, PNG and BMP through stb_image, PNG out through
// stb_image_write; and float images (Radiance .hdr) through both.
//
//   const rl::Image diffuse = rl::load_image("obj/crate_diffuse.tga");  // .tga .png .jpg .bmp
//   rl::check_image_output("out.png");  // before rendering: a bad path costs nothing
//   rl::save_image("out.png", image);  // .tga or .png, by the extension
//   const rl::HdrImage sky = rl::load_hdr_image("sky.hdr");  // linear float RGB
#pragma once

#include <climits>
#include <filesystem>
#include <string>

#include "rasterlab/image.hpp"
#include "rasterlab/tga.hpp"
#include "rasterlab/vec.hpp"

namespace rl {

// Reads .tga with read_tga(), and PNG, JPEG or BMP by their signatures.
// Throws FileError (TgaError for TGA files) naming the file and the problem.
Image load_image(const std::filesystem::path& path);

// A float image: linear RGB values of any size (light, not bytes), alpha 1.
using HdrImage = Grid<vec4>;

// The largest image a caller takes from a file, and what to call that
// limit in a refusal ("lesson 09's cap on a lat-long map").
struct ImageCap {
    int width = INT_MAX;
    int height = INT_MAX;
    std::string name = "the cap";
};

// Reads a Radiance .hdr file (RGBE, flat or run-length encoded), by its
// signature. The header is read first: an image wider or taller than `cap`
// is refused before a texel is decoded (a few megabytes of run-length data
// can claim gigabytes of float texels). Throws FileError naming the file and
// the problem.
HdrImage load_hdr_image(const std::filesystem::path& path, const ImageCap& cap = {});

// The bytes of a Radiance .hdr file of the image (top row first in the
// file, as the format requires). Values below 0 or not finite are refused.
std::vector<std::uint8_t> encode_hdr(const std::filesystem::path& path, const HdrImage& image);

// Writes a PNG (top row first in the file, as PNG requires), atomically.
void write_png(const std::filesystem::path& path, const Image& image);

// Writes .tga (RLE, 24-bit unless `keep_alpha`) or .png, chosen by extension.
void save_image(const std::filesystem::path& path, const Image& image, bool keep_alpha = false);

// The bytes save_image() would write to `path`: TGA or PNG by its extension.
std::vector<std::uint8_t> encode_image(const std::filesystem::path& path, const Image& image,
                                       bool keep_alpha = false);

// Throws FileError unless `path` ends in .tga or .png and check_output()
// accepts it. Programs call it for every output before they start work, so
// that a bad path costs nothing and replaces nothing.
void check_image_output(const std::filesystem::path& path);

// Several images written all or nothing (see OutputFiles):
//   rl::ImageOutputs out; out.check(a); out.check(b);   // before rendering
//   out.stage(a, image_a); out.stage(b, image_b); out.commit();
class ImageOutputs {
  public:
    void check(const std::filesystem::path& path) {
        check_image_output(path);
        files_.check(path);  // and not the same file as another output
    }
    // An output of another kind (staged with stage_bytes): only the file
    // rules, whatever its extension.
    void check_file(const std::filesystem::path& path) { files_.check(path); }
    void stage(const std::filesystem::path& path, const Image& image, bool keep_alpha = false) {
        files_.stage(path, encode_image(path, image, keep_alpha));
    }
    void stage_bytes(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
        files_.stage(path, bytes);
    }
    void commit() { files_.commit(); }

  private:
    OutputFiles files_;
};

}  // namespace rl
