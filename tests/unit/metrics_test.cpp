#include <gtest/gtest.h>

#include <cmath>

#include "rasterlab/image_metrics.hpp"
#include "rasterlab/results_table.hpp"
#include "temp_dir.hpp"

namespace {

using rl::Image;
using rl::Rgba;

TEST(ImageMetrics, IdenticalImagesHaveInfinitePsnr) {
    const Image a(4, 4, Rgba{10, 20, 30, 255});
    const rl::ImageDiff d = rl::compare_images(a, a);
    EXPECT_EQ(d.max_abs, 0);
    EXPECT_EQ(d.share_over, 0.0);
    EXPECT_TRUE(std::isinf(d.psnr));
}

TEST(ImageMetrics, KnownDifferences) {
    Image a(2, 2, Rgba{0, 0, 0, 255});
    Image b = a;
    b.set(1, 1, Rgba{30, 0, 0, 255});  // one channel of one pixel off by 30
    b.set(0, 1, Rgba{0, 0, 3, 0});     // small difference; alpha is ignored
    const rl::ImageDiff d = rl::compare_images(a, b, 5);
    EXPECT_EQ(d.max_abs, 30);
    EXPECT_DOUBLE_EQ(d.mean_abs, 33.0 / 12.0);
    EXPECT_DOUBLE_EQ(d.rmse, std::sqrt((900.0 + 9.0) / 12.0));
    EXPECT_DOUBLE_EQ(d.share_over, 0.25);  // only the pixel off by 30 exceeds 5
    EXPECT_NEAR(d.psnr, 20 * std::log10(255.0 / d.rmse), 1e-12);

    const Image diff = rl::difference_image(a, b, 5);
    EXPECT_EQ(diff.get(1, 1), (Rgba{255, 0, 0, 255}));
    EXPECT_EQ(diff.get(0, 1), (Rgba{25, 25, 25, 255}));  // 3 of the worst 30, scaled to 255
    EXPECT_EQ(diff.get(0, 0), (Rgba{0, 0, 0, 255}));
}

TEST(ImageMetrics, OverlayDimsTheActualImageAndPaintsWrongPixelsMagenta) {
    Image expected(2, 1, Rgba{90, 60, 30, 255});
    Image actual = expected;
    actual.set(1, 0, Rgba{90, 60, 40, 255});  // off by 10
    const Image loose = rl::difference_overlay(expected, actual, 10);
    EXPECT_EQ(loose.get(1, 0), (Rgba{30, 20, 13, 255}));  // within the threshold: dimmed to a third
    const Image strict = rl::difference_overlay(expected, actual, 9);
    EXPECT_EQ(strict.get(0, 0), (Rgba{30, 20, 10, 255}));
    EXPECT_EQ(strict.get(1, 0), (Rgba{255, 0, 255, 255}));
}

TEST(ImageMetrics, SizesMustMatch) {
    EXPECT_THROW(rl::compare_images(Image(2, 2), Image(2, 3)), std::invalid_argument);
}

TEST(ResultsTable, WritesCsvWithQuotingAndExactFloats) {
    rl::ResultsTable table({"method", "ns_per_pixel", "pixels"});
    table.add_row({std::string("bresenham"), 1.25, 1000LL});
    table.add_row({std::string("wu, anti-aliased"), 0.1f * 3, 7LL});
    EXPECT_EQ(
        table.to_csv(),
        "method,ns_per_pixel,pixels\nbresenham,1.25,1000\n\"wu, anti-aliased\",0.300000012,7\n");
    EXPECT_THROW(table.add_row({1.0}), std::invalid_argument);

    rl_test::TempDir dir;
    table.write_csv(dir.path() / "lab.csv");
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "lab.csv"));
}

}  // namespace
