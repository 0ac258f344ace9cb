// Reading and writing images by file extension: .tga through our own codec,
// PNG/JPG/BMP through stb_image, PNG out through stb_image_write.
#pragma once

#include <filesystem>

#include "rasterlab/image.hpp"
#include "rasterlab/tga.hpp"

namespace rl {

// Reads .tga with read_tga() and anything else stb_image understands.
// Throws FileError (TgaError for TGA files) naming the file and the problem.
Image load_image(const std::filesystem::path& path);

// Writes a PNG (top row first in the file, as PNG requires), atomically.
void write_png(const std::filesystem::path& path, const Image& image);

// Writes .tga (RLE, 24-bit unless `keep_alpha`) or .png, chosen by extension.
void save_image(const std::filesystem::path& path, const Image& image, bool keep_alpha = false);

}  // namespace rl
