// The pipeline's render targets, depth state, samples, tiles, flat values
// and varyings arithmetic (docs/05_perspective.md#the-pipeline).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "05_perspective/scene.hpp"
#include "05_perspective/truths/tile_check.hpp"
#include "05_perspective/view_options.hpp"
#include "rasterlab/checkpoint.hpp"
#include "rasterlab/image_metrics.hpp"

namespace {

using namespace pipeline;

// Triangles given directly in clip space, as the pipeline's geometry.
struct ClipCorner {
    rl::vec4 position;
    int face, corner;
};
struct ClipTriangles {
    std::vector<std::array<rl::vec4, 3>> faces;
    int face_count() const { return static_cast<int>(faces.size()); }
    ClipCorner corner(int face, int k) const {
        return {faces[static_cast<std::size_t>(face)][static_cast<std::size_t>(k)], face, k};
    }
};

// A square of two triangles filling NDC x, y in [-1, 1] at clip depth z(x)
// (w = 1, so NDC is clip space): depth grows to the right when tilt > 0.
ClipTriangles square(float depth, float tilt = 0) {
    const auto at = [&](float x, float y) { return rl::vec4{x, y, depth + tilt * x, 1}; };
    return {{{at(-1, -1), at(1, -1), at(1, 1)}, {at(-1, -1), at(1, 1), at(-1, 1)}}};
}

TargetOptions with_samples(int samples) {
    TargetOptions o;
    o.samples = samples;
    return o;
}
TargetOptions with_depth(const zbuffer::DepthState& state) {
    TargetOptions o;
    o.depth = state;
    return o;
}
zbuffer::DepthState depth_state(zbuffer::DepthCompare compare, float clear, bool write = true) {
    zbuffer::DepthState d;
    d.compare = compare;
    d.clear = clear;
    d.write = write;
    return d;
}

// One triangle much larger than the screen, covering all of it.
ClipTriangles covering_triangle() {
    return {{{rl::vec4{-1, -1, 0, 1}, rl::vec4{3, -1, 0, 1}, rl::vec4{-1, 3, 0, 1}}}};
}

// Writes a constant, or the position's x and y, to every attachment it is given.
struct Constant {
    rl::Rgba colour;
    using Varyings = rl::vec2;  // NDC x, y
    ClipVertex<rl::vec2> vertex(const ClipCorner& c) const {
        return {rl::cast<double>(c.position), {c.position.x, c.position.y}};
    }
    rl::Rgba fragment(const Fragment<rl::vec2>&) const { return colour; }
};

struct DepthOnly {
    int* fragment_calls;
    using Varyings = float;
    ClipVertex<float> vertex(const ClipCorner& c) const {
        return {rl::cast<double>(c.position), 0.0f};
    }
    rl::Rgba fragment(const Fragment<float>&) const {
        ++*fragment_calls;
        return {};
    }
};

TEST(Pipeline, DepthOnlyPassWritesDepthAndShadesNothing) {
    int calls = 0;
    RenderTarget<> target(32, 32);
    const PipelineCounts counts = draw(square(0.5f), DepthOnly{&calls}, target);
    EXPECT_EQ(calls, 0);  // no colour to write: the fragment stage never runs
    EXPECT_EQ(counts.shaded, 0u);
    EXPECT_EQ(counts.stored, 32u * 32u);
    EXPECT_FLOAT_EQ(target.depth()->at(10, 20), 0.75f);  // window depth (0.5 + 1) / 2
}

// A hook that counts the checkpoints it is called at, and throws at the
// `stop_at`-th: what the Python module's Ctrl-C does.
struct Stopped {};
int g_checkpoints = 0, g_stop_at = 0;
void count_and_maybe_stop() {
    if (++g_checkpoints == g_stop_at) throw Stopped{};
}
struct CheckpointHook {
    explicit CheckpointHook(int stop_at) {
        g_checkpoints = 0;
        g_stop_at = stop_at;
        rl::set_checkpoint_hook(count_and_maybe_stop);
    }
    ~CheckpointHook() { rl::set_checkpoint_hook(nullptr); }
};

TEST(Pipeline, AHostCanStopAScreenFillingTriangleBetweenBandsOfRows) {
    const int size = 4 * triangles::kCheckpointRows;
    RenderTarget<rl::Rgba> target(size, size, {}, rl::Rgba{});
    {
        const CheckpointHook hook(0);  // counts only
        draw(covering_triangle(), Constant{{1, 2, 3, 255}}, target);
        EXPECT_EQ(g_checkpoints, 4);  // one triangle, four bands
    }
    RenderTarget<rl::Rgba> stopped(size, size, {}, rl::Rgba{});
    const CheckpointHook hook(3);  // stops before the third band
    EXPECT_THROW(draw(covering_triangle(), Constant{{1, 2, 3, 255}}, stopped), Stopped);
    // Two bands drawn, as the whole draw drew them; nothing below.
    for (int y = 0; y < size; y += 7) {
        const bool drawn = y < 2 * triangles::kCheckpointRows;
        EXPECT_EQ(stopped.colour<0>().at(5, y) == target.colour<0>().at(5, y), drawn) << y;
        EXPECT_EQ(stopped.colour<0>().at(5, y) == rl::Rgba{}, !drawn) << y;
    }
}

struct Two {
    using Varyings = rl::vec2;
    ClipVertex<rl::vec2> vertex(const ClipCorner& c) const {
        return {rl::cast<double>(c.position), {c.position.x, c.position.y}};
    }
    std::tuple<rl::Rgba, rl::vec3> fragment(const Fragment<rl::vec2>& f) const {
        return {rl::Rgba{10, 20, 30, 255}, rl::vec3{f.varyings.x, f.varyings.y, 1}};
    }
};

TEST(Pipeline, OnePassFillsTwoOutputs) {
    RenderTarget<rl::Rgba, rl::vec3> target(16, 16, {}, rl::kBackground, rl::vec3{});
    draw(square(0), Two{}, target);
    EXPECT_EQ(target.colour<0>().at(3, 12), (rl::Rgba{10, 20, 30, 255}));
    const rl::vec3 n =
        target.colour<1>().at(3, 12);  // centre (3.5, 12.5) of 16: NDC (-0.5625, 0.5625)
    EXPECT_NEAR(n.x, -0.5625f, 1e-5f);
    EXPECT_NEAR(n.y, 0.5625f, 1e-5f);
    EXPECT_EQ(n.z, 1.0f);
}

// A frame loop reuses its target: clear() puts every attachment and the
// depth back, so the second frame draws exactly what a new target would.
TEST(Pipeline, AClearedTargetDrawsLikeANewOne) {
    RenderTarget<rl::Rgba, rl::vec3> reused(16, 16, {}, rl::kBackground, rl::vec3{});
    draw(square(-0.5f), Two{}, reused);  // nearer: without a depth clear it hides the next frame
    reused.clear(rl::kBackground, rl::vec3{});
    EXPECT_EQ(reused.colour<0>().at(0, 0), rl::kBackground);
    EXPECT_EQ(reused.depth()->at(0, 0), reused.depth_state.clear);
    draw(square(0.5f), Two{}, reused);
    RenderTarget<rl::Rgba, rl::vec3> fresh(16, 16, {}, rl::kBackground, rl::vec3{});
    draw(square(0.5f), Two{}, fresh);
    EXPECT_EQ(reused.colour<1>().pixels(), fresh.colour<1>().pixels());
    EXPECT_EQ(reused.depth()->pixels(), fresh.depth()->pixels());
}

struct Bright {
    using Varyings = float;
    ClipVertex<float> vertex(const ClipCorner& c) const {
        return {rl::cast<double>(c.position), 0.0f};
    }
    rl::vec3 fragment(const Fragment<float>&) const { return {4.0f, 2.5f, 1000.0f}; }
};

TEST(Pipeline, FloatTargetKeepsValuesAboveOne) {
    RenderTarget<rl::vec3> target(8, 8, {}, rl::vec3{});
    draw(square(0), Bright{}, target);
    EXPECT_EQ(target.colour().at(4, 4), (rl::vec3{4.0f, 2.5f, 1000.0f}));
}

// Lesson 05's scene drawn with its own program, clip z negated (so window
// depth d becomes 1 - d) when reversed.
struct MaybeReversed {
    TexturedProgram program;
    bool reversed;
    using Varyings = rl::vec2;
    ClipVertex<rl::vec2> vertex(const MeshCorner& c) const {
        ClipVertex<rl::vec2> v = program.vertex(c);
        if (reversed) v.position.z = -v.position.z;
        return v;
    }
    rl::Rgba fragment(const Fragment<rl::vec2>& f) const { return program.fragment(f); }
};

ColourTarget draw_default_scene(bool reversed) {
    std::vector<std::string> warnings;
    const std::vector<TexturedModel> models = default_scene(warnings);
    const Camera camera = resolve_camera({}, scene_bounds(models), 4.0f / 3.0f);
    const rl::mat4 vp = view_projection(camera, 4.0f / 3.0f);
    const TargetOptions options = with_depth(
        reversed ? depth_state(zbuffer::DepthCompare::greater, 0.0f) : zbuffer::DepthState{});
    ColourTarget frame(160, 120, options, rl::kBackground);
    for (const TexturedModel& m : models) {
        const std::vector<float> light(m.mesh.faces.size(), 1.0f);
        const TexturedProgram program{vp * m.transform, m.texture, {}, LodMethod::pixel, light};
        draw(MeshView(m.mesh, m.transform), MaybeReversed{program, reversed}, frame);
    }
    return frame;
}

TEST(Pipeline, GreaterWithClearZeroReproducesReverseZ) {
    const ColourTarget usual = draw_default_scene(false), reversed = draw_default_scene(true);
    EXPECT_FLOAT_EQ(reversed.depth()->at(0, 119), 0.0f);  // the clear value where nothing is
    // Equal up to rounding at the few pixels where two surfaces' depths tie.
    const rl::ImageDiff d = rl::compare_images(usual.colour(), reversed.colour(), 0);
    EXPECT_LT(d.share_over, 0.001) << d.max_abs;
    EXPECT_GT(
        rl::compare_images(usual.colour(), rl::Image(160, 120, rl::kBackground), 0).share_over,
        0.1);  // (the scene is there)
}

TEST(Pipeline, BiasMovesDepthByTheStatedAmount) {
    // Depth z = 0.2 x in clip space: window depth changes by 0.1 per NDC
    // unit, 0.1 * 2 / 64 per pixel to the right, nothing upwards.
    const float slope = 0.1f * 2 / 64;
    zbuffer::DepthState bias;
    bias.constant_bias = 0.01f;
    bias.slope_bias = 3;
    RenderTarget<> plain(64, 64), biased(64, 64, with_depth(bias));
    draw(square(0, 0.2f), Constant{}, plain);
    draw(square(0, 0.2f), Constant{}, biased);
    for (const int x : {5, 31, 60})
        EXPECT_NEAR(biased.depth()->at(x, 17) - plain.depth()->at(x, 17), 0.01f + 3 * slope, 1e-6f);
}

TEST(Pipeline, DepthStateComparesAndWritesAsStated) {
    // A square at depth 0.75 over one at 0.25: `less` keeps the near one,
    // `greater` the far one, and with writes off the buffer keeps its clear.
    const auto run = [](const zbuffer::DepthState& state) {
        ColourTarget t(8, 8, with_depth(state), rl::kBackground);
        draw(square(-0.5f), Constant{{1, 0, 0, 255}}, t);  // window depth 0.25
        draw(square(0.5f), Constant{{2, 0, 0, 255}}, t);   // window depth 0.75
        return std::pair{t.colour().at(4, 4).r, t.depth()->at(4, 4)};
    };
    EXPECT_EQ(run({}).first, 1);
    EXPECT_EQ(run(depth_state(zbuffer::DepthCompare::greater, 0)).first, 2);
    EXPECT_EQ(run(depth_state(zbuffer::DepthCompare::always, 1)).first, 2);
    const auto [colour, depth] = run(depth_state(zbuffer::DepthCompare::less, 1, false));
    EXPECT_EQ(colour, 2);  // nothing written: each square passes against the clear value
    EXPECT_EQ(depth, 1.0f);
}

TEST(CoverageSeam, OneSamplePerPixelRefusesATargetOfSeveralSamples) {
    ColourTarget four(8, 8, with_samples(4), rl::kBackground);
    EXPECT_THROW(draw(covering_triangle(), Constant{{1, 2, 3, 255}}, four), std::invalid_argument);
}

// Which sample counts exist is a pattern's (lesson 11's); a target refuses
// only what it cannot store: no samples, or more columns than an int counts.
TEST(Pipeline, ASampleCountATargetCannotStoreIsRefused) {
    EXPECT_THROW(ColourTarget(4, 4, with_samples(0), rl::kBackground), std::invalid_argument);
    EXPECT_THROW(ColourTarget(4, 4, with_samples(-4), rl::kBackground), std::invalid_argument);
    EXPECT_THROW(RenderTarget<>(1 << 16, 1, with_samples(1 << 15)), std::invalid_argument);
    EXPECT_NO_THROW(ColourTarget(4, 4, with_samples(3), rl::kBackground));
    EXPECT_NO_THROW(ColourTarget(4, 4, with_samples(16), rl::kBackground));
}

TEST(Pipeline, TileByTileEqualsOneDraw) {
    std::vector<std::string> warnings;
    const std::vector<TexturedModel> models = default_scene(warnings);
    const Camera camera = resolve_camera({}, scene_bounds(models), 1.5f);
    EXPECT_TRUE(tiles_add_up(300, 200, 64, [&](ColourTarget& frame, auto tile) {
        RenderOptions options;
        options.pipeline.tile = tile;
        render(models, camera, options, frame);
    }));
    // The counts of the tiles add up to the whole frame's.
    ColourTarget whole = colour_target(300, 200), tiled = colour_target(300, 200);
    const PipelineCounts one = render(models, camera, {}, whole);
    PipelineCounts sum;
    for (const triangles::PixelRect& tile : tiles(300, 200, 64)) {
        RenderOptions options;
        options.pipeline.tile = tile;
        sum += render(models, camera, options, tiled);
    }
    EXPECT_EQ(sum.shaded, one.shaded);
    EXPECT_EQ(sum.faces, one.faces * tiles(300, 200, 64).size());
}

// A draw covering its target more than max_overdraw times over is refused
// (issue 17: one screen-filling triangle repeated 100 000 times took 119 s);
// one just under the bound is drawn.
TEST(Pipeline, ADrawCoveringTheTargetMoreThanMaxOverdrawTimesIsRefused) {
    const ClipTriangles one = covering_triangle();
    const auto layers = [&](std::size_t n) {
        ClipTriangles many;
        many.faces.assign(n, one.faces[0]);
        return many;
    };
    ColourTarget target = colour_target(16, 16);
    PipelineOptions options;
    options.max_overdraw = 10;
    EXPECT_EQ(draw(layers(10), Constant{{1, 2, 3, 255}}, target, options).visited, 10u * 16 * 16);
    EXPECT_THROW(draw(layers(11), Constant{{1, 2, 3, 255}}, target, options), OverdrawError);
    options.max_overdraw = 0;  // no bound
    EXPECT_EQ(draw(layers(2000), Constant{{1, 2, 3, 255}}, target, options).drawn, 2000u);
    EXPECT_THROW(draw(layers(1001), Constant{{1, 2, 3, 255}}, target, {}),
                 OverdrawError);  // default
}

struct Provoking {
    rl::mat4 vp;
    using Varyings = float;
    using Flat = float;
    ClipVertex<float, float> vertex(const MeshCorner& c) const {
        return {clip_position(vp, c.position()), 0.0f, static_cast<float>(c.corner + 1)};
    }
    float fragment(const Fragment<float, float>& f) const { return f.flat(); }
};

TEST(Pipeline, FlatValuesComeFromTheFacesFirstVertexEvenWhenClipped) {
    // A floor running from behind the eye to far in front: the near plane cuts it.
    rl::Mesh floor;
    floor.positions = {{-5, -1, 5}, {5, -1, 5}, {0, -1, -20}};
    floor.faces.push_back({});
    for (int k = 0; k < 3; ++k) floor.faces[0].corners[static_cast<std::size_t>(k)].position = k;
    Camera camera;
    camera.eye = {0, 0, 0};
    camera.target = {0, -0.2f, -1};
    camera.near = 0.1f;
    camera.far = 50;
    RenderTarget<float> target(40, 30, {}, 0.0f);
    const PipelineCounts counts =
        draw(MeshView(floor), Provoking{view_projection(camera, 4.0f / 3.0f)}, target);
    EXPECT_EQ(counts.clipped, 1u);
    EXPECT_GT(counts.shaded, 100u);
    for (float v : target.colour().pixels()) EXPECT_TRUE(v == 0.0f || v == 1.0f) << v;
}

TEST(Pipeline, VaryingsArithmeticCoversEveryMember) {
    struct Three {
        rl::vec3 a;
        float b;
        rl::vec2 c;
    };
    const Three x{{1, 2, 3}, 4, {5, 6}}, y{{10, 20, 30}, 40, {50, 60}}, z{{0, 0, 1}, 0, {0, 2}};
    const Three m = blend(x, 0.5f, y, 2.0f);
    EXPECT_EQ(m.a, (rl::vec3{20.5f, 41, 61.5f}));
    EXPECT_EQ(m.b, 82.0f);
    EXPECT_EQ(m.c, (rl::vec2{102.5f, 123}));
    const Three w = weighted<Three>({x, y, z}, {1, 1, 1});
    EXPECT_EQ(w.c, (rl::vec2{55, 68}));
    EXPECT_EQ(scaled(x, 2.0f).b, 8.0f);
}

}  // namespace
