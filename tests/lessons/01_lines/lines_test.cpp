// Lesson 01's stability cases: the inputs on which line methods break. The
// robust methods must pass; the weak method's failure is measured and pinned.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "01_lines/draw_line.hpp"
#include "01_lines/lab/line_measure.hpp"
#include "01_lines/wireframe.hpp"

namespace {

using lines::LineMethod;
using lines::Segment;
using rl::vec2;

std::set<std::pair<int, int>> pixels(LineMethod method, Segment s, int size = 64) {
    std::set<std::pair<int, int>> out;
    for (const auto& p : lines::plotted_pixels(method, s, size, size))
        if (p.coverage > 0) out.insert({p.x, p.y});
    return out;
}

std::set<std::pair<int, int>> expected(std::initializer_list<std::pair<int, int>> list) {
    return list;
}

class AliasedLine : public testing::TestWithParam<LineMethod> {};

TEST_P(AliasedLine, ZeroLengthIsOnePixel) {
    EXPECT_EQ(pixels(GetParam(), {{5.5f, 7.5f}, {5.5f, 7.5f}}), expected({{5, 7}}));
}

TEST_P(AliasedLine, HorizontalVerticalAndDiagonalHitExactlyTheirPixels) {
    std::set<std::pair<int, int>> row, column, diagonal;
    for (int i = 2; i <= 9; ++i) row.insert({i, 4}), column.insert({4, i}), diagonal.insert({i, i});
    EXPECT_EQ(pixels(GetParam(), {{2.5f, 4.5f}, {9.5f, 4.5f}}), row);
    EXPECT_EQ(pixels(GetParam(), {{4.5f, 9.5f}, {4.5f, 2.5f}}), column);
    EXPECT_EQ(pixels(GetParam(), {{9.5f, 9.5f}, {2.5f, 2.5f}}), diagonal);
}

TEST_P(AliasedLine, EveryOctantHasNoGapsNoDuplicatesAndStaysWithinHalfAPixel) {
    lines::LineScore score;
    for (const Segment& s : lines::random_segments(400, 128, 42))
        lines::score_segment(GetParam(), s, 128, 128, score);
    EXPECT_EQ(score.gaps, 0);
    EXPECT_EQ(score.duplicates, 0);
    EXPECT_LE(score.max_distance, 0.5 + 1e-9);
}

TEST_P(AliasedLine, ReversedEndpointsLightAsManyPixelsAsCloseToTheLine) {
    for (const Segment& s : lines::random_segments(200, 128, 7)) {
        const auto forward = pixels(GetParam(), s, 128),
                   backward = pixels(GetParam(), {s.b, s.a}, 128);
        EXPECT_EQ(forward.size(), backward.size());
        for (const auto& [x, y] : backward)
            EXPECT_LE(lines::distance_to_segment({x + 0.5, y + 0.5}, s), 0.5 + 1e-9);
    }
}

TEST_P(AliasedLine, EndpointsOnPixelCentresAreBothLit) {
    const Segment s{{3.5f, 1.5f}, {40.5f, 17.5f}};
    const auto lit = pixels(GetParam(), s);
    EXPECT_TRUE(lit.count({3, 1}));
    EXPECT_TRUE(lit.count({40, 17}));
}

INSTANTIATE_TEST_SUITE_P(Robust, AliasedLine,
                         testing::Values(LineMethod::dda, LineMethod::bresenham),
                         [](const auto& param_info) { return lines::name(param_info.param); });

class AnyLine : public testing::TestWithParam<LineMethod> {};

TEST_P(AnyLine, FarOutsideEndpointsAreClippedExactlyAndQuickly) {
    for (float far : {1e6f, 1e9f}) {
        // The diagonal y = x through the image, from far below-left to far above-right.
        const Segment s{{-far + 0.5f, -far + 0.5f}, {far + 0.5f, far + 0.5f}};
        rl::Image image(64, 64);
        EXPECT_EQ(lines::draw_line(image, s.a, s.b, {255, 255, 255, 255}, GetParam()),
                  lines::ClipResult::clipped);
        for (const auto& [x, y] : pixels(GetParam(), s))
            EXPECT_LE(std::abs(x - y), 1) << "far = " << far;
    }
}

TEST_P(AnyLine, NanAndInfiniteEndpointsAreRefused) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    rl::Image image(16, 16, rl::Rgba{0, 0, 0, 255});
    const rl::Image before = image;
    for (Segment s :
         {Segment{{nan, 1}, {5, 5}}, Segment{{1, 1}, {inf, 5}}, Segment{{-inf, 1}, {5, nan}}})
        EXPECT_EQ(lines::draw_line(image, s.a, s.b, {255, 255, 255, 255}, GetParam()),
                  lines::ClipResult::refused);
    EXPECT_EQ(image, before);
}

TEST_P(AnyLine, LinesOutsideTheImageDrawNothing) {
    rl::Image image(16, 16, rl::Rgba{0, 0, 0, 255});
    const rl::Image before = image;
    EXPECT_EQ(lines::draw_line(image, {-50, -5}, {100, -1}, {255, 255, 255, 255}, GetParam()),
              lines::ClipResult::outside);
    EXPECT_EQ(image, before);
}

INSTANTIATE_TEST_SUITE_P(All, AnyLine, testing::ValuesIn(lines::kLineMethods),
                         [](const auto& param_info) { return lines::name(param_info.param); });

TEST(LineWeaknesses, FixedParametricStepsLeaveGapsOnLongLines) {
    lines::LineScore score;
    lines::score_segment(LineMethod::parametric, {{0.5f, 0.5f}, {300.5f, 20.5f}}, 512, 512, score);
    EXPECT_GT(score.gaps, 150);  // 100 samples for 301 columns
    lines::LineScore short_line;
    lines::score_segment(LineMethod::parametric, {{0.5f, 0.5f}, {5.5f, 2.5f}}, 512, 512,
                         short_line);
    EXPECT_GT(short_line.duplicates, 80);  // and the same pixels again and again on short ones
}

TEST(LineWeaknesses, WuPutsInkWhereTheExactLineIs) {
    lines::LineScore wu, bresenham;
    for (const Segment& s : lines::random_segments(100, 128, 3)) {
        lines::score_segment(LineMethod::wu, s, 128, 128, wu);
        lines::score_segment(LineMethod::bresenham, s, 128, 128, bresenham);
    }
    EXPECT_LT(wu.coverage_error_per_length(), 0.5 * bresenham.coverage_error_per_length());
}

// The pitfall "blending twice": Wu lines blend, so an edge drawn once for
// each of its two triangles would come out darker than the rest.
TEST(Wireframe, SharedEdgesAreDrawnOnceSoWuInkIsNotDoubled) {
    const rl::Mesh square =
        rl::parse_obj("v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nf 1 2 3\nf 1 3 4\n",
                      "", "square.obj");
    rl::Image once(64, 64, rl::Rgba{0, 0, 0, 255});
    EXPECT_EQ(lines::draw_wireframe(once, square, {200, 200, 200, 255}, LineMethod::wu), 5u);
    // The same two triangles, each listed twice: still five edges, the same image.
    const rl::Mesh doubled = rl::parse_obj(
        "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nf 1 2 3\nf 1 3 4\nf 3 1 "
        "2\nf 4 1 3\n",
        "", "doubled.obj");
    rl::Image again(64, 64, rl::Rgba{0, 0, 0, 255});
    EXPECT_EQ(lines::draw_wireframe(again, doubled, {200, 200, 200, 255}, LineMethod::wu), 5u);
    EXPECT_EQ(again, once);
}

TEST(LineClip, LiangBarskyMeetsTheRectangleEdges) {
    const lines::Rect r{0, 0, 10, 10};
    const auto c = lines::clip_segment({-5, 5}, {15, 5}, r);
    ASSERT_EQ(c.result, lines::ClipResult::clipped);
    EXPECT_EQ(c.a, (vec2{0, 5}));
    EXPECT_EQ(c.b, (vec2{10, 5}));
    EXPECT_EQ(lines::clip_segment({2, 2}, {3, 3}, r).result, lines::ClipResult::inside);
    EXPECT_EQ(lines::clip_segment({11, -1}, {20, 5}, r).result, lines::ClipResult::outside);
    EXPECT_EQ(lines::clip_segment({-1, 11}, {11, 12}, r).result, lines::ClipResult::outside);
}

TEST(LineCoverage, ExactCoverageOfAnAxisAlignedLine) {
    const Segment s{{0.5f, 2.5f}, {10.5f, 2.5f}};  // the band covers row 2 exactly
    EXPECT_DOUBLE_EQ(lines::exact_coverage(3, 2, s), 1.0);
    EXPECT_DOUBLE_EQ(lines::exact_coverage(3, 3, s), 0.0);
    EXPECT_DOUBLE_EQ(lines::exact_coverage(0, 2, s), 0.5);  // the line starts at the centre
}

}  // namespace
