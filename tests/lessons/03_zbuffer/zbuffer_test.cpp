// Lesson 03's stability cases: coplanar surfaces, cycles, extreme depth
// ranges and shared edges. The z-buffer and the BSP tree must get them
// right; the painter's algorithm's and the weak depth formats' failures are
// measured and pinned.
#include <gtest/gtest.h>

#include "03_zbuffer/hsr_scenes.hpp"
#include "03_zbuffer/zfight.hpp"

namespace {

using namespace zbuffer;

Frame rendered(HsrMethod method, const std::vector<SceneTriangle>& scene, int size = 128) {
    Frame frame(size, size);
    render(method, scene, frame);
    return frame;
}

TEST(ZBuffer, CoplanarSurfacesGiveTheSameResultEveryTimeAndTheFirstWins) {
    const auto pair = coplanar_pair(64);
    const Frame first = rendered(HsrMethod::zbuffer, pair, 64),
                again = rendered(HsrMethod::zbuffer, pair, 64);
    EXPECT_EQ(first.ids, again.ids);
    long covered = 0;
    for (int id : first.ids.pixels()) {
        if (id < 0) continue;
        ++covered;
        EXPECT_EQ(id, 0);  // `less`: an equal depth does not replace what is there
    }
    EXPECT_GT(covered, 500);
}

TEST(ZBuffer, CyclicOverlapDefeatsThePainterButNotTheBspTree) {
    const auto sticks = cyclic_sticks(128);
    const Frame truth = rendered(HsrMethod::zbuffer, sticks);
    EXPECT_GT(wrong_share(rendered(HsrMethod::painter, sticks), truth),
              0.01);  // one crossing of three
    EXPECT_LT(wrong_share(rendered(HsrMethod::bsp, sticks), truth), 0.002);
}

TEST(ZBuffer, InterpenetratingTrianglesAreSplitByTheBspTree) {
    const auto soup = random_soup(30, 128, 4);
    const Frame truth = rendered(HsrMethod::zbuffer, soup);
    EXPECT_GT(wrong_share(rendered(HsrMethod::painter, soup), truth), 0.01);
    EXPECT_LT(wrong_share(rendered(HsrMethod::bsp, soup), truth), 0.005);
    const BspTree tree = build_bsp(soup);
    EXPECT_GT(tree.triangles, soup.size());  // splitting adds triangles
}

TEST(ZBuffer, SharedEdgesAreNotFoughtOver) {
    // A crease: two triangles meeting along an edge at equal depth. The fill
    // rule gives each pixel of the edge to one triangle, so the result does
    // not depend on the order they are drawn in.
    const rl::vec3 a{10, 10, 0.2f}, b{110, 20, 0.5f}, c{60, 115, 0.2f}, d{115, 100, 0.9f};
    std::vector<SceneTriangle> scene = {{{a, b, c}, {255, 0, 0, 255}, 0},
                                        {{b, d, c}, {0, 0, 255, 255}, 1}};
    const Frame forward = rendered(HsrMethod::zbuffer, scene);
    std::swap(scene[0], scene[1]);
    const Frame backward = rendered(HsrMethod::zbuffer, scene);
    EXPECT_EQ(forward.ids, backward.ids);
}

TEST(DepthFormats, StoredDepthNeverDecreasesWithDistance) {
    const DepthRange range{0.1f, 1000.0f};
    for (DepthFormat f : kDepthFormats) {
        double previous = -1e300;
        for (float w = 0.1f; w <= 1000.0f; w *= 1.01f) {
            const double key = depth_key(f, w, range);
            EXPECT_GE(key, previous) << name(f) << " at " << w;
            previous = key;
        }
    }
}

TEST(DepthFormats, LooseRangesZFightWhereReverseZAndFittedRangesDoNot) {
    TwoPlanes planes;
    planes.size = 64;
    planes.distance = 100;
    const DepthRange loose{0.1f, 1000.0f};
    EXPECT_GT(zfight_share(DepthFormat::fixed16, loose, planes), 0.9);
    EXPECT_GT(zfight_share(DepthFormat::float_z, loose, planes), 0.0);
    EXPECT_EQ(zfight_share(DepthFormat::reverse_z, loose, planes), 0.0);
    EXPECT_EQ(zfight_share(DepthFormat::inverse_w, loose, planes), 0.0);
    EXPECT_EQ(zfight_share(DepthFormat::fixed16, fitted_range(planes), planes), 0.0);
}

TEST(DepthFormats, ExtremeNearFarRatiosBreakStandardDepthFirst) {
    TwoPlanes planes;
    planes.size = 64;
    planes.distance = 10;
    const DepthRange extreme{1e-4f, 1e4f};  // a ratio of 10^8
    const double standard = zfight_share(DepthFormat::float_z, extreme, planes);
    EXPECT_GT(standard, 0.5);
    EXPECT_LT(zfight_share(DepthFormat::reverse_z, extreme, planes), standard);
    EXPECT_EQ(zfight_share(DepthFormat::logarithmic, extreme, planes), 0.0);
}

}  // namespace

namespace {

TEST(Bsp, SplittingIsCappedAndRefusedWithAMessage) {
    // 3000 random triangles piercing each other once took 59 s and 9.6 GB.
    const auto soup = random_soup(3000, 512, 4);
    try {
        build_bsp(soup);
        FAIL() << "built an uncapped tree";
    } catch (const BspTooLarge& e) {
        EXPECT_NE(std::string(e.what()).find("--hsr zbuffer"), std::string::npos) << e.what();
    }
    // The lab's own soup (200 triangles, 512 x 512, seed 9) stays below the cap.
    const BspTree tree = build_bsp(random_soup(200, 512, 9));
    EXPECT_LE(tree.triangles, max_bsp_pieces(200));
    EXPECT_GE(tree.triangles, 200u);
}

TEST(ZBuffer, StartsClearedToTheFarPlaneAndTestsLess) {
    // Cleared to 0 (or tested with `greater`), nothing would ever be drawn.
    const std::vector<SceneTriangle> near_far = {
        {{{5, 5, 0.999f}, {60, 5, 0.999f}, {5, 60, 0.999f}}, {255, 0, 0, 255}, 0},
        {{{5, 5, 1.0f}, {60, 5, 1.0f}, {60, 60, 1.0f}}, {0, 255, 0, 255}, 1}};
    const Frame frame = rendered(HsrMethod::zbuffer, near_far, 64);
    EXPECT_EQ(frame.ids.get(10, 10), 0);  // just in front of the far plane: drawn
    EXPECT_EQ(frame.ids.get(50, 20),
              -1);  // exactly at the far plane: not nearer than the clear value
}

TEST(ZBuffer, ATriangleOnTheFarPlaneWritesNoPixelAtAll) {
    // Unclamped, float weights summing to just under 1 put about a fifth of
    // this triangle's pixels a hair in front of the far plane. Every covered
    // pixel is checked, not one.
    const std::vector<SceneTriangle> far = {
        {{{0.3f, 0.7f, 1.0f}, {250.1f, 3.9f, 1.0f}, {17.7f, 251.3f, 1.0f}}, {0, 255, 0, 255}, 0}};
    const Frame frame = rendered(HsrMethod::zbuffer, far, 256);
    long covered = 0;
    triangles::rasterize_edge(screen(far[0]), 256, 256, [&](int x, int y, rl::vec3 b) {
        ++covered;
        EXPECT_EQ(frame.ids.get(x, y), -1) << x << "," << y;
        EXPECT_EQ(interpolate_depth(b, 1.0f, 1.0f, 1.0f), 1.0f);
    });
    EXPECT_GT(covered, 25000);
}

TEST(ZBuffer, InterpolatedDepthStaysWithinTheVertexDepths) {
    const SceneTriangle t{
        {{1.1f, 2.3f, 0.25f}, {200.7f, 9.9f, 0.75f}, {50.5f, 230.2f, 0.5f}}, {0, 0, 0, 255}, 0};
    triangles::rasterize_edge(screen(t), 256, 256, [&](int, int, rl::vec3 b) {
        const float z = interpolate_depth(b, t.v[0].z, t.v[1].z, t.v[2].z);
        EXPECT_GE(z, 0.25f);
        EXPECT_LE(z, 0.75f);
    });
}

}  // namespace
