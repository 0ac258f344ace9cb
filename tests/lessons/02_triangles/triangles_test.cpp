// Lesson 02's stability cases. The fixed-point edge rasterizer must agree
// with the exact rule everywhere; the float methods' failures are measured
// and pinned here, so a change that hides or worsens them shows up.
#include <gtest/gtest.h>

#include <limits>
#include <set>

#include "02_triangles/truths/triangle_measure.hpp"

namespace {

using triangles::RasterMethod;
using triangles::ScreenTriangle;

std::set<std::pair<int, int>> pixels(RasterMethod m, const ScreenTriangle& t, int size = 64) {
    const auto list = triangles::covered_pixels(m, t, size, size);
    return {list.begin(), list.end()};
}

std::set<std::pair<int, int>> reference(const ScreenTriangle& t, int size = 64) {
    std::set<std::pair<int, int>> out;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if (triangles::reference_covers(t, x, y)) out.insert({x, y});
    return out;
}

class EveryMethod : public testing::TestWithParam<RasterMethod> {};

TEST_P(EveryMethod, ZeroAreaTrianglesCoverNothing) {
    EXPECT_TRUE(
        pixels(GetParam(), {{{1.5f, 1.5f}, {10.5f, 10.5f}, {20.5f, 20.5f}}}).empty());  // collinear
    EXPECT_TRUE(pixels(GetParam(), {{{5, 5}, {5, 5}, {5, 5}}}).empty());
}

TEST_P(EveryMethod, NanAndInfinityAreRefusedWithoutDrawing) {
    const float nan = std::numeric_limits<float>::quiet_NaN(),
                inf = std::numeric_limits<float>::infinity();
    for (const ScreenTriangle& t :
         {ScreenTriangle{{{nan, 1}, {5, 5}, {9, 1}}}, ScreenTriangle{{{1, 1}, {inf, 5}, {9, 1}}}}) {
        int calls = 0;
        EXPECT_FALSE(
            triangles::rasterize(GetParam(), t, 16, 16, [&](int, int, rl::vec3) { ++calls; }));
        EXPECT_EQ(calls, 0);
    }
}

TEST_P(EveryMethod, TrianglesPartlyOrFarOffScreenStayInsideTheImage) {
    // Any pixel outside would trip the debug bounds check or the sanitizers.
    for (const ScreenTriangle& t : {ScreenTriangle{{{-100, -100}, {40, 10}, {10, 300}}},
                                    ScreenTriangle{{{-5e5f, -5e5f}, {5e5f, -5e5f}, {0, 5e5f}}},
                                    ScreenTriangle{{{1e6f, 1e6f}, {2e6f, 1e6f}, {1e6f, 2e6f}}}}) {
        triangles::rasterize(GetParam(), t, 32, 32, [&](int x, int y, rl::vec3) {
            ASSERT_TRUE(x >= 0 && y >= 0 && x < 32 && y < 32) << x << "," << y;
        });
    }
}

TEST_P(EveryMethod, BarycentricWeightsInterpolateThePixelCentre) {
    const ScreenTriangle t{{{2.25f, 3.5f}, {40.75f, 9.0f}, {12.0f, 50.5f}}};
    triangles::rasterize(GetParam(), t, 64, 64, [&](int x, int y, rl::vec3 b) {
        const rl::vec2 p = t.v[0] * b.x + t.v[1] * b.y + t.v[2] * b.z;
        EXPECT_NEAR(p.x, x + 0.5f, 1e-3f);
        EXPECT_NEAR(p.y, y + 0.5f, 1e-3f);
        EXPECT_NEAR(b.x + b.y + b.z, 1.0f, 1e-5f);
    });
}

// Far-out vertices: the scanline method used to call shade with x = INT_MIN
// for (3e38, 10.5) (-3e38, 300.5) (1.5e38, 100.5) and crash; bbox drew
// nothing for a full-screen triangle from 1e20 up. Now every method refuses
// what lies beyond kMaxCoordinate and draws the rest inside the image.
TEST_P(EveryMethod, FarOutVerticesAreRefusedWithoutACall) {
    for (const ScreenTriangle& t :
         {ScreenTriangle{{{3e38f, 10.5f}, {-3e38f, 300.5f}, {1.5e38f, 100.5f}}},
          ScreenTriangle{{{-1e20f, -1e20f}, {1e20f, -1e20f}, {0, 1e20f}}},
          ScreenTriangle{{{-4194305.0f, 0}, {40, 0}, {0, 40}}}}) {
        int calls = 0;
        EXPECT_FALSE(
            triangles::rasterize(GetParam(), t, 64, 64, [&](int, int, rl::vec3) { ++calls; }));
        EXPECT_EQ(calls, 0);
    }
}

TEST_P(EveryMethod, TrianglesReachingTheRangeLimitStayInsideAndDrawEachPixelOnce) {
    // 600 random triangles with vertices up to 2^22 pixels out, crossing a
    // 64 x 64 image: every call inside, no pixel twice, and within two pixels
    // in a thousand of the exact rule (measured: 1.1 for scanline, 1.0 for
    // bbox; float's spacing is half a pixel out there). The edge method: none.
    std::uint64_t state = 99;
    auto uniform = [&](double low, double high) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return low + (high - low) * static_cast<double>(state >> 11) / 9007199254740992.0;
    };
    const double limit = triangles::kMaxCoordinate;
    long wrong = 0, covered = 0;
    for (int i = 0; i < 600; ++i) {
        ScreenTriangle t;
        for (rl::vec2& v : t.v) v = {float(uniform(-limit, limit)), float(uniform(-limit, limit))};
        if (i % 2) t.v[0] = {float(uniform(0, 64)), float(uniform(0, 64))};  // one inside
        std::set<std::pair<int, int>> seen;
        ASSERT_TRUE(triangles::rasterize(GetParam(), t, 64, 64, [&](int x, int y, rl::vec3) {
            ASSERT_TRUE(x >= 0 && y >= 0 && x < 64 && y < 64) << x << "," << y;
            EXPECT_TRUE(seen.insert({x, y}).second) << "pixel " << x << "," << y << " twice";
        }));
        const auto exact = reference(t);
        covered += static_cast<long>(exact.size());
        for (const auto& p : exact) wrong += !seen.count(p);
        for (const auto& p : seen) wrong += !exact.count(p);
    }
    EXPECT_GT(covered, 100000);
    if (GetParam() == RasterMethod::edge)
        EXPECT_EQ(wrong, 0);
    else
        EXPECT_LT(wrong * 500, covered) << wrong << " wrong of " << covered;
}

INSTANTIATE_TEST_SUITE_P(All, EveryMethod, testing::ValuesIn(triangles::kRasterMethods),
                         [](const auto& param_info) { return triangles::name(param_info.param); });

// docs/02_triangles.md works this example by hand; the code must agree.
TEST(Barycentric, TheWorkedExampleOfThePage) {
    const ScreenTriangle t{{{1, 1}, {9, 2}, {3, 7}}};
    const float area = triangles::signed_area2(t);
    EXPECT_EQ(area, 46.0f);
    const rl::vec3 b = triangles::barycentric(t, {4, 3}, area);
    EXPECT_FLOAT_EQ(b.x * 46, 19);
    EXPECT_FLOAT_EQ(b.y * 46, 14);
    EXPECT_FLOAT_EQ(b.z * 46, 13);
}

TEST(EdgeRasterizer, MatchesTheExactRuleOnRandomTrianglesAndTies) {
    for (const auto& scene :
         {triangles::random_triangles(300, 60, 64, 11), triangles::tie_triangles(300, 64, 12)}) {
        const auto score = triangles::score_coverage(RasterMethod::edge, scene, 64, 64);
        EXPECT_EQ(score.wrong(), 0);
        EXPECT_GT(score.reference_pixels, 1000);
    }
}

TEST(EdgeRasterizer, NeedlesAndSliversMatchTheExactRule) {
    const ScreenTriangle needle{{{0.5f, 0.5f}, {63.5f, 1.0f}, {63.5f, 0.75f}}};
    const ScreenTriangle sliver{{{3.0f, 60.0f}, {60.0f, 3.0f}, {60.1f, 3.2f}}};
    const ScreenTriangle on_centres{{{4.5f, 4.5f}, {30.5f, 4.5f}, {4.5f, 30.5f}}};
    for (const ScreenTriangle& t : {needle, sliver, on_centres})
        EXPECT_EQ(pixels(RasterMethod::edge, t), reference(t));
}

TEST(EdgeRasterizer, BothWindingsCoverTheSamePixels) {
    for (const ScreenTriangle& t : triangles::random_triangles(100, 200, 64, 13))
        EXPECT_EQ(pixels(RasterMethod::edge, t),
                  pixels(RasterMethod::edge, {{t.v[0], t.v[2], t.v[1]}}));
}

TEST(EdgeRasterizer, FansAndGridsCoverEveryPixelExactlyOnce) {
    for (const auto& mesh :
         {triangles::disc_fan({32.5f, 32.5f}, 28, 24), triangles::jittered_grid(6, 64, 4, 3)}) {
        const auto score = triangles::score_watertight(RasterMethod::edge, mesh, 64, 64);
        EXPECT_EQ(score.double_covered, 0);
        EXPECT_EQ(score.holes, 0);
        EXPECT_GT(score.pixels, 1500);
    }
}

TEST(EdgeRasterizer, HugeCoordinatesWithinRangeStayExactAndBeyondAreRefused) {
    // A triangle reaching 3 million pixels out, still inside the fixed-point range.
    const ScreenTriangle huge{{{-3e6f, -1e6f}, {3e6f, -2e6f}, {10.25f, 3e6f}}};
    EXPECT_EQ(pixels(RasterMethod::edge, huge), reference(huge));
    const ScreenTriangle beyond{{{-5e6f, 0}, {5e6f, 0}, {0, 5e6f}}};  // past 2^22 pixels
    EXPECT_FALSE(
        triangles::rasterize(RasterMethod::edge, beyond, 64, 64, [](int, int, rl::vec3) {}));
}

// The weak methods, measured.
TEST(FloatRasterizers, BoundingBoxDrawsSharedEdgesTwice) {
    const auto fan = triangles::disc_fan({32.5f, 32.5f}, 28, 24);
    const auto score = triangles::score_watertight(RasterMethod::bbox, fan, 64, 64);
    EXPECT_GT(score.double_covered, 0);  // every centre on a shared edge, including the hub
}

TEST(FloatRasterizers, ScanlineIsWatertightButBreaksTiesTheOtherWay) {
    // Half-open rows [bottom, top) and columns [left, right): a bottom-left
    // rule. Consistent across shared edges, but not the top-left rule.
    const auto fan = triangles::disc_fan({32.5f, 32.5f}, 28, 24);
    const auto mesh = triangles::score_watertight(RasterMethod::scanline, fan, 64, 64);
    EXPECT_EQ(mesh.double_covered, 0);
    EXPECT_EQ(mesh.holes, 0);
    const ScreenTriangle flat_top{
        {{4.5f, 4.5f}, {30.5f, 20.5f}, {4.5f, 20.5f}}};  // top edge through centres
    EXPECT_NE(pixels(RasterMethod::scanline, flat_top), reference(flat_top));
}

}  // namespace
