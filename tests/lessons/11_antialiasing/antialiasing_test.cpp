// Lesson 11's tests: the sample patterns, the coverage policies (every
// sample of a shared edge stored once, the shading rate of each policy,
// centroid shading inside the triangle, a program that discards), the
// resolves (linear light, the tent), and the frame's caps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "06_shading/colour.hpp"
#include "11_antialiasing/scene.hpp"

namespace {

using namespace antialiasing;
using pipeline::ClipVertex;
using pipeline::Fragment;

// Triangles given directly in clip space (w = 1: clip space is NDC).
struct ClipCorner {
    rl::vec4 position;
    float u;  // an attribute: 1 at each face's first corner, 0 at the others
};
struct ClipTriangles {
    std::vector<std::array<rl::vec4, 3>> faces;
    int face_count() const { return static_cast<int>(faces.size()); }
    ClipCorner corner(int face, int k) const {
        return {faces[static_cast<std::size_t>(face)][static_cast<std::size_t>(k)],
                k == 0 ? 1.0f : 0.0f};
    }
};

// A square filling the screen, cut along a diagonal into two triangles
// that share that edge, and a fan of wedges around a point near the
// centre: many edges shared, at every slant.
ClipTriangles shared_edges() {
    ClipTriangles t{{{rl::vec4{-1, -1, 0, 1}, rl::vec4{1, -1, 0, 1}, rl::vec4{1, 1, 0, 1}},
                     {rl::vec4{-1, -1, 0, 1}, rl::vec4{1, 1, 0, 1}, rl::vec4{-1, 1, 0, 1}}}};
    return t;
}
ClipTriangles fan(int blades) {
    ClipTriangles t;
    const float pi = 3.14159265f;
    for (int i = 0; i < blades; ++i) {
        const float a0 = 2 * pi * static_cast<float>(i) / static_cast<float>(blades) + 0.1f,
                    a1 = 2 * pi * static_cast<float>(i + 1) / static_cast<float>(blades) + 0.1f;
        t.faces.push_back({rl::vec4{0.013f, -0.021f, 0, 1},
                           rl::vec4{2 * std::cos(a0), 2 * std::sin(a0), 0, 1},
                           rl::vec4{2 * std::cos(a1), 2 * std::sin(a1), 0, 1}});
    }
    return t;
}

// Writes a constant colour; counts its fragment stage's runs; records the
// attribute u where it runs.
struct Counted {
    using Varyings = float;
    int* runs;
    float* lowest_u;
    ClipVertex<float> vertex(const ClipCorner& c) const {
        return {rl::cast<double>(c.position), c.u};
    }
    rl::vec3 fragment(const Fragment<float>& f) const {
        ++*runs;
        *lowest_u = std::min(*lowest_u, f.varyings);
        return {1, 1, 1};
    }
};

using Target = pipeline::RenderTarget<rl::vec3>;

Target target_of(int size, int samples) {
    pipeline::TargetOptions o;
    o.samples = samples;
    o.depth.compare = zbuffer::DepthCompare::always;  // every covered sample is stored
    return Target(size, size, o, rl::vec3{0, 0, 0});
}

TEST(SamplePattern, EachLiesInThePixelWithItsOwnRowAndColumn) {
    for (Pattern p : kPatterns)
        for (int n : {1, 2, 4, 8, 16}) {
            if (!has_count(p, n)) continue;
            const std::vector<rl::vec2> offsets = sample_offsets(p, n);
            ASSERT_EQ(offsets.size(), static_cast<std::size_t>(n));
            std::set<float> xs, ys;
            for (rl::vec2 o : offsets) {
                // Direct3D's 16 puts two samples on the pixel's border (-8/16).
                EXPECT_LE(std::abs(o.x), 0.5f) << name(p) << " " << n;
                EXPECT_LE(std::abs(o.y), 0.5f) << name(p) << " " << n;
                xs.insert(o.x), ys.insert(o.y);
            }
            // The ordered grid shares its rows and columns (n x n samples on
            // sqrt(n) heights); the others give each sample its own.
            const std::size_t expected = p == Pattern::grid
                                             ? static_cast<std::size_t>(std::lround(std::sqrt(n)))
                                             : static_cast<std::size_t>(n);
            EXPECT_EQ(xs.size(), expected) << name(p) << " " << n;
            EXPECT_EQ(ys.size(), expected) << name(p) << " " << n;
        }
}

TEST(SamplePattern, CountsAPatternLacksAreRefused) {
    EXPECT_THROW(sample_offsets(Pattern::rotated, 8), std::invalid_argument);
    EXPECT_THROW(sample_offsets(Pattern::grid, 8), std::invalid_argument);
    EXPECT_THROW(sample_offsets(Pattern::standard, 3), std::invalid_argument);
    EXPECT_THROW(check(AaOptions{.method = Method::ssaa, .samples = 2, .pattern = Pattern::grid}),
                 std::invalid_argument);
    EXPECT_NO_THROW(check(AaOptions{.method = Method::none, .samples = 3}));
}

// Lesson 02's fill rule, applied per sample: along every shared edge each
// sample is stored by exactly one of the two triangles, whatever the
// pattern (no sample twice, none left out), for both policies.
TEST(Coverage, SharedEdgesStoreEachSampleOnce) {
    for (Pattern p : kPatterns)
        for (int n : {2, 4, 8, 16}) {
            if (!has_count(p, n)) continue;
            const std::vector<rl::vec2> offsets = sample_offsets(p, n);
            for (const ClipTriangles& geometry : {shared_edges(), fan(23)}) {
                int runs = 0;
                float lowest = 1;
                Target ssaa = target_of(29, n), msaa = target_of(29, n);
                const auto a = pipeline::draw(geometry, Counted{&runs, &lowest}, ssaa, {},
                                              Supersampling{offsets});
                const auto b = pipeline::draw(geometry, Counted{&runs, &lowest}, msaa, {},
                                              Multisampling{offsets});
                const std::size_t all = 29u * 29u * static_cast<std::size_t>(n);
                EXPECT_EQ(a.stored, all) << name(p) << " " << n;
                EXPECT_EQ(b.stored, all) << name(p) << " " << n;
                for (const rl::vec3& c : ssaa.colour().pixels()) ASSERT_EQ(c.x, 1.0f);
                for (const rl::vec3& c : msaa.colour().pixels()) ASSERT_EQ(c.x, 1.0f);
            }
        }
}

// Each sample is tested where its pattern puts it: an edge at x = 1.6
// pixels covers sample s of pixel 1 (centre 1.5) exactly when its offset's
// x exceeds 0.1, for every pattern and both policies (a sample tested at
// the centre, or with its offset mirrored, lands on the wrong side).
TEST(Coverage, SamplesAreTestedWhereThePatternPutsThem) {
    const float edge = 1.6f / 4 * 2 - 1;  // in NDC, on a target 4 pixels wide
    const ClipTriangles right{
        {{rl::vec4{edge, -1, 0, 1}, rl::vec4{3, -1, 0, 1}, rl::vec4{edge, 3, 0, 1}}}};
    for (Pattern p : kPatterns)
        for (int n : {2, 4, 8, 16}) {
            if (!has_count(p, n)) continue;
            const std::vector<rl::vec2> offsets = sample_offsets(p, n);
            int runs = 0;
            float lowest = 1;
            Target a = target_of(4, n), b = target_of(4, n);
            pipeline::draw(right, Counted{&runs, &lowest}, a, {}, Supersampling{offsets});
            pipeline::draw(right, Counted{&runs, &lowest}, b, {}, Multisampling{offsets});
            for (int s = 0; s < n; ++s) {
                const float expected = offsets[static_cast<std::size_t>(s)].x > 0.1f ? 1.0f : 0.0f;
                EXPECT_EQ(a.colour().get(n + s, 1).x, expected) << name(p) << " " << n << " " << s;
                EXPECT_EQ(b.colour().get(n + s, 1).x, expected) << name(p) << " " << n << " " << s;
            }
        }
}

// Multisampling tests depth per sample and writes it only where the test
// passed: a near triangle over part of the screen (its edge through a
// column of pixels), then a far one over all of it; in the pixels of the
// edge some samples pass and some do not, and those that did not keep the
// near depth.
TEST(Coverage, MultisamplingKeepsTheNearerDepth) {
    const std::vector<rl::vec2> offsets = sample_offsets(Pattern::standard, 4);
    const float edge = 3.5f / 6 * 2 - 1;  // through the centres of pixel column 3
    const ClipTriangles near_part{
        {{rl::vec4{edge, -1, -0.5f, 1}, rl::vec4{3, -1, -0.5f, 1}, rl::vec4{edge, 3, -0.5f, 1}}}};
    const ClipTriangles far_all{
        {{rl::vec4{-1, -1, 0.5f, 1}, rl::vec4{3, -1, 0.5f, 1}, rl::vec4{-1, 3, 0.5f, 1}}}};
    pipeline::TargetOptions four;
    four.samples = 4;  // the default depth state: less, written
    pipeline::RenderTarget<rl::vec3> t(6, 6, four, rl::vec3{0, 0, 0});
    int runs = 0;
    float lowest = 1;
    pipeline::draw(near_part, Counted{&runs, &lowest}, t, {}, Multisampling{offsets});
    const std::vector<float> after_near = t.depth()->pixels();
    pipeline::draw(far_all, Counted{&runs, &lowest}, t, {}, Multisampling{offsets});
    int kept = 0;
    for (std::size_t i = 0; i < after_near.size(); ++i) {
        if (after_near[i] == t.depth_state.clear) continue;
        EXPECT_EQ(t.depth()->pixels()[i], after_near[i]) << "sample " << i;
        ++kept;
    }
    EXPECT_EQ(kept, 6 * 3 * 4 - 6 * 2);  // columns 4 and 5, and 2 of each column-3 pixel's 4
}

// A fence of slivers thinner than a pixel: vertical bars 0.25 pixel wide,
// one a pixel, at a different place in each pixel. One sample a pixel sees
// a bar in some pixels and not in others (all or nothing); 16 samples on
// the ordered grid see each bar in one column of 4: a quarter of every
// pixel, as the bars cover. And a gap 0.05 pixel wide between two
// triangles: one sample misses it or not; every sample pattern keeps the
// picture within 1/n of the truth there.
ClipTriangles fence(int pixels, float width) {
    ClipTriangles t;
    for (int i = 0; i < pixels; ++i) {
        const float x0 = static_cast<float>(i) + 0.1f + 0.7f * static_cast<float>(i) / pixels;
        const float a = x0 / pixels * 2 - 1, b = (x0 + width) / pixels * 2 - 1;
        t.faces.push_back({rl::vec4{a, -1, 0, 1}, rl::vec4{b, -1, 0, 1}, rl::vec4{b, 1, 0, 1}});
        t.faces.push_back({rl::vec4{a, -1, 0, 1}, rl::vec4{b, 1, 0, 1}, rl::vec4{a, 1, 0, 1}});
    }
    return t;
}

TEST(Stability, AFenceOfSliversIsCoveredByItsShare) {
    const int size = 16;
    const ClipTriangles bars = fence(size, 0.25f);
    int runs = 0;
    float lowest = 1;
    Target one = target_of(size, 1);
    pipeline::draw(bars, Counted{&runs, &lowest}, one);
    Target sixteen = target_of(size, 16);
    const std::vector<rl::vec2> grid = sample_offsets(Pattern::grid, 16);
    pipeline::draw(bars, Counted{&runs, &lowest}, sixteen, {}, Multisampling{grid});
    const rl::Grid<rl::vec3> resolved = resolve(sixteen.colour(), grid, Resolve::box);
    int seen = 0;
    for (int x = 0; x < size; ++x) {
        seen += one.colour().get(x, 5).x == 1;
        EXPECT_NEAR(resolved.get(x, 5).x, 0.25f, 1.0f / 16) << "pixel " << x;
    }
    // One sample: the bars whose pixel centre they cross are whole, the others gone.
    EXPECT_GT(seen, 0);
    EXPECT_LT(seen, size);
}

TEST(Stability, ASubPixelGapShowsByItsShareAtMost) {
    // Two triangles covering the screen but for a gap 0.05 pixel wide at x = 5.55.
    const int size = 12;
    const float g0 = 5.55f / size * 2 - 1, g1 = 5.60f / size * 2 - 1;
    const ClipTriangles two{
        {{rl::vec4{-1, -1, 0, 1}, rl::vec4{g0, -1, 0, 1}, rl::vec4{g0, 3, 0, 1}},
         {rl::vec4{g1, -1, 0, 1}, rl::vec4{3, -1, 0, 1}, rl::vec4{g1, 3, 0, 1}},
         {rl::vec4{-1, -1, 0, 1}, rl::vec4{g0, 3, 0, 1}, rl::vec4{-1, 3, 0, 1}}}};
    for (int n : {4, 8, 16}) {
        const std::vector<rl::vec2> offsets = sample_offsets(Pattern::standard, n);
        Target t = target_of(size, n);
        int runs = 0;
        float lowest = 1;
        pipeline::draw(two, Counted{&runs, &lowest}, t, {}, Multisampling{offsets});
        const rl::Grid<rl::vec3> light = resolve(t.colour(), offsets, Resolve::box);
        for (int x = 0; x < size; ++x)
            EXPECT_GE(light.get(x, 3).x, x == 5 ? 1.0f - 1.0f / static_cast<float>(n) : 1.0f)
                << n << " samples, pixel " << x;
    }
}

// Supersampling runs the fragment stage once a sample, multisampling once
// a pixel a triangle reaches: on one triangle covering the screen, 16 times
// fewer runs at 16 samples.
TEST(Coverage, EachPolicyShadesAtItsRate) {
    const std::vector<rl::vec2> offsets = sample_offsets(Pattern::standard, 16);
    const ClipTriangles covering{
        {{rl::vec4{-1, -1, 0, 1}, rl::vec4{3, -1, 0, 1}, rl::vec4{-1, 3, 0, 1}}}};
    int ssaa_runs = 0, msaa_runs = 0;
    float lowest = 1;
    Target a = target_of(20, 16), b = target_of(20, 16);
    pipeline::draw(covering, Counted{&ssaa_runs, &lowest}, a, {}, Supersampling{offsets});
    pipeline::draw(covering, Counted{&msaa_runs, &lowest}, b, {}, Multisampling{offsets});
    EXPECT_EQ(ssaa_runs, 20 * 20 * 16);
    EXPECT_EQ(msaa_runs, 20 * 20);
    // A policy refuses a target of another sample count.
    Target four = target_of(8, 4);
    EXPECT_THROW(
        pipeline::draw(covering, Counted{&msaa_runs, &lowest}, four, {}, Multisampling{offsets}),
        std::invalid_argument);
}

// Lesson 05's seam from the other side: a triangle covering every sample,
// multisampled with the fragment stage at each pixel's centre, resolves to
// the one-sample image (to float rounding: the centre's weights come from
// the float barycentric, the one-sample draw's from the edge functions).
struct Gradient {
    using Varyings = float;
    ClipVertex<float> vertex(const ClipCorner& c) const {
        return {rl::cast<double>(c.position), c.position.x * 0.37f + c.position.y * 0.21f};
    }
    rl::vec3 fragment(const Fragment<float>& f) const {
        return {f.varyings, 1 - f.varyings, 0.25f};
    }
};

TEST(Coverage, AllSamplesCoveredResolveToTheOneSampleImage) {
    const ClipTriangles covering{
        {{rl::vec4{-1, -1, 0, 1}, rl::vec4{3, -1, 0, 1}, rl::vec4{-1, 3, 0, 1}}}};
    Target one = target_of(23, 1);
    pipeline::draw(covering, Gradient{}, one);
    for (int n : {2, 4, 8, 16}) {
        const std::vector<rl::vec2> offsets = sample_offsets(Pattern::standard, n);
        Target many = target_of(23, n);
        const auto counts =
            pipeline::draw(covering, Gradient{}, many, {}, Multisampling{offsets, ShadeAt::centre});
        EXPECT_EQ(counts.stored, 23u * 23u * static_cast<std::size_t>(n));
        const rl::Grid<rl::vec3> resolved = resolve(many.colour(), offsets, Resolve::box);
        for (int y = 0; y < 23; ++y)
            for (int x = 0; x < 23; ++x) {
                EXPECT_NEAR(resolved.get(x, y).x, one.colour().get(x, y).x, 1e-6f) << n;
                EXPECT_NEAR(resolved.get(x, y).y, one.colour().get(x, y).y, 1e-6f) << n;
            }
    }
}

// Supersampling shades every sample where it lies: a constant colour over a
// triangle covering every sample resolves to the one-sample image exactly,
// after n fragment runs a pixel.
TEST(Coverage, SupersamplingAFlatColourResolvesToTheOneSampleImage) {
    const ClipTriangles covering{
        {{rl::vec4{-1, -1, 0, 1}, rl::vec4{3, -1, 0, 1}, rl::vec4{-1, 3, 0, 1}}}};
    int runs = 0;
    float lowest = 1;
    Target one = target_of(23, 1);
    pipeline::draw(covering, Counted{&runs, &lowest}, one);
    for (int n : {2, 4, 8, 16}) {
        const std::vector<rl::vec2> offsets = sample_offsets(Pattern::standard, n);
        Target many = target_of(23, n);
        runs = 0;
        pipeline::draw(covering, Counted{&runs, &lowest}, many, {}, Supersampling{offsets});
        EXPECT_EQ(runs, 23 * 23 * n);
        EXPECT_EQ(resolve(many.colour(), offsets, Resolve::box), one.colour()) << n;
    }
}

// At a pixel the triangle covers only in part, its centre can lie outside:
// shading there extrapolates the varyings (u below 0 here, where u is 0 on
// the far edge); shading at the centroid of the covered samples stays in.
TEST(Coverage, CentroidShadingStaysInsideTheTriangle) {
    const std::vector<rl::vec2> offsets = sample_offsets(Pattern::standard, 8);
    // About 5 pixels wide: u falls by a fifth a pixel towards the edge x = -0.6.
    const ClipTriangles thin{{{rl::vec4{-0.9f, -0.9f, 0, 1}, rl::vec4{-0.6f, -0.9f, 0, 1},
                               rl::vec4{-0.6f, -0.55f, 0, 1}}}};
    float centre_lowest = 1, centroid_lowest = 1;
    int runs = 0;
    Target a = target_of(31, 8), b = target_of(31, 8);
    pipeline::draw(thin, Counted{&runs, &centre_lowest}, a, {},
                   Multisampling{offsets, ShadeAt::centre});
    pipeline::draw(thin, Counted{&runs, &centroid_lowest}, b, {},
                   Multisampling{offsets, ShadeAt::centroid});
    EXPECT_LT(centre_lowest, -0.01f);
    EXPECT_GE(centroid_lowest, -1e-6f);
}

// A program that discards under multisampling discards the pixel's whole
// share of the triangle: nothing stored, no depth written.
struct Discarding {
    using Varyings = float;
    static constexpr bool may_discard = true;
    ClipVertex<float> vertex(const ClipCorner& c) const {
        return {rl::cast<double>(c.position), c.u};
    }
    std::optional<rl::vec3> fragment(const Fragment<float>& f) const {
        if (f.x % 2 == 0) return std::nullopt;
        return rl::vec3{1, 1, 1};
    }
};

TEST(Coverage, MultisamplingWithADiscardingProgramStoresNothingThere) {
    const std::vector<rl::vec2> offsets = sample_offsets(Pattern::standard, 4);
    pipeline::TargetOptions four;
    four.samples = 4;
    pipeline::RenderTarget<rl::vec3> t(8, 8, four, rl::vec3{0, 0, 0});
    pipeline::draw(shared_edges(), Discarding{}, t, {}, Multisampling{offsets});
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int s = 0; s < 4; ++s) {
                EXPECT_EQ(t.colour().get(4 * x + s, y).x, x % 2 == 0 ? 0.0f : 1.0f);
                EXPECT_EQ(t.depth()->get(4 * x + s, y) == t.depth_state.clear, x % 2 == 0);
            }
}

// The resolve in linear light: a pixel half covered by white over black is
// half the light, which sRGB encodes as 188; averaging the encoded bytes
// (255 and 0) would give 128, far darker: every edge would look too thin.
TEST(Resolve, AHalfCoveredPixelIsHalfTheLight) {
    const std::vector<rl::vec2> offsets = sample_offsets(Pattern::grid, 4);
    Target t = target_of(4, 4);
    int runs = 0;
    float lowest = 1;
    // A vertical edge through pixel 1's centre (x = 1.5 pixels of 4), so
    // that 2 of its 4 grid samples are covered.
    const float x = (1.5f / 4) * 2 - 1;
    const ClipTriangles right{
        {{rl::vec4{x, -1, 0, 1}, rl::vec4{3, -1, 0, 1}, rl::vec4{x, 3, 0, 1}}}};
    pipeline::draw(right, Counted{&runs, &lowest}, t, {}, Supersampling{offsets});
    const rl::Grid<rl::vec3> light = resolve(t.colour(), offsets, Resolve::box);
    EXPECT_FLOAT_EQ(light.get(1, 0).x, 0.5f);
    EXPECT_EQ(encoded(light).at(1, 0).r, 188);
    // The pitfall, as --resolve-encoded shows it: the bytes' mean, 127.5.
    AaOptions pitfall;
    pitfall.resolve_encoded = true;
    EXPECT_NEAR(encoded(shown_light(t.colour(), offsets, pitfall)).at(1, 0).r, 127.5, 0.5);
    EXPECT_EQ(light.get(0, 0).x, 0.0f);
    EXPECT_EQ(light.get(2, 0).x, 1.0f);
}

// The tone map's order at a bright edge: a pixel half covered by light 16
// times white (after the exposure) over black. Tone-mapped after the
// resolve it is ACES(8), nearly white (0.97); tone-mapped per sample before
// it, (ACES(16) + ACES(0)) / 2, about half (0.50): the bright side wins the
// pixel only in the first.
TEST(Resolve, TheToneMapsOrderDecidesABrightEdge) {
    const std::vector<rl::vec2> offsets = sample_offsets(Pattern::grid, 4);
    rl::Grid<rl::vec3> samples(4, 1, rl::vec3{0, 0, 0});
    samples.at(0, 0) = samples.at(1, 0) = {16, 16, 16};
    AaOptions after, before;
    after.tone = ToneOrder::after_resolve, before.tone = ToneOrder::before_resolve;
    const float a = shown_light(samples, offsets, after).get(0, 0).x,
                b = shown_light(samples, offsets, before).get(0, 0).x;
    environment::Exposure aces;
    EXPECT_FLOAT_EQ(a, environment::tone_map(8.0f, aces));
    EXPECT_FLOAT_EQ(b, environment::tone_map(16.0f, aces) / 2);
    EXPECT_GT(a, 0.95f);
    EXPECT_NEAR(b, 0.5f, 0.01f);
}

// The tent keeps a flat picture flat and spreads an edge over one more
// pixel on each side than the box.
TEST(Resolve, TheTentKeepsFlatLightAndWidensAnEdge) {
    const std::vector<rl::vec2> offsets = sample_offsets(Pattern::standard, 8);
    rl::Grid<rl::vec3> flat(5 * 8, 3, rl::vec3{0.25f, 0.5f, 2});
    const rl::Grid<rl::vec3> a = resolve(flat, offsets, Resolve::tent);
    for (const rl::vec3& c : a.pixels()) {
        EXPECT_FLOAT_EQ(c.x, 0.25f);
        EXPECT_FLOAT_EQ(c.y, 0.5f);
        EXPECT_FLOAT_EQ(c.z, 2);
    }
    rl::Grid<rl::vec3> step(5 * 8, 1, rl::vec3{0, 0, 0});
    for (int x = 3 * 8; x < 5 * 8; ++x) step.at(x, 0) = {1, 1, 1};  // pixels 3 and 4 white
    const rl::Grid<rl::vec3> box = resolve(step, offsets, Resolve::box),
                             tent = resolve(step, offsets, Resolve::tent);
    EXPECT_EQ(box.get(2, 0).x, 0.0f);
    EXPECT_GT(tent.get(2, 0).x, 0.05f);
    EXPECT_LT(tent.get(3, 0).x, 1.0f);
}

// The edge filter on a picture of one sample a pixel: a half plane of white
// over black whose edge rises 1 pixel in 8, drawn by pixel centres (steps).
// The filter leaves flat regions as they are and brings the edge's pixels
// nearer their true coverage; a line one pixel wide, which is not an edge
// but a detail, is smeared: its brightest pixels lose light.
rl::Grid<rl::vec3> slanted_edge(int size, bool coverage) {
    rl::Grid<rl::vec3> out(size, size, rl::vec3{0, 0, 0});
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double edge = 10.3 + (x + 0.5) / 8;  // white above it
            const double share =
                coverage ? std::clamp(y + 1 - edge, 0.0, 1.0) : (y + 0.5 > edge ? 1.0 : 0.0);
            // The share of the pixel's height above the edge at its centre
            // column: its exact coverage while the edge crosses it straight
            // (the edge is linear across the pixel's width).
            const float v = static_cast<float>(share);
            out.at(x, y) = {v, v, v};
        }
    return out;
}

TEST(EdgeFilter, FlatLightStaysAndAnEdgeNearsItsCoverage) {
    const rl::Grid<rl::vec3> flat(16, 16, rl::vec3{0.3f, 0.3f, 0.3f});
    EXPECT_EQ(edge_filter(flat).pixels(), flat.pixels());
    const rl::Grid<rl::vec3> stepped = slanted_edge(48, false), exact = slanted_edge(48, true);
    const rl::Grid<rl::vec3> filtered = edge_filter(stepped);
    double before = 0, after = 0;
    for (int y = 4; y < 44; ++y)
        for (int x = 4; x < 44; ++x) {
            const auto srgb = [](float v) { return shading::linear_to_srgb(v); };
            before += std::abs(srgb(stepped.get(x, y).x) - srgb(exact.get(x, y).x));
            after += std::abs(srgb(filtered.get(x, y).x) - srgb(exact.get(x, y).x));
        }
    EXPECT_LT(after, 0.6 * before) << before << " -> " << after;
}

TEST(EdgeFilter, SmearsALineOnePixelWide) {
    rl::Grid<rl::vec3> line(16, 16, rl::vec3{0, 0, 0});
    for (int x = 0; x < 16; ++x) line.at(x, 8) = {1, 1, 1};
    const rl::Grid<rl::vec3> filtered = edge_filter(line);
    EXPECT_LT(filtered.get(8, 8).x, 0.9f);                         // the line loses light
    EXPECT_GT(filtered.get(8, 7).x + filtered.get(8, 9).x, 0.1f);  // to its neighbours
}

TEST(Frame, SamplesPastTheCapAreRefused) {
    EXPECT_NO_THROW(check_frame_size(4096, 4096, 4));
    EXPECT_THROW(check_frame_size(4096, 4096, 8), std::invalid_argument);
    EXPECT_THROW(check_frame_size(2049, 2048, 16), std::invalid_argument);
}

}  // namespace
