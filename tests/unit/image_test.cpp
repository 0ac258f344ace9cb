#include <gtest/gtest.h>

#include "rasterlab/image.hpp"
#include "rasterlab/image_io.hpp"
#include "temp_dir.hpp"

namespace {

using rl::Image;
using rl::Rgba;

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

}  // namespace
