// Lesson 12's tests: the fast path covers exactly the pixels lesson 02's edge
// rasterizer covers, draws lesson 07's image for every shading option, gives
// the same bytes on any number of threads and with any technique turned off,
// allocates nothing after its first frame, and encodes sRGB as lesson 06 does
// on every instruction set it was built for. docs/12_fast.md links each.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <random>
#include <set>

#include "02_triangles/overdraw.hpp"
#include "02_triangles/truths/triangle_measure.hpp"
#include "06_shading/colour.hpp"
#include "07_normal_mapping/scene.hpp"
#include "12_fast/lab/coverage_check.hpp"
#include "12_fast/orbit.hpp"
#include "12_fast/packed_texture.hpp"
#include "12_fast/renderer.hpp"
#include "hwy/targets.h"
#include "rasterlab/checkpoint.hpp"
#include "rasterlab/image_metrics.hpp"
#include "rasterlab/transform.hpp"

// Every allocation of this test program, counted (the frame loop must make
// none). The replacements pair malloc with free; GCC, seeing operator new's
// memory reach free() through them, would warn of a mismatch that is not one.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
namespace {
std::atomic<long> allocations{0};
}
void* operator new(std::size_t size) {
    ++allocations;
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
#pragma GCC diagnostic pop

namespace {

using triangles::ScreenTriangle;
using Pixels = std::set<std::pair<int, int>>;

Pixels lesson02(const ScreenTriangle& t, int width, int height) {
    const auto list = triangles::covered_pixels(triangles::RasterMethod::edge, t, width, height);
    return {list.begin(), list.end()};
}

// The fast path's pixels, with every tiling and with the coarse block test on and off.
void expect_same_coverage(const ScreenTriangle& t, int width, int height) {
    for (int tile : {8, 16, 64})
        for (bool coarse : {true, false}) {
            fast::Techniques techniques;
            techniques.coarse_blocks = coarse;
            const auto fast = fast::covered_pixels(t, width, height, tile, techniques);
            ASSERT_TRUE(fast.has_value());
            EXPECT_EQ(Pixels(fast->begin(), fast->end()), lesson02(t, width, height))
                << "tile " << tile << (coarse ? ", coarse" : "") << ": (" << t.v[0].x << ", "
                << t.v[0].y << ") (" << t.v[1].x << ", " << t.v[1].y << ") (" << t.v[2].x << ", "
                << t.v[2].y << ")";
        }
}

TEST(Coverage, MatchesLessonTwoOnItsStabilityScenesBitForBit) {
    std::vector<ScreenTriangle> scene = triangles::random_triangles(200, 60, 64, 11);
    for (const auto& more :
         {triangles::tie_triangles(200, 64, 12), triangles::disc_fan({32.5f, 32.5f}, 28, 24),
          triangles::jittered_grid(6, 64, 4, 3)})
        scene.insert(scene.end(), more.begin(), more.end());
    // Needles, slivers, centres exactly on edges, a triangle 3 million pixels out.
    scene.push_back({{{0.5f, 0.5f}, {63.5f, 1.0f}, {63.5f, 0.75f}}});
    scene.push_back({{{3.0f, 60.0f}, {60.0f, 3.0f}, {60.1f, 3.2f}}});
    scene.push_back({{{4.5f, 4.5f}, {30.5f, 4.5f}, {4.5f, 30.5f}}});
    scene.push_back({{{-3e6f, -1e6f}, {3e6f, -2e6f}, {10.25f, 3e6f}}});
    for (const ScreenTriangle& t : scene) {
        expect_same_coverage(t, 64, 64);
        expect_same_coverage({{t.v[0], t.v[2], t.v[1]}}, 64, 64);  // the other winding
    }
}

TEST(Coverage, MatchesLessonTwoAcrossTileSeamsOfALargerFrame) {
    // 200 x 150: tiles of 64 meet inside the triangles, and the last ones are cut short.
    for (ScreenTriangle t : triangles::random_triangles(150, 3000, 200, 21)) {
        for (rl::vec2& v : t.v) v.y *= 0.75f;
        expect_same_coverage(t, 200, 150);
    }
}

// docs/12_fast.md's worked example: the triangle (0, 0), (20, 0), (0, 20) in
// one 64x64 tile. Of the nine 8x8 blocks its box touches, the corners accept
// one whole, reject three and leave five to test pixel by pixel; 190 centres
// lie inside and 20 exactly on the long edge: a right edge, so lesson 02's
// tie rule leaves them to the triangle on its other side.
TEST(WorkedExample, TheBlocksOfThePage) {
    fast::Setup setup{};
    setup.window[0] = {0, 0, 0.5f};
    setup.window[1] = {20, 0, 0.5f};
    setup.window[2] = {0, 20, 0.5f};
    std::vector<fast::FastTriangle> triangles(1);
    ASSERT_TRUE(fast::fast_triangle(setup, 0, 64, 64, triangles[0]));
    fast::TileBuffers buffers(64);
    const fast::TriangleChunks chunks{{triangles.data()}, {0, 1}};
    const std::uint32_t bin[1] = {0};
    const fast::TileWork work{0, 0, 64, 64, &chunks, bin, 1, nullptr, {}};
    fast::TileCounts counts;
    fast::rasterize_tile(work, buffers, counts);
    EXPECT_EQ(counts.blocks_full, 1u);
    EXPECT_EQ(counts.blocks_rejected, 3u);
    EXPECT_EQ(counts.blocks_partial, 5u);
    EXPECT_EQ(counts.depth_passed, 190u);
    EXPECT_EQ(lesson02({{{0, 0}, {20, 0}, {0, 20}}}, 64, 64).size(), 190u);
}

// docs/12_fast.md's failure pictures (12_failures): a 64x64 fan of twelve
// triangles in tiles of 16, through the tile kernels with one mistake of the
// tile loop each. Right, no pixel differs from lesson 02's edge rasterizer;
// each mistake changes the pixels the page counts, in the way it says.
TEST(Coverage, TheTileLoopMistakesOfThePage) {
    const int size = 64, slices = 12;
    const rl::Image right = triangles::fan_owners(
        triangles::covered_by(triangles::RasterMethod::edge, size, size), size, slices);
    const rl::Rgba twice{230, 30, 30, 255}, none{0, 0, 0, 255};
    struct Count {
        int differing = 0, drawn_twice = 0, undrawn = 0;
    };
    auto count = [&](fast::CoverageMistake mistake) {
        const rl::Image picture = triangles::fan_owners(
            [&](const ScreenTriangle& t) {
                return fast::covered_pixels(t, size, size, 16, {}, mistake).value();
            },
            size, slices);
        Count c;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const rl::Rgba p = picture.get(x, y), q = right.get(x, y);
                c.differing += p != q;
                c.drawn_twice += p == twice;
                c.undrawn += p == none && q != none;
            }
        return c;
    };
    EXPECT_EQ(count(fast::CoverageMistake::none).differing, 0);
    const Count inclusive = count(fast::CoverageMistake::inclusive_ties);
    EXPECT_EQ(inclusive.differing, 105);
    EXPECT_EQ(inclusive.drawn_twice, 105);  // every differing pixel drawn twice
    const Count exclusive = count(fast::CoverageMistake::exclusive_ties);
    EXPECT_EQ(exclusive.differing, 105);
    EXPECT_EQ(exclusive.undrawn, 105);  // the same centres, drawn by none
    EXPECT_EQ(count(fast::CoverageMistake::tile_origin).differing, 773);
    EXPECT_EQ(count(fast::CoverageMistake::shared_buffer).differing, 1451);
}

TEST(Coverage, RefusesWhatLessonTwoRefuses) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (const ScreenTriangle& t :
         {ScreenTriangle{{{nan, 0}, {10, 0}, {0, 10}}}, ScreenTriangle{{{0, 0}, {inf, 0}, {0, 10}}},
          ScreenTriangle{{{-5e6f, 0}, {5e6f, 0}, {0, 5e6f}}}}) {
        EXPECT_FALSE(triangles::rasterize(triangles::RasterMethod::edge, t, 64, 64,
                                          [](int, int, rl::vec3) {}));
        EXPECT_FALSE(fast::covered_pixels(t, 64, 64, 16, {}).has_value());
    }
    // Zero area: nothing, as lesson 02.
    const auto flat = fast::covered_pixels({{{0, 0}, {10, 10}, {20, 20}}}, 64, 64, 16, {});
    ASSERT_TRUE(flat.has_value());
    EXPECT_TRUE(flat->empty());
}

// ----------------------------------------------------------------- images

struct Scene {
    std::vector<normal_mapping::MappedModel> models;
    pipeline::Camera camera;
};

Scene default_scene(const normal_mapping::RenderOptions& options) {
    std::vector<std::string> warnings;
    Scene s{normal_mapping::default_scene(normal_mapping::TangentMethod::split, warnings,
                                          options.output),
            {}};
    s.camera.eye = {0.6f, 2.2f, 4.2f};
    s.camera.target = {0, 0.5f, 0};
    s.camera.near = 0.5f;
    s.camera.far = 20;
    return s;
}

rl::Image lesson07(const Scene& s, const normal_mapping::RenderOptions& options, int width,
                   int height) {
    pipeline::ColourTarget frame = pipeline::colour_target(width, height);
    normal_mapping::render(s.models, s.camera, options, frame);
    return frame.colour();
}

rl::Image fast_image(const Scene& s, const fast::FastOptions& options, int width, int height,
                     const pipeline::Camera* camera = nullptr) {
    fast::Renderer renderer(s.models, width, height, options);
    renderer.render(camera ? *camera : s.camera);
    return renderer.frame();
}

// Lesson 07's golden tolerance: no channel 8 levels off, at most 0.1% of
// pixels more than 1 level off.
void expect_lesson07_tolerance(const rl::Image& expected, const rl::Image& actual,
                               const std::string& what) {
    const rl::ImageDiff d = rl::compare_images(expected, actual, 1);
    EXPECT_LE(d.max_abs, 8) << what;
    EXPECT_LE(d.share_over, 0.001) << what;
}

struct Variant {
    const char* name;
    void (*apply)(normal_mapping::RenderOptions&);
};

TEST(Image, MatchesLessonSevenForEveryShadingOption) {
    const Variant variants[] = {
        {"default", [](normal_mapping::RenderOptions&) {}},
        {"object map", [](auto& o) { o.normal_map = normal_mapping::NormalMap::object; }},
        {"no map", [](auto& o) { o.normal_map = normal_mapping::NormalMap::none; }},
        {"phong", [](auto& o) { o.specular = shading::Specular::phong; }},
        {"bilinear", [](auto& o) { o.filter = textures::Filter::bilinear; }},
        {"nearest", [](auto& o) { o.filter = textures::Filter::nearest; }},
        {"naive", [](auto& o) { o.output = shading::Output::naive; }},
        {"one light", [](auto& o) { o.lighting.lights.resize(1); }},
        {"shininess 7.5", [](auto& o) { o.lighting.shininess = 7.5f; }},
        {"affine", [](auto& o) { o.pipeline.interpolation = pipeline::Interpolation::affine; }},
        {"all planes", [](auto& o) { o.pipeline.clip = pipeline::ClipMode::all; }},
        {"no culling", [](auto& o) { o.pipeline.cull = pipeline::Cull::none; }},
    };
    for (const Variant& v : variants) {
        fast::FastOptions options;
        v.apply(options.render);
        const Scene s = default_scene(options.render);
        expect_lesson07_tolerance(lesson07(s, options.render, 160, 120),
                                  fast_image(s, options, 160, 120), v.name);
    }
}

TEST(Image, MatchesLessonSevenWithTheEyeInsideTheSceneAndAMirroredModel) {
    fast::FastOptions options;
    Scene s = default_scene(options.render);
    std::vector<std::string> warnings;
    // The globe mirrored in x: its faces come clockwise, its bitangents flip.
    s.models.push_back(normal_mapping::load_mapped_model(
        rl::project_model("globe"),
        rl::compose({.translation = {0.2f, 0.6f, 1.2f}, .scale = {-0.5f, 0.5f, 0.5f}}),
        normal_mapping::TangentMethod::split, warnings));
    expect_lesson07_tolerance(lesson07(s, options.render, 160, 120),
                              fast_image(s, options, 160, 120), "mirrored globe");
    // The eye between the models, most of the floor and the crate behind it
    // or beside it: faces cut by the near plane (lesson 05's clipping).
    s.camera.eye = {0.1f, 0.7f, 0.3f};
    s.camera.target = {-0.75f, 0.8f, -0.2f};
    s.camera.near = 0.05f;
    expect_lesson07_tolerance(lesson07(s, options.render, 160, 120),
                              fast_image(s, options, 160, 120), "eye inside");
}

// The page's promise, for every filter: within one level of lesson 07's
// image at every pixel, from random views around the scene (near and far,
// grazing and steep). The weights and texture coordinates are lesson 07's
// to the bit, so `nearest` picks lesson 07's texel; a coordinate one bit
// off flips a texel and a channel by tens of levels.
TEST(Image, EveryFilterWithinOneLevelOfLessonSevenOnRandomViews) {
    std::uint32_t state = 12345;
    const auto next = [&state](float lo, float hi) {
        state = state * 1664525u + 1013904223u;
        return lo + (hi - lo) * static_cast<float>(state >> 8) / 16777216.0f;
    };
    for (textures::Filter filter : textures::kFilters) {
        fast::FastOptions options;
        options.render.filter = filter;
        Scene s = default_scene(options.render);
        for (int view = 0; view < 12; ++view) {
            const float distance = next(0.6f, 6), azimuth = next(0, 6.2832f),
                        height = next(0.05f, 3);
            s.camera.eye = {distance * std::cos(azimuth), height, distance * std::sin(azimuth)};
            s.camera.target = {next(-0.5f, 0.5f), next(0, 0.8f), next(-0.5f, 0.5f)};
            s.camera.near = 0.05f;
            const rl::ImageDiff d = rl::compare_images(lesson07(s, options.render, 96, 72),
                                                       fast_image(s, options, 96, 72), 1);
            EXPECT_LE(d.max_abs, 1) << textures::name(filter) << ", view " << view;
        }
    }
}

// Random meshes with degenerate faces (a repeated vertex, three collinear
// ones), at sizes from 1e-8 to 1, framed by lesson 05's camera: the fast
// path draws lesson 07's picture at every size. With weights stepped in
// float, tiny meshes came out with a quarter of their pixels far off.
TEST(Image, RandomDegenerateMeshesMatchLessonSevenAtAnySize) {
    std::mt19937 random(7);
    const auto uniform = [&random](float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(random);
    };
    const std::filesystem::path obj =
        std::filesystem::temp_directory_path() /
        ("rasterlab-fast-degenerate-" + std::to_string(std::random_device{}()) + ".obj");
    for (int mesh = 0; mesh < 24; ++mesh) {
        const float scale =
            std::array{1e-8f, 1e-6f, 1e-4f, 1.0f}[static_cast<std::size_t>(mesh % 4)];
        std::vector<rl::vec3> v(12);
        for (rl::vec3& p : v) p = rl::vec3{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)} * scale;
        v.push_back(v[0]);                  // a repeated vertex
        v.push_back((v[0] + v[1]) * 0.5f);  // collinear with v[0] and v[1]
        {
            std::ofstream out(obj);
            out.precision(9);
            for (const rl::vec3& p : v) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
            for (std::size_t i = 0; i < v.size(); ++i)
                out << "vt " << uniform(0, 1) << ' ' << uniform(0, 1) << '\n';
            const auto face = [&out](std::size_t a, std::size_t b, std::size_t c) {
                out << "f " << a + 1 << '/' << a + 1 << ' ' << b + 1 << '/' << b + 1 << ' ' << c + 1
                    << '/' << c + 1 << '\n';
            };
            for (int f = 0; f < 16; ++f)
                face(random() % v.size(), random() % v.size(), random() % v.size());
            face(1, 12, 13);  // degenerate: v[12] = v[0], v[13] on the line v[0] v[1]
            face(0, 13, 2);
        }
        fast::FastOptions options;
        std::vector<std::string> warnings;
        Scene s{{}, {}};
        s.models.push_back(normal_mapping::load_mapped_model(
            obj, rl::mat4::identity(), normal_mapping::TangentMethod::split, warnings));
        s.camera = pipeline::frame_box(normal_mapping::scene_box(s.models), 50, 1);
        expect_lesson07_tolerance(
            lesson07(s, options.render, 64, 64), fast_image(s, options, 64, 64),
            "mesh " + testing::PrintToString(mesh) + " at scale " + testing::PrintToString(scale));
    }
    std::filesystem::remove(obj);
}

// Pitfall: the depth test is `less`, as lesson 07's: of two coplanar
// surfaces, the one drawn first keeps every pixel. The floor drawn twice,
// the second copy plain red: a `less or equal` test would let the red copy
// win wherever its depth rounds the same (every pixel here, the same
// triangles twice), and the picture would no longer be lesson 07's.
TEST(Image, EqualDepthsKeepTheSurfaceDrawnFirst) {
    fast::FastOptions options;
    Scene s = default_scene(options.render);
    s.models.erase(s.models.begin() + 1, s.models.end());  // the floor
    s.models.push_back(s.models.front());
    rl::Image red(4, 4);
    for (rl::Rgba& p : red.pixels()) p = {255, 0, 0, 255};
    s.models.back().lit.model.texture = textures::MipChain(red);
    const rl::Image expected = lesson07(s, options.render, 96, 72);
    const rl::Image actual = fast_image(s, options, 96, 72);
    expect_lesson07_tolerance(expected, actual, "coplanar floors");
    int red_pixels = 0;
    for (const rl::Rgba& p : actual.pixels()) red_pixels += p.r > 3 * p.g + 30;
    EXPECT_EQ(red_pixels, 0);
}

TEST(Image, SameBytesWhateverTheThreadCount) {
    fast::FastOptions options;
    const Scene s = default_scene(options.render);
    options.threads = 1;
    const rl::Image one = fast_image(s, options, 301, 203);  // tiles cut short at the edges
    for (int threads : {2, 7}) {
        options.threads = threads;
        EXPECT_EQ(fast_image(s, options, 301, 203), one) << threads << " threads";
    }
}

// A hook that counts the checkpoints it is called at (from any thread), and
// throws at the `stop_at`-th: what the Python module's Ctrl-C does.
struct Stopped {};
std::atomic<int> g_checkpoints{0};
int g_stop_at = 0;
void count_and_maybe_stop() {
    if (++g_checkpoints == g_stop_at) throw Stopped{};
}

TEST(Renderer, AHostCanStopAFrameBetweenTiles) {
    fast::FastOptions options;
    const Scene s = default_scene(options.render);
    options.threads = 2;
    fast::Renderer renderer(s.models, 256, 192, options);  // 4 x 3 tiles of 64
    g_checkpoints = 0;
    g_stop_at = 0;  // counts only
    rl::set_checkpoint_hook(count_and_maybe_stop);
    renderer.render(s.camera);
    EXPECT_EQ(g_checkpoints.load(), 12);
    g_checkpoints = 0;
    g_stop_at = 5;
    EXPECT_THROW(renderer.render(s.camera), Stopped);  // from whichever thread met it
    rl::set_checkpoint_hook(nullptr);
    // The renderer is still whole: the next frame is the frame.
    renderer.render(s.camera);
    EXPECT_EQ(renderer.frame(), fast_image(s, options, 256, 192));
}

TEST(Image, EachTechniqueOffLeavesTheImageAlone) {
    const fast::FastOptions all;
    const Scene s = default_scene(all.render);
    const rl::Image reference = fast_image(s, all, 160, 120);
    const auto with = [&](auto&& change) {
        fast::FastOptions o = all;
        change(o);
        return fast_image(s, o, 160, 120);
    };
    // The same integers and floats in another order of work: the same bytes.
    EXPECT_EQ(with([](auto& o) { o.vertex_cache = false; }), reference);
    EXPECT_EQ(with([](auto& o) { o.parallel = false; }), reference);
    EXPECT_EQ(with([](auto& o) { o.techniques.coarse_blocks = false; }), reference);
    EXPECT_EQ(with([](auto& o) { o.techniques.hierarchical_depth = false; }), reference);
    EXPECT_EQ(with([](auto& o) { o.techniques.across_triangles = false; }), reference);
    EXPECT_EQ(with([](auto& o) { o.techniques.block_rows = false; }), reference);
    EXPECT_EQ(with([](auto& o) { o.techniques.srgb_one_gather = false; }), reference);
    // The albedo's 16-bit words against its square roots in one word: the
    // values differ by less than a fifth of a level (the encoding test).
    expect_lesson07_tolerance(reference, with([](auto& o) { o.albedo_in_one_word = false; }),
                              "albedo in two words");
    // Shading by blocks steps the weights from each block's corner, not from
    // the tile's: a level apart in a few pixels at most; shading every passing
    // pixel at once (no visibility buffer) ends on the same colours as that.
    const rl::Image by_blocks = with([](auto& o) { o.techniques.full_vectors = false; });
    expect_lesson07_tolerance(reference, by_blocks, "by blocks");
    EXPECT_EQ(with([](auto& o) { o.techniques.shade_once = false; }), by_blocks);
}

// The specular map read from the normal map's alpha bytes: the very
// picture the specular map read on its own gives, byte for byte, for both
// normal maps and every filter, from random views (the globe's seam, where
// a row's extra texel is read, comes into some of them); and the default
// scene's globe and crate do carry it there.
TEST(Image, TheSpecularMapInTheNormalMapsAlphaLeavesTheImageAlone) {
    std::uint32_t state = 777;
    const auto next = [&state](float lo, float hi) {
        state = state * 1664525u + 1013904223u;
        return lo + (hi - lo) * static_cast<float>(state >> 8) / 16777216.0f;
    };
    int packed = 0;
    for (const normal_mapping::NormalMap normals :
         {normal_mapping::NormalMap::tangent, normal_mapping::NormalMap::object})
        for (const textures::Filter filter : textures::kFilters) {
            fast::FastOptions on;
            on.render.normal_map = normals;
            on.render.filter = filter;
            fast::FastOptions off = on;
            off.specular_in_normal_alpha = false;
            Scene s = default_scene(on.render);
            for (const normal_mapping::MappedModel& m : s.models) {
                const fast::FastModel f = fast::fast_model(m, on);
                const fast::PackedTexture* map = normals == normal_mapping::NormalMap::tangent
                                                     ? f.tangent_map.get()
                                                     : f.object_map.get();
                packed += map && f.specular_map && map->alpha_holds_other;
            }
            // Each renderer prepares the models once for the three views.
            fast::Renderer packed_in_alpha(s.models, 96, 72, on), read_apart(s.models, 96, 72, off);
            for (int view = 0; view < 3; ++view) {
                const float distance = next(0.8f, 5), azimuth = next(0, 6.2832f);
                s.camera.eye = {distance * std::cos(azimuth), next(0.1f, 3),
                                distance * std::sin(azimuth)};
                s.camera.target = {next(-0.5f, 0.5f), next(0, 0.8f), next(-0.5f, 0.5f)};
                s.camera.near = 0.05f;
                packed_in_alpha.render(s.camera);
                read_apart.render(s.camera);
                EXPECT_EQ(packed_in_alpha.frame(), read_apart.frame())
                    << normal_mapping::name(normals) << ", " << textures::name(filter) << ", view "
                    << view;
            }
        }
    // The globe and the crate have both maps of the same size; the floor has none.
    // (The object-space map: the globe's alone.)
    EXPECT_EQ(packed, 3 * 2 + 3 * 1);
}

TEST(Image, EveryInstructionSetGivesLessonSevensImage) {
    fast::FastOptions options;
    const Scene s = default_scene(options.render);
    const rl::Image expected = lesson07(s, options.render, 160, 120);
    int tested = 0;
    for (std::int64_t target : fast::simd_targets()) {
        hwy::SetSupportedTargetsForTest(target);
        expect_lesson07_tolerance(expected, fast_image(s, options, 160, 120),
                                  std::string(fast::simd_target()));
        EXPECT_STREQ(fast::simd_target(), hwy::TargetName(target));
        ++tested;
    }
    hwy::SetSupportedTargetsForTest(0);  // back to the best this CPU has
    EXPECT_GE(tested, 2);                // the portable fallback and at least one SIMD set
}

TEST(Frames, NoAllocationAfterTheFirstFrame) {
    fast::FastOptions options;
    const Scene s = default_scene(options.render);
    fast::Renderer renderer(s.models, 200, 150, options);
    renderer.render(fast::orbit(s.camera, 0, 8));
    const long before = allocations.load();
    for (int frame = 1; frame < 8; ++frame) renderer.render(fast::orbit(s.camera, frame, 8));
    EXPECT_EQ(allocations.load() - before, 0);
}

TEST(Frames, TheOrbitEndsOnTheCameraGiven) {
    pipeline::Camera c;
    c.eye = {1, 2, 3};
    const pipeline::Camera last = fast::orbit(c, 9, 10);
    EXPECT_EQ(last.eye, c.eye);
    const pipeline::Camera half = fast::orbit(c, 4, 10);  // 180 degrees about +y
    EXPECT_NEAR(half.eye.x, -1, 1e-5);
    EXPECT_NEAR(half.eye.y, 2, 1e-5);
    EXPECT_NEAR(half.eye.z, -3, 1e-5);
    EXPECT_EQ(fast::median_after_first({100, 3, 1, 2}), 2);
}

TEST(Encoding, SimdSrgbMatchesLessonSixByteForByte) {
    std::vector<float> values = {0.0f,
                                 -0.0f,
                                 -1.0f,
                                 1.0f,
                                 2.0f,
                                 1e-30f,
                                 std::numeric_limits<float>::quiet_NaN(),
                                 std::numeric_limits<float>::infinity()};
    const shading::SrgbByteTables& tables = shading::srgb_byte_tables();
    for (std::size_t k = 0; k < 255; ++k) {  // each step and its neighbours
        const float step = tables.steps[k];
        values.push_back(step);
        values.push_back(std::nextafter(step, 0.0f));
        values.push_back(std::nextafter(step, 2.0f));
    }
    for (int i = 0; i <= 4096; ++i) {  // each slice's ends, where the one gather changes entry
        const float end = static_cast<float>(i) / 4096.0f;
        values.push_back(end);
        values.push_back(std::nextafter(end, 0.0f));
        values.push_back(std::nextafter(end, 2.0f));
    }
    for (int i = 0; i <= 200000; ++i) values.push_back(static_cast<float>(i) / 200000.0f);
    std::vector<std::uint8_t> bytes(values.size());
    for (std::int64_t target : fast::simd_targets())
        for (const bool one_gather : {true, false}) {
            hwy::SetSupportedTargetsForTest(target);
            fast::encode_srgb(values.data(), bytes.data(), values.size(), one_gather);
            for (std::size_t i = 0; i < values.size(); ++i)
                ASSERT_EQ(bytes[i], shading::encode({values[i], 0, 0}, shading::Output::srgb).r)
                    << values[i] << " on " << hwy::TargetName(target)
                    << (one_gather ? ", one gather" : ", two gathers");
        }
    hwy::SetSupportedTargetsForTest(0);
}

// The decoded albedo: every byte of each channel, as the lookups read it,
// against lesson 06's value of that byte, in fractions of the output level
// at that value (the step between the sRGB bytes either side): the 16-bit
// words within 0.03 of a level, the square roots in one word within 0.2
// (0.16 at worst, for blue's 10 bits near black; docs/12_fast.md, "The
// albedo in one word").
TEST(Encoding, TheDecodedAlbedoIsWithinAFifthOfALevel) {
    rl::Image image(256, 1);
    for (int i = 0; i < 256; ++i)  // each channel its own order: a swap shows
        image.at(i, 0) = {static_cast<std::uint8_t>(i),
                          static_cast<std::uint8_t>((i * 7 + 3) % 256),
                          static_cast<std::uint8_t>(255 - i), 255};
    const textures::MipChain chain(image);
    const shading::SrgbByteTables& tables = shading::srgb_byte_tables();
    const textures::TexelEncoding& srgb = shading::srgb_texels();
    const auto level_at = [&](int byte) {  // the linear width of the output level of `byte`
        const double below = byte > 0 ? tables.steps[static_cast<std::size_t>(byte - 1)] : 0.0;
        const double above = byte < 255 ? tables.steps[static_cast<std::size_t>(byte)] : 1.0;
        return above - below;
    };
    std::vector<std::int32_t> index(256);
    for (int i = 0; i < 256; ++i) index[static_cast<std::size_t>(i)] = i;  // row 0 of level 0
    for (const bool one_word : {false, true}) {
        const fast::PackedTexture packed(chain, false, &srgb, one_word);
        ASSERT_EQ(packed.one_word, one_word);
        for (std::int64_t target : fast::simd_targets()) {
            hwy::SetSupportedTargetsForTest(target);
            std::vector<float> rgb(3 * 256);
            fast::decode_texels(packed, index.data(), index.size(), rgb.data());
            for (int i = 0; i < 256; ++i)
                for (int c = 0; c < 3; ++c) {
                    const rl::Rgba texel = image.at(i, 0);
                    const int byte = c == 0 ? texel.r : c == 1 ? texel.g : texel.b;
                    const double off = std::abs(rgb[static_cast<std::size_t>(3 * i + c)] -
                                                srgb.value[static_cast<std::size_t>(byte)]);
                    ASSERT_LE(off / level_at(byte), one_word ? 0.2 : 0.03)
                        << "byte " << byte << " of channel " << c << (one_word ? ", one word" : "")
                        << " on " << hwy::TargetName(target);
                }
        }
        hwy::SetSupportedTargetsForTest(0);
    }
}

TEST(Options, RefusedWithTheReason) {
    const fast::FastOptions defaults;
    const Scene s = default_scene(defaults.render);
    fast::FastOptions o = defaults;
    o.tile_size = 12;
    EXPECT_THROW(fast::Renderer(s.models, 64, 64, o), std::invalid_argument);
    o = defaults;
    o.render.pipeline.raster = triangles::RasterMethod::scanline;
    EXPECT_THROW(fast::Renderer(s.models, 64, 64, o), std::invalid_argument);
    o = defaults;
    o.render.lighting.lights.resize(9, o.render.lighting.lights[0]);
    EXPECT_THROW(fast::Renderer(s.models, 64, 64, o), std::invalid_argument);
}

// The bins are sized in 64 bits and capped: a frame that would bin more
// tile entries than the cap is refused, naming the cap and --tile-size,
// before anything is written (at 16384² in 8-pixel tiles a few hundred large
// triangles wrapped a 32-bit count and wrote past the buffer). At 64x64
// in 8-pixel tiles the default scene bins about a hundred entries.
TEST(Options, BinningOverItsCapIsRefusedNamingTheCap) {
    fast::FastOptions options;
    options.tile_size = 8;
    const Scene s = default_scene(options.render);
    fast::Renderer fits(s.models, 64, 64, options);
    EXPECT_NO_THROW(fits.render(s.camera));
    options.max_binned_entries = 20;
    fast::Renderer over(s.models, 64, 64, options);
    try {
        over.render(s.camera);
        ADD_FAILURE() << "a frame over the binning cap was drawn";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("more than the cap of 20"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("--tile-size"), std::string::npos) << e.what();
    }
}

}  // namespace
