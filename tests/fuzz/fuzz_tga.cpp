// libFuzzer target: the TGA decoder. Any file is either refused with a
// TgaError or decoded into an image that survives an encode/decode round
// trip unchanged. Any other exception, a crash or a sanitizer report is a
// finding. Run: build-fuzz/tests/fuzz/fuzz_tga tests/fuzz/corpus/tga
#include <cstdint>
#include <cstdlib>

#include "rasterlab/tga.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rl::Image image(1, 1);
    try {
        image = rl::decode_tga({data, size}, "fuzz.tga");
    } catch (const rl::TgaError&) {
        return 0;  // refused with a message: the expected outcome for junk
    }
    rl::TgaWriteOptions options;
    options.format = rl::TgaPixelFormat::bgra32;
    if (rl::decode_tga(rl::encode_tga(image, options), "round trip") != image) std::abort();
    return 0;
}
