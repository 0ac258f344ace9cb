#include <gtest/gtest.h>

#include <algorithm>

#include "rasterlab/image.hpp"
#include "rasterlab/image_io.hpp"
#include "temp_dir.hpp"

namespace {

using rl::HdrImage;
using rl::Image;
using rl::Rgba;
using rl::vec4;

TEST(Image, StartsFilledAndIsBottomRowFirst) {
    Image image(3, 2, Rgba{1, 2, 3, 4});
    EXPECT_EQ(image.get(2, 1), (Rgba{1, 2, 3, 4}));
    image.set(0, 0, Rgba{9, 9, 9, 255});
    EXPECT_EQ(image.pixels()[0], (Rgba{9, 9, 9, 255}));  // (0, 0) is the first pixel in memory
    image.set(0, 1, Rgba{7, 7, 7, 255});
    EXPECT_EQ(image.pixels()[3], (Rgba{7, 7, 7, 255}));  // row 1 follows row 0
}

TEST(Image, FlipsAreTheirOwnInverse) {
    Image image(5, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            image.set(x, y, {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 0, 255});
    Image flipped = image;
    flipped.flip_vertically();
    EXPECT_EQ(flipped.get(1, 0), image.get(1, 2));
    flipped.flip_vertically();
    EXPECT_EQ(flipped, image);
    flipped.flip_horizontally();
    EXPECT_EQ(flipped.get(0, 1), image.get(4, 1));
}

TEST(Image, RefusesBadDimensions) {
    EXPECT_THROW(Image(0, 5), std::invalid_argument);
    EXPECT_THROW(Image(5, -1), std::invalid_argument);
    EXPECT_THROW(Image(1 << 15, 1 << 14), std::invalid_argument);  // 2^29 pixels
    EXPECT_NO_THROW(rl::FloatImage(1 << 14, 1));
}

#ifndef NDEBUG
TEST(Image, DebugBuildsCheckBounds) {
    Image image(2, 2);
    EXPECT_THROW(image.set(2, 0, Rgba{}), std::out_of_range);
    EXPECT_THROW((void)image.get(0, -1), std::out_of_range);
}
#endif

TEST(ImageIo, PngRoundTripKeepsOrientation) {
    rl_test::TempDir dir;
    Image image(4, 3, Rgba{0, 0, 0, 255});
    image.set(0, 0, Rgba{255, 0, 0, 255});  // bottom-left
    rl::write_png(dir.path() / "a.png", image);
    const Image back = rl::load_image(dir.path() / "a.png");
    EXPECT_EQ(back, image);
}

TEST(ImageIo, UnknownOrBrokenFilesAreNamed) {
    rl_test::TempDir dir;
    const auto junk = dir.path() / "junk.png";
    rl_test::write_text(junk, "not an image at all");
    try {
        rl::load_image(junk);
        FAIL();
    } catch (const rl::FileError& e) {
        EXPECT_NE(std::string(e.what()).find("junk.png"), std::string::npos) << e.what();
    }
    EXPECT_THROW(rl::save_image(dir.path() / "x.bmp", Image(1, 1)), rl::FileError);
}

// Headers claiming 16384 x 16384 on files of a few dozen bytes are refused
// before decoding, naming the missing data (issue 17: a 54-byte BMP became a
// black 2.39 GB texture in 5 s; a JPEG header took 397 MB before its refusal).
std::vector<std::uint8_t> bmp_header(std::uint32_t size) {
    std::vector<std::uint8_t> b(54, 0);
    const auto put = [&](std::size_t at, std::uint32_t v, int bytes) {
        for (int i = 0; i < bytes; ++i) b[at + static_cast<std::size_t>(i)] = (v >> (8 * i)) & 0xff;
    };
    b[0] = 'B', b[1] = 'M';
    put(2, 54, 4), put(10, 54, 4), put(14, 40, 4), put(18, size, 4), put(22, size, 4);
    put(26, 1, 2), put(28, 24, 2);  // 24 bits, no compression
    return b;
}
TEST(ImageIo, HeadersClaimingMoreThanTheFileHoldsAreRefusedBeforeDecoding) {
    rl_test::TempDir dir;
    // SOI, a frame header claiming 16384 x 16384 in three components, the
    // start of a scan (a JPEG's header ends there), and nothing more.
    const std::vector<std::uint8_t> jpeg = {
        0xff, 0xd8, 0xff, 0xc0, 0x00, 0x11, 0x08, 0x40, 0x00, 0x40, 0x00, 0x03, 0x01,
        0x22, 0x00, 0x02, 0x11, 0x01, 0x03, 0x11, 0x01, 0xff, 0xda, 0x00, 0x0c, 0x03,
        0x01, 0x00, 0x02, 0x11, 0x03, 0x11, 0x00, 0x3f, 0x00, 0xff, 0xd9};
    const std::vector<std::uint8_t> png = {
        0x89, 'P', 'N', 'G',  '\r', '\n', 0x1a, '\n', 0,   0,   0,   13, 'I', 'H', 'D',
        'R',  0,   0,   0x40, 0,    0,    0,    0x40, 0,   8,   6,   0,  0,   0,   0,
        0,    0,   0,   0,    0,    0,    0,    'I',  'E', 'N', 'D', 0,  0,   0,   0};
    const std::pair<const char*, std::vector<std::uint8_t>> files[] = {
        {"huge.bmp", bmp_header(16384)}, {"huge.jpg", jpeg}, {"huge.png", png}};
    for (const auto& [name, bytes] : files) {
        rl_test::write_bytes(dir.path() / name, bytes);
        try {
            rl::load_image(dir.path() / name);
            ADD_FAILURE() << name << " was decoded";
        } catch (const rl::FileError& e) {
            EXPECT_NE(std::string(e.what()).find("truncated pixel data: a 16384x16384 image"),
                      std::string::npos)
                << e.what();
        }
    }
    std::vector<std::uint8_t> one_pixel = bmp_header(1);  // a whole 1x1 BMP still loads
    one_pixel.insert(one_pixel.end(), {0, 0, 255, 0});
    one_pixel[2] = 58;
    rl_test::write_bytes(dir.path() / "one.bmp", one_pixel);
    EXPECT_EQ(rl::load_image(dir.path() / "one.bmp").get(0, 0), (rl::Rgba{255, 0, 0, 255}));
}

// Radiance .hdr: values a byte cannot hold (the sun at 5000, a shadow at
// 0.002) come back within RGBE's precision (8 bits of mantissa shared by the
// three channels: 1/256 of the largest), bottom row first as every image.
TEST(ImageIo, HdrRoundTripKeepsValuesAndOrientation) {
    rl_test::TempDir dir;
    HdrImage image(9, 3, vec4{0.5f, 0.25f, 0.125f, 1});  // 9 wide: run-length encoded rows
    image.set(0, 0, vec4{5000, 2500, 1, 1});             // bottom-left
    image.set(8, 2, vec4{0.002f, 0.001f, 0.0005f, 1});   // top-right
    rl_test::write_bytes(dir.path() / "sky.hdr", rl::encode_hdr(dir.path() / "sky.hdr", image));
    const HdrImage back = rl::load_hdr_image(dir.path() / "sky.hdr");
    ASSERT_EQ(back.width(), 9);
    ASSERT_EQ(back.height(), 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 9; ++x) {
            const vec4 a = image.get(x, y), b = back.get(x, y);
            const float largest = std::max({a.x, a.y, a.z});
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[c], a[c], largest / 128) << x << "," << y;
            EXPECT_EQ(b.w, 1.0f);
        }
    EXPECT_THROW(rl::encode_hdr("neg.hdr", HdrImage(1, 1, vec4{-1, 0, 0, 1})), rl::FileError);
}

TEST(ImageIo, BrokenHdrFilesAreRefusedNamingTheCause) {
    rl_test::TempDir dir;
    const auto refusal = [&](const std::string& name, const std::string& text) {
        rl_test::write_text(dir.path() / name, text);
        try {
            rl::load_hdr_image(dir.path() / name);
        } catch (const rl::FileError& e) {
            return std::string(e.what());
        }
        return std::string("loaded");
    };
    EXPECT_NE(refusal("png.hdr", "\x89PNG").find("not a Radiance .hdr file"), std::string::npos);
    // A header claiming 16384 x 16384 and no pixels: refused before decoding.
    const std::string huge =
        refusal("huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16384 +X 16384\n");
    EXPECT_NE(huge.find("truncated pixel data"), std::string::npos) << huge;
    EXPECT_NE(huge.find("16384x16384"), std::string::npos) << huge;
    const std::string short_rows =
        refusal("short.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\nabcd");
    EXPECT_NE(short_rows.find("truncated pixel data"), std::string::npos) << short_rows;
    // A run of length 0, on which stb_image loops forever (found by fuzz_texture).
    const std::string zero_run =
        refusal("zero.hdr", std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n") +
                                std::string("\x02\x02\x00\x08\x00", 5));
    EXPECT_NE(zero_run.find("corrupt run-length data: a run of 0"), std::string::npos) << zero_run;
    // A run-length encoded file cut one byte short of its last row.
    HdrImage sky(16, 4, vec4{0.5f, 0.75f, 1.5f, 1});
    sky.set(3, 3, vec4{20, 1, 0, 1});
    std::vector<std::uint8_t> cut = rl::encode_hdr("cut.hdr", sky);
    rl_test::write_bytes(dir.path() / "whole.hdr", cut);
    EXPECT_EQ(rl::load_hdr_image(dir.path() / "whole.hdr").get(3, 3).x, 20.0f);
    cut.pop_back();
    rl_test::write_bytes(dir.path() / "cut.hdr", cut);
    EXPECT_THROW(rl::load_hdr_image(dir.path() / "cut.hdr"), rl::FileError);
}

// A resolution line's numbers past an int: stb_image's strtol cast to int
// read 4294967297 as 1, and the file loaded as 8x1 with no word.
TEST(ImageIo, AnHdrSizePastAnIntIsACorruptHeader) {
    rl_test::TempDir dir;
    const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";
    const std::string pixels(8 * 4 * 4, '\x10');  // flat texels enough for 8x4
    const auto refusal = [&](const std::string& name, const std::string& resolution) {
        rl_test::write_text(dir.path() / name, header + resolution + "\n" + pixels);
        try {
            const HdrImage image = rl::load_hdr_image(dir.path() / name);
            return "loaded " + std::to_string(image.width()) + "x" + std::to_string(image.height());
        } catch (const rl::FileError& e) {
            return std::string(e.what());
        }
    };
    EXPECT_EQ(refusal("fine.hdr", "-Y 4 +X 8"), "loaded 8x4");
    // What stb_image's strtol reads as well: blanks, a plus sign, a trailing blank.
    EXPECT_EQ(refusal("blanks.hdr", "-Y  +4 +X \t8 \r"), "loaded 8x4");
    for (const std::string line : {"-Y 4294967297 +X 8", "-Y 4294967300 +X 4294967304",
                                   "-Y 2147483648 +X 8", "-Y -4 +X 8", "-Y 4 +X 8x"}) {
        const std::string message = refusal("wrapped.hdr", line);
        EXPECT_NE(message.find("corrupt header: the resolution line"), std::string::npos)
            << line << ": " << message;
    }
}

// A cap is applied from the header, before a texel is decoded: a header
// alone claiming 16384x8192 names the cap, not the missing pixels.
TEST(ImageIo, AnHdrPastTheCallersCapIsRefusedBeforeDecoding) {
    rl_test::TempDir dir;
    const rl::ImageCap cap{4096, 2048, "the test's cap"};
    rl_test::write_text(dir.path() / "huge.hdr",
                        "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8192 +X 16384\n");
    try {
        rl::load_hdr_image(dir.path() / "huge.hdr", cap);
        ADD_FAILURE() << "a 16384x8192 header loaded under a 4096x2048 cap";
    } catch (const rl::FileError& e) {
        EXPECT_NE(std::string(e.what()).find("a 16384x8192 image, past the test's cap of "
                                             "4096x2048 texels"),
                  std::string::npos)
            << e.what();
    }
    // Whole, valid files: one texel past the cap either way is refused, the cap itself loads.
    const auto write = [&](const std::string& name, int width, int height) {
        const std::filesystem::path path = dir.path() / name;
        rl_test::write_bytes(path, rl::encode_hdr(path, HdrImage(width, height, vec4{1, 1, 1, 1})));
        return path;
    };
    EXPECT_THROW(rl::load_hdr_image(write("wide.hdr", 4097, 1), cap), rl::FileError);
    EXPECT_THROW(rl::load_hdr_image(write("tall.hdr", 1, 2049), cap), rl::FileError);
    EXPECT_EQ(rl::load_hdr_image(write("cap.hdr", 4096, 1), cap).width(), 4096);
    EXPECT_EQ(rl::load_hdr_image(write("wide.hdr", 4097, 1)).width(), 4097);  // no cap given
}

}  // namespace
