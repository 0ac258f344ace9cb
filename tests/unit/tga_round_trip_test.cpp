// Every TGA variant we write must read back pixel for pixel, through our
// reader and through stb_image's independent one.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <memory>
#include <random>

#include "rasterlab/tga.hpp"

namespace {

using rl::Image;
using rl::Rgba;
using rl::TgaPixelFormat;
using rl::TgaWriteOptions;

// Random pixels with some repeats, so RLE writes both run and raw packets.
Image random_image(int width, int height, TgaPixelFormat format, unsigned seed) {
    std::mt19937 rng(seed);
    Image image(width, height);
    Rgba previous{};
    for (Rgba& p : image.pixels()) {
        if (rng() % 3 == 0) {
            p = previous;
            continue;
        }
        const auto byte = [&] { return static_cast<std::uint8_t>(rng() & 0xff); };
        p = {byte(), byte(), byte(), 255};
        if (format == TgaPixelFormat::grey8) p.g = p.b = p.r;
        if (format == TgaPixelFormat::bgra32) p.a = byte();
        previous = p;
    }
    return image;
}

struct Variant {
    TgaPixelFormat format;
    bool rle;
    bool top_row_first;
};

void PrintTo(const Variant& v, std::ostream* out) {
    *out << "format " << static_cast<int>(v.format) << (v.rle ? " rle" : " raw")
         << (v.top_row_first ? " top-first" : " bottom-first");
}

std::string variant_name(const testing::TestParamInfo<Variant>& info) {
    const char* format[] = {"grey8", "bgr24", "bgra32"};
    return std::string(format[static_cast<int>(info.param.format)]) +
           (info.param.rle ? "_rle" : "_raw") + (info.param.top_row_first ? "_top" : "_bottom");
}

class TgaRoundTrip : public testing::TestWithParam<Variant> {};

TEST_P(TgaRoundTrip, ReadsBackEveryPixel) {
    const Variant v = GetParam();
    const Image image = random_image(37, 23, v.format, 7);  // odd sizes on purpose
    const TgaWriteOptions options{v.format, v.rle, v.top_row_first};
    const std::vector<std::uint8_t> bytes = rl::encode_tga(image, options);

    const rl::TgaHeader h = rl::parse_tga_header(bytes, "memory");
    const bool grey = v.format == TgaPixelFormat::grey8;
    EXPECT_EQ(h.image_type, grey ? (v.rle ? 11 : 3) : (v.rle ? 10 : 2));
    EXPECT_EQ(h.top_row_first(), v.top_row_first);
    EXPECT_EQ(h.width, 37);
    EXPECT_EQ(h.height, 23);

    EXPECT_EQ(rl::decode_tga(bytes, "memory"), image);
}

TEST_P(TgaRoundTrip, AgreesWithStbImage) {
    const Variant v = GetParam();
    const Image image = random_image(19, 11, v.format, 11);
    const std::vector<std::uint8_t> bytes =
        rl::encode_tga(image, {v.format, v.rle, v.top_row_first});
    int w = 0, h = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 4),
        stbi_image_free);
    ASSERT_TRUE(data) << stbi_failure_reason();
    ASSERT_EQ(w, 19);
    ASSERT_EQ(h, 11);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const stbi_uc* p = data.get() + (static_cast<std::size_t>(h - 1 - y) * w + x) * 4;
            const Rgba expected = image.get(x, y);
            ASSERT_EQ((Rgba{p[0], p[1], p[2], p[3]}), expected) << "pixel " << x << "," << y;
        }
}

INSTANTIATE_TEST_SUITE_P(
    AllWrittenVariants, TgaRoundTrip,
    testing::Values(
        Variant{TgaPixelFormat::grey8, false, false}, Variant{TgaPixelFormat::grey8, false, true},
        Variant{TgaPixelFormat::grey8, true, false}, Variant{TgaPixelFormat::grey8, true, true},
        Variant{TgaPixelFormat::bgr24, false, false}, Variant{TgaPixelFormat::bgr24, false, true},
        Variant{TgaPixelFormat::bgr24, true, false}, Variant{TgaPixelFormat::bgr24, true, true},
        Variant{TgaPixelFormat::bgra32, false, false}, Variant{TgaPixelFormat::bgra32, false, true},
        Variant{TgaPixelFormat::bgra32, true, false}, Variant{TgaPixelFormat::bgra32, true, true}),
    variant_name);

// A hand-made 2x2 file: byte order, origin bits and right-to-left columns.
std::vector<std::uint8_t> tiny_header(std::uint8_t type, std::uint8_t bpp,
                                      std::uint8_t descriptor) {
    return {0, 0, type, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, bpp, descriptor};
}

TEST(TgaDecode, StoresBlueGreenRedAndHonoursBothOrigins) {
    // File order: first row A B, second row C D; each pixel B, G, R.
    const std::vector<std::uint8_t> pixels = {0,   0, 255, 0, 255, 0,   // A red, B green
                                              255, 0, 0,   9, 9,   9};  // C blue, D grey
    auto file = [&](std::uint8_t descriptor) {
        std::vector<std::uint8_t> bytes = tiny_header(2, 24, descriptor);
        bytes.insert(bytes.end(), pixels.begin(), pixels.end());
        return rl::decode_tga(bytes, "tiny");
    };
    const Rgba red{255, 0, 0, 255}, green{0, 255, 0, 255}, blue{0, 0, 255, 255}, grey{9, 9, 9, 255};

    const Image bottom_first = file(0x00);  // first row in the file is the bottom row
    EXPECT_EQ(bottom_first.get(0, 0), red);
    EXPECT_EQ(bottom_first.get(1, 0), green);
    EXPECT_EQ(bottom_first.get(0, 1), blue);

    const Image top_first = file(0x20);  // first row in the file is the top row
    EXPECT_EQ(top_first.get(0, 1), red);
    EXPECT_EQ(top_first.get(1, 1), green);
    EXPECT_EQ(top_first.get(1, 0), grey);

    const Image right_to_left = file(0x10);
    EXPECT_EQ(right_to_left.get(1, 0), red);
    EXPECT_EQ(right_to_left.get(0, 0), green);
}

TEST(TgaDecode, SkipsImageIdAndUnusedColourMap) {
    std::vector<std::uint8_t> bytes = tiny_header(3, 8, 0);
    bytes[0] = 3;                 // three bytes of image ID
    bytes[1] = 1;                 // a colour map is present...
    bytes[5] = 2, bytes[7] = 24;  // ...of two 24-bit entries
    bytes.insert(bytes.end(), {'a', 'b', 'c'});
    bytes.insert(bytes.end(), 6, 0x77);  // the colour map
    bytes.insert(bytes.end(), {10, 20, 30, 40});
    const Image image = rl::decode_tga(bytes, "with-id");
    EXPECT_EQ(image.get(0, 0), (Rgba{10, 10, 10, 255}));
    EXPECT_EQ(image.get(1, 1), (Rgba{40, 40, 40, 255}));
}

TEST(TgaDecode, AcceptsRlePacketsThatCrossRows) {
    // One run packet of 4 pixels covers both rows; the spec discourages it,
    // but real files do it, and it stays inside the image.
    std::vector<std::uint8_t> bytes = tiny_header(11, 8, 0);
    bytes.insert(bytes.end(), {0x83, 200});
    const Image image = rl::decode_tga(bytes, "crossing");
    for (const Rgba& p : image.pixels()) EXPECT_EQ(p, (Rgba{200, 200, 200, 255}));
}

TEST(TgaEncode, RlePacketsForAKnownRow) {
    // Row: X X X Y Z: a run of three, then a raw packet of two.
    Image image(5, 1);
    const Rgba x{1, 1, 1, 255}, y{2, 2, 2, 255}, z{3, 3, 3, 255};
    image.set(0, 0, x), image.set(1, 0, x), image.set(2, 0, x), image.set(3, 0, y),
        image.set(4, 0, z);
    const std::vector<std::uint8_t> bytes =
        rl::encode_tga(image, {TgaPixelFormat::grey8, true, false});
    const std::vector<std::uint8_t> body(bytes.begin() + rl::kTgaHeaderSize,
                                         bytes.begin() + rl::kTgaHeaderSize + 5);
    EXPECT_EQ(body, (std::vector<std::uint8_t>{0x82, 1, 0x01, 2, 3}));
}

TEST(TgaEncode, LongRunsSplitAt128Pixels) {
    Image image(300, 1, Rgba{5, 5, 5, 255});
    const std::vector<std::uint8_t> bytes =
        rl::encode_tga(image, {TgaPixelFormat::grey8, true, false});
    const std::vector<std::uint8_t> body(bytes.begin() + rl::kTgaHeaderSize,
                                         bytes.begin() + rl::kTgaHeaderSize + 6);
    // 128 + 128 + 44 pixels.
    EXPECT_EQ(body, (std::vector<std::uint8_t>{0xff, 5, 0xff, 5, 0x80 + 43, 5}));
    EXPECT_EQ(rl::decode_tga(bytes, "long"), image);
}

TEST(TgaEncode, RleIsSmallerOnFlatImagesAndNeverMuchLarger) {
    const Image flat(64, 64, Rgba{10, 20, 30, 255});
    const auto raw = rl::encode_tga(flat, {TgaPixelFormat::bgr24, false, false});
    const auto rle = rl::encode_tga(flat, {TgaPixelFormat::bgr24, true, false});
    EXPECT_LT(rle.size() * 20, raw.size());

    // Worst case for RLE (no two neighbours equal): one header byte per 128 pixels.
    Image noisy(256, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 256; ++x)
            noisy.set(x, y, {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 0, 255});
    const auto raw_noisy = rl::encode_tga(noisy, {TgaPixelFormat::bgr24, false, false});
    const auto rle_noisy = rl::encode_tga(noisy, {TgaPixelFormat::bgr24, true, false});
    EXPECT_EQ(rle_noisy.size(), raw_noisy.size() + 4 * 2);
}

// Packets never cross rows, so the overhead is per row: for 24- and 32-bit
// pixels at most floor(w / 128) + 1 bytes a row, whatever the pixels. A
// 1-pixel-wide image pays one byte per pixel, a third of a 24-bit pixel.
TEST(TgaEncode, RleOverheadIsBoundedPerRowAndLargestOnNarrowImages) {
    for (int width : {1, 2, 3, 127, 128, 129, 300}) {
        for (unsigned seed = 1; seed <= 20; ++seed) {
            for (TgaPixelFormat format : {TgaPixelFormat::bgr24, TgaPixelFormat::bgra32}) {
                const Image image = random_image(width, 9, format, seed);
                const auto raw = rl::encode_tga(image, {format, false, false});
                const auto rle = rl::encode_tga(image, {format, true, false});
                EXPECT_LE(rle.size(), raw.size() + 9u * static_cast<unsigned>(width / 128 + 1))
                    << width << " wide, seed " << seed;
            }
        }
    }
    Image column(1, 1000);  // no two neighbours in a row: there are none
    for (int y = 0; y < 1000; ++y)
        column.set(0, y, {static_cast<std::uint8_t>(y), static_cast<std::uint8_t>(y * 7), 1, 255});
    const auto raw = rl::encode_tga(column, {TgaPixelFormat::bgr24, false, false});
    const auto rle = rl::encode_tga(column, {TgaPixelFormat::bgr24, true, false});
    EXPECT_EQ(rle.size() - raw.size(), 1000u);  // 4 bytes a pixel instead of 3
}

// 8-bit grey is worse: a run of two costs as much as the two pixels raw, so
// the pattern A A B C C D ... pays a raw-packet header for every third pixel.
TEST(TgaEncode, GreyRleCanCostAThirdMore) {
    Image row(300, 1);
    for (int x = 0; x < 300; ++x) {
        const auto level = static_cast<std::uint8_t>(x % 3 == 2 ? 200 - x / 3 : x / 3);
        row.set(x, 0, {level, level, level, 255});
    }
    const auto raw = rl::encode_tga(row, {TgaPixelFormat::grey8, false, false});
    const auto rle = rl::encode_tga(row, {TgaPixelFormat::grey8, true, false});
    EXPECT_EQ(rle.size() - raw.size(), 100u);  // 4 bytes for every 3 pixels
}

}  // namespace
