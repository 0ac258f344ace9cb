// The TGA (Truevision TARGA) codec: lesson 00's subject, written by hand.
// The format is explained in docs/00_framebuffer.md.
//
//   const rl::Image image = rl::read_tga("obj/crate_diffuse.tga");  // throws rl::TgaError
//   rl::write_tga("out.tga", image, {.format = rl::TgaPixelFormat::bgra32, .rle = false});
//   const std::vector<std::uint8_t> bytes = rl::encode_tga(image);  // RLE, 24-bit
//   const rl::TgaHeader header = rl::parse_tga_header(bytes, "out.tga");
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "rasterlab/file_io.hpp"
#include "rasterlab/image.hpp"

namespace rl {

// Raised for any file that is not a TGA this codec can read; the message names
// the file and what is wrong with it.
class TgaError : public FileError {
  public:
    using FileError::FileError;
};

// The image types this codec reads and writes (byte 2 of the header).
enum class TgaImageType : std::uint8_t {
    true_colour = 2,
    grey = 3,
    true_colour_rle = 10,
    grey_rle = 11,
};

enum class TgaPixelFormat { grey8, bgr24, bgra32 };

struct TgaWriteOptions {
    TgaPixelFormat format = TgaPixelFormat::bgr24;
    bool rle = true;
    bool top_row_first = false;  // the file's origin; the Image is bottom-first either way
};

// The 18-byte header, decoded and checked.
struct TgaHeader {
    std::uint8_t id_length = 0;
    std::uint8_t colour_map_type = 0;
    std::uint8_t image_type = 0;
    std::uint16_t colour_map_length = 0;
    std::uint8_t colour_map_entry_bits = 0;
    std::uint16_t width = 0;
    std::uint16_t height = 0;
    std::uint8_t bits_per_pixel = 0;
    std::uint8_t descriptor = 0;

    bool rle() const {
        return image_type == static_cast<std::uint8_t>(TgaImageType::true_colour_rle) ||
               image_type == static_cast<std::uint8_t>(TgaImageType::grey_rle);
    }
    bool top_row_first() const { return (descriptor & 0x20) != 0; }
    bool right_to_left() const { return (descriptor & 0x10) != 0; }
    int bytes_per_pixel() const { return bits_per_pixel / 8; }
};

inline constexpr std::size_t kTgaHeaderSize = 18;

// Decodes and validates the header; `name` is used in error messages.
TgaHeader parse_tga_header(std::span<const std::uint8_t> bytes, const std::string& name);

Image decode_tga(std::span<const std::uint8_t> bytes, const std::string& name);
std::vector<std::uint8_t> encode_tga(const Image& image, const TgaWriteOptions& options = {});

Image read_tga(const std::filesystem::path& path);
void write_tga(const std::filesystem::path& path, const Image& image,
               const TgaWriteOptions& options = {});

}  // namespace rl
