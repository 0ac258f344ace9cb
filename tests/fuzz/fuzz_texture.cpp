// libFuzzer target: loading a texture file as the lessons do, by extension:
// .tga through our codec, JPEG through libjpeg-turbo, PNG/BMP through
// stb_image, and float images (Radiance .hdr) through our header parser and
// stb_image. The first input byte picks the extension (0xf0 and up: .hdr;
// 0xf8 and up: .hdr under a cap of 64 x 64, as lesson 09 caps its maps); the
// rest is the file. It is refused with a FileError or loaded into a non-empty
// image (within the cap, when there is one).
// Run: build-fuzz/tests/fuzz/fuzz_texture tests/fuzz/corpus/texture
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "rasterlab/image_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static const char* const extensions[] = {".tga", ".png", ".jpg", ".bmp"};
    static const std::filesystem::path folder = [] {
        auto dir = std::filesystem::temp_directory_path() /
                   ("rasterlab-fuzz-texture-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        return dir;
    }();
    const bool hdr = data[0] >= 0xf0;
    const std::filesystem::path path =
        folder / (std::string("texture") + (hdr ? ".hdr" : extensions[data[0] % 4]));
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    }
    try {
        if (hdr) {
            const rl::ImageCap cap{64, 64, "the fuzz cap"};
            const bool capped = data[0] >= 0xf8;
            const rl::HdrImage image =
                capped ? rl::load_hdr_image(path, cap) : rl::load_hdr_image(path);
            if (image.width() <= 0 || image.height() <= 0) std::abort();
            if (capped && (image.width() > cap.width || image.height() > cap.height)) std::abort();
        } else {
            const rl::Image image = rl::load_image(path);
            if (image.width() <= 0 || image.height() <= 0) std::abort();
        }
    } catch (const rl::FileError&) {
    }
    std::filesystem::remove(path);
    return 0;
}
