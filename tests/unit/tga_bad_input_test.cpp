// The bad-input corpus: every way a TGA file can lie, each refused with a
// message that names the file and the problem, without reading out of bounds
// (the sanitizer build checks the latter).
#include <gtest/gtest.h>

#include <filesystem>

#include "rasterlab/tga.hpp"
#include "temp_dir.hpp"

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes header(std::uint8_t type, std::uint16_t width, std::uint16_t height, std::uint8_t bpp,
             std::uint8_t descriptor = 0) {
    return {0,
            0,
            type,
            0,
            0,
            0,
            0,
            0,
            0,
            0,
            0,
            0,
            static_cast<std::uint8_t>(width & 0xff),
            static_cast<std::uint8_t>(width >> 8),
            static_cast<std::uint8_t>(height & 0xff),
            static_cast<std::uint8_t>(height >> 8),
            bpp,
            descriptor};
}

Bytes with(Bytes bytes, std::initializer_list<std::uint8_t> more) {
    bytes.insert(bytes.end(), more);
    return bytes;
}

struct BadFile {
    const char* name;
    Bytes bytes;
    const char* problem;  // must appear in the error message
};

std::vector<BadFile> corpus() {
    Bytes id_past_end = header(2, 1, 1, 24);
    id_past_end[0] = 200;
    Bytes bad_map_type = header(2, 1, 1, 24);
    bad_map_type[1] = 7;
    Bytes map_past_end = header(2, 1, 1, 24);
    map_past_end[1] = 1, map_past_end[5] = 0xff, map_past_end[6] = 0xff, map_past_end[7] = 32;
    return {
        {"empty", {}, "truncated header (0 of 18 bytes)"},
        {"short_header", Bytes(17, 0), "truncated header (17 of 18 bytes)"},
        {"colour_mapped", header(1, 4, 4, 8), "colour-mapped TGA (type 1)"},
        {"colour_mapped_rle", header(9, 4, 4, 8), "colour-mapped TGA (type 9)"},
        {"no_image", header(0, 4, 4, 24), "type 0 holds no image data"},
        {"unknown_type", header(7, 4, 4, 24), "unknown TGA image type 7"},
        {"true_colour_8bit", header(2, 4, 4, 8), "8 bits per pixel does not fit a true-colour"},
        {"true_colour_16bit", header(10, 4, 4, 16), "16 bits per pixel does not fit"},
        {"grey_24bit", header(3, 4, 4, 24), "24 bits per pixel does not fit a greyscale"},
        {"zero_width", header(2, 0, 4, 24), "zero image size 0x4"},
        {"zero_height", header(11, 4, 0, 8), "zero image size 4x0"},
        {"absurd_size", header(2, 65535, 65535, 24), "exceeds the limit"},
        {"bad_colour_map_type", bad_map_type, "invalid colour map type 7"},
        {"id_past_end", id_past_end, "truncated image ID field"},
        {"colour_map_past_end", map_past_end, "truncated colour map"},
        {"raw_truncated", with(header(2, 2, 2, 24), {1, 2, 3, 4, 5, 6}), "truncated pixel data"},
        {"rle_no_packets", header(10, 2, 2, 24), "truncated pixel data"},
        {"rle_packet_missing", with(header(10, 200, 1, 24), {0xff, 1, 2, 3, 0x00, 1, 2, 3}),
         "truncated RLE packet header"},
        {"rle_run_truncated", with(header(10, 2, 2, 32), {0x81, 1, 2, 3, 4, 0x81, 1, 2}),
         "truncated RLE run"},
        // The header alone claims 16384 x 16384: refused from the length the
        // header implies, before the gigabyte of pixels is allocated.
        {"huge_header_only", header(2, 16384, 16384, 32), "needs at least 1073741824 bytes"},
        {"huge_rle_header_only", header(10, 16384, 16384, 32), "needs at least 10485760 bytes"},
        {"rle_raw_truncated", with(header(11, 2, 2, 8), {0x03, 1, 2}), "truncated RLE raw packet"},
        {"rle_run_overrun", with(header(11, 2, 2, 8), {0x84, 9}), "overruns the image"},
        {"rle_raw_overrun", with(header(11, 2, 2, 8), {0x7f, 1, 2, 3, 4}), "overruns the image"},
        {"rle_late_overrun", with(header(11, 2, 2, 8), {0x82, 9, 0x81, 9}), "overruns the image"},
    };
}

void PrintTo(const BadFile& bad, std::ostream* out) {
    *out << bad.name;
}

class TgaBadInput : public testing::TestWithParam<BadFile> {};

TEST_P(TgaBadInput, IsRefusedFromMemoryWithItsProblemNamed) {
    const BadFile& bad = GetParam();
    try {
        rl::decode_tga(bad.bytes, bad.name);
        FAIL() << "decoded a broken file";
    } catch (const rl::TgaError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(std::string(bad.name) + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(bad.problem), std::string::npos) << message;
    }
}

TEST_P(TgaBadInput, IsRefusedFromDiskWithThePathNamed) {
    const BadFile& bad = GetParam();
    rl_test::TempDir dir;
    const std::filesystem::path path = dir.path() / (std::string(bad.name) + ".tga");
    rl_test::write_bytes(path, bad.bytes);
    try {
        rl::read_tga(path);
        FAIL() << "read a broken file";
    } catch (const rl::TgaError& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Corpus, TgaBadInput, testing::ValuesIn(corpus()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(TgaFiles, MissingFileAndDirectoryAreNamed) {
    rl_test::TempDir dir;
    EXPECT_THROW(rl::read_tga(dir.path() / "absent.tga"), rl::FileError);
    EXPECT_THROW(rl::read_tga(dir.path()), rl::FileError);
}

TEST(TgaFiles, UnwritablePathLeavesNothingBehind) {
    rl_test::TempDir dir;
    const rl::Image image(4, 4);
    EXPECT_THROW(rl::write_tga(dir.path() / "no_such_dir" / "x.tga", image), rl::FileError);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(TgaFiles, FailedWriteKeepsTheOldFile) {
    rl_test::TempDir dir;
    const std::filesystem::path path = dir.path() / "keep.tga";
    const rl::Image original(3, 3, rl::Rgba{1, 2, 3, 255});
    rl::write_tga(path, original);
    // An image TGA cannot store (wider than 65535) is refused before any
    // byte is written; the old file must survive intact.
    const rl::Image huge(70000, 1);
    EXPECT_THROW(rl::write_tga(path, huge), std::invalid_argument);
    EXPECT_EQ(rl::read_tga(path), original);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                            std::filesystem::directory_iterator()),
              1);
}

}  // namespace
