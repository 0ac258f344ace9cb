// Lesson 09's glossy light: GGX's facets cover the surface once; the split
// sum's importance sampling agrees with the BRDF integrated directly; one
// bounce never creates light; the white furnace holds for every roughness
// once the lost bounces are put back (and does not without them); the
// blurred maps; the grazing, mirror and fully rough ends; a sun 10^5 times
// the sky.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "09_environment/brdf.hpp"
#include "09_environment/glossy_map.hpp"
#include "09_environment/scene.hpp"
#include "09_environment/sphere_sampling.hpp"

namespace {

using namespace environment;

constexpr double kPi = std::numbers::pi;

Environment constant(rl::dvec3 value, int size = 8) {
    return Environment(cube_map([value](rl::dvec3) { return value; }, size, 1),
                       MapFilter::seamless);
}

// D times n.h integrates to 1 over the hemisphere: the facets' projected
// area is the surface's, for every roughness.
TEST(Brdf, GgxFacetsCoverTheSurfaceOnce) {
    for (double alpha : {0.05, 0.2, 0.5, 1.0}) {
        // dw = 2 pi d(cos theta) about the normal; midpoints in cos theta.
        const int steps = 400000;
        double sum = 0;
        for (int i = 0; i < steps; ++i) {
            const double mu = (i + 0.5) / steps;
            sum += ggx_distribution(mu, alpha) * mu;
        }
        EXPECT_NEAR(sum * 2 * kPi / steps, 1.0, 1e-4) << "alpha " << alpha;
    }
}

// The split sum's importance-sampled integral equals the BRDF (D, G and F
// evaluated as written) times n.l summed over a fine grid of directions:
// f0 = 0 leaves the bias, f0 = 1 the whole albedo.
TEST(Brdf, TheSplitSumIsTheBrdfsIntegral) {
    for (const auto& [n_dot_v, roughness] :
         std::vector<std::pair<double, double>>{{1.0, 0.5}, {0.5, 0.4}, {0.2, 0.7}, {0.8, 1.0}}) {
        const rl::dvec3 n{0, 0, 1}, v{std::sqrt(1 - n_dot_v * n_dot_v), 0, n_dot_v};
        const double alpha = ggx_alpha(roughness);
        const int rings = 1500, spokes = 1500;
        double albedo = 0, bias = 0;
        for (int i = 0; i < rings; ++i) {
            const double mu = (i + 0.5) / rings, s = std::sqrt(1 - mu * mu);
            for (int j = 0; j < spokes; ++j) {
                const double phi = 2 * kPi * (j + 0.5) / spokes;
                const rl::dvec3 l{s * std::cos(phi), s * std::sin(phi), mu};
                albedo += cook_torrance(n, v, l, alpha, {1, 1, 1}).x * mu;
                bias += cook_torrance(n, v, l, alpha, {0, 0, 0}).x * mu;
            }
        }
        const double cell = 2 * kPi / (rings * spokes);
        const SplitSum sampled = split_sum(n_dot_v, roughness, 4096);
        EXPECT_NEAR(sampled.albedo(), albedo * cell, 2e-3) << n_dot_v << ", " << roughness;
        EXPECT_NEAR(sampled.bias, bias * cell, 1e-3) << n_dot_v << ", " << roughness;
    }
}

// One bounce returns at most what arrives: all of it for a mirror, less
// the rougher the surface and the more grazing the view (the light that
// hits a second facet is not counted).
TEST(Brdf, OneBounceNeverCreatesLight) {
    for (int r = 0; r <= 10; ++r)
        for (double n_dot_v : {1e-3, 0.05, 0.3, 0.7, 1.0}) {
            const SplitSum s = split_sum(n_dot_v, r / 10.0, 4096);
            EXPECT_LE(s.albedo(), 1 + 1e-4) << r << ", " << n_dot_v;
            EXPECT_GE(s.scale, 0);
            EXPECT_GE(s.bias, 0);
        }
    EXPECT_NEAR(split_sum(0.5, 0, 64).albedo(), 1.0, 1e-12);
    // Roughness 1 seen head-on has a closed form: D = 1 / pi everywhere and
    // G = 2 n.l / (1 + n.l), so the albedo is the integral of G / (4 pi)
    // over the hemisphere, 1 - ln 2 = 0.307: two thirds of the light lost.
    EXPECT_NEAR(split_sum(1.0, 1.0, 4096).albedo(), 1 - std::log(2.0), 1e-3);
    EXPECT_GT(split_sum(1.0, 0.25, 4096).albedo(), 0.95);
}

// The table is the integral, read between its entries.
TEST(Brdf, TheTableReadsTheIntegral) {
    const SplitSumTable& table = split_sum_table();
    for (const auto& [n_dot_v, roughness] : std::vector<std::pair<float, float>>{
             {1, 0}, {0.37f, 0.61f}, {0.9f, 0.22f}, {0.1f, 0.9f}}) {
        const SplitSum exact = split_sum(n_dot_v, roughness, 4096),
                       read = table.at(n_dot_v, roughness);
        EXPECT_NEAR(read.scale, exact.scale, 1e-2) << n_dot_v << ", " << roughness;
        EXPECT_NEAR(read.bias, exact.bias, 1e-2) << n_dot_v << ", " << roughness;
    }
    // Broken inputs read an entry, never memory outside the table.
    for (float bad : {std::nanf(""), -1.0f, 7.0f, INFINITY}) {
        const SplitSum s = table.at(bad, bad);
        EXPECT_TRUE(std::isfinite(s.scale) && std::isfinite(s.bias));
    }
}

// The white furnace: a white rough metal (f0 = 1) in a world of radiance 1
// must return exactly 1 at every roughness and angle. The split sum's one
// bounce alone falls short; with the lost bounces put back it is exact.
TEST(Brdf, TheWhiteFurnaceHoldsForEveryRoughness) {
    const SplitSumTable& table = split_sum_table();
    for (int r = 0; r <= 20; ++r)
        for (float n_dot_v : {0.0f, 0.02f, 0.2f, 0.5f, 1.0f}) {
            const SplitSum ab = table.at(n_dot_v, r / 20.0f);
            const SpecularShares kept = specular_shares({1, 1, 1}, ab);
            EXPECT_NEAR(kept.single.x + kept.multiple.x, 1.0, 1e-5) << r << ", " << n_dot_v;
            // A plastic reflects less than 1 and passes the rest to its diffuse layer.
            const SpecularShares plastic = specular_shares({0.04f, 0.04f, 0.04f}, ab);
            EXPECT_LE(plastic.single.y + plastic.multiple.y, 1.0f);
            EXPECT_GE(plastic.multiple.y, 0.0f);
        }
    const SpecularShares lost = specular_shares({1, 1, 1}, table.at(1, 1), false);
    EXPECT_LT(lost.single.x + lost.multiple.x, 0.6f);
}

// The same through the whole render: every pixel of a white rough metal in
// the white world is 1 (both methods), and darker without the lost bounces.
TEST(Brdf, TheWhiteFurnaceRenderVanishes) {
    std::vector<std::string> warnings;
    const auto scene =
        load_scene(pipeline::ViewOptions{}, normal_mapping::TangentMethod::split, 64, 48, warnings);
    const Environment white = constant({1, 1, 1});
    for (float roughness : {0.0f, 0.3f, 0.7f, 1.0f})
        for (Glossy method : kGlossies)
            for (bool multiple : {true, false}) {
                RenderOptions options;
                options.material = Material::rough_metal;
                options.metal = {1, 1, 1};
                options.roughness = roughness;
                options.glossy = method;
                options.multiple_scattering = multiple;
                options.samples = 16;
                options.prefilter = {.levels = 3, .size = 16, .samples = 16};
                options.skybox = false;
                LightTarget frame = light_target(64, 48);
                render(scene.models, scene.camera, white, options, frame);
                double lowest = 2, highest = 0, sum = 0;
                int drawn = 0;
                for (int y = 0; y < 48; ++y)
                    for (int x = 0; x < 64; ++x) {
                        if (frame.depth()->get(x, y) == frame.depth_state.clear) continue;
                        const float value = frame.colour().get(x, y).y;
                        lowest = std::min<double>(lowest, value);
                        highest = std::max<double>(highest, value);
                        sum += value;
                        ++drawn;
                    }
                const std::string what = std::string(name(method)) + " roughness " +
                                         std::to_string(roughness) + (multiple ? "" : " single");
                ASSERT_GT(drawn, 300);
                if (method == Glossy::monte_carlo) {
                    // One bounce by Monte Carlo is the albedo on average only.
                    if (multiple || roughness == 0) {
                        EXPECT_NEAR(sum / drawn, 1.0, 0.02) << what;
                    } else if (roughness == 1.0f) {
                        EXPECT_LT(sum / drawn, 0.8) << what;
                    }
                    continue;
                }
                EXPECT_LE(highest, 1 + 2e-3) << what;
                if (multiple || roughness == 0) {
                    EXPECT_GE(lowest, 1 - 2e-3) << what;
                } else if (roughness == 1.0f) {
                    EXPECT_LT(lowest, 0.75) << what;
                }
            }
}

// Roughness 0 reads the environment itself; a constant environment stays
// constant when blurred; the roughest level is smooth.
TEST(GlossyMap, TheMirrorEndAndAConstantWorld) {
    const Environment sky(cube_map(Analytic::sky, 32, 2), MapFilter::seamless);
    const GlossyMap glossy(sky, {.levels = 5, .size = 32, .samples = 32});
    EXPECT_EQ(glossy.levels(), 5);
    for (rl::vec3 d : {rl::vec3{0.3f, 0.4f, -0.2f}, rl::vec3{0, 1, 0}, rl::vec3{1, 1, 1}}) {
        const rl::vec3 a = glossy.sample(d, 0), b = sky.sample(d);
        EXPECT_EQ(a.x, b.x);
        EXPECT_EQ(a.z, b.z);
    }
    const Environment grey = constant({0.5, 0.5, 0.5});
    const GlossyMap blurred(grey, {.levels = 3, .size = 16, .samples = 8});
    for (float roughness : {0.1f, 0.5f, 0.8f, 1.0f})
        EXPECT_NEAR(blurred.sample({0.2f, -0.9f, 0.1f}, roughness).y, 0.5, 1e-5);
}

// Filtered importance sampling: 64 samples (more for the rough lobes, as a
// GlossyMap gives them) reading blurred mip levels give the GGX-weighted mean of the sky that
// 2^18 samples of the analytic sky itself give, within 5%, sun included.
TEST(GlossyMap, FewBlurredSamplesMatchManySharpOnes) {
    const Environment sky(cube_map(Analytic::sky, 128, 2), MapFilter::seamless);
    const Sky truth = default_sky();
    for (double roughness : {0.2, 0.6, 1.0})
        for (rl::dvec3 r : {truth.sun_direction, rl::normalize(rl::dvec3{-0.5, 0.3, 0.4})}) {
            const Frame frame(r);
            const double alpha = ggx_alpha(roughness);
            rl::dvec3 sum{0, 0, 0};
            double weight = 0;
            const std::uint32_t count = 1u << 18;
            for (std::uint32_t i = 0; i < count; ++i) {
                const rl::dvec3 h = ggx_half_vector(hammersley(i, count), alpha);
                const rl::dvec3 l{2 * h.z * h.x, 2 * h.z * h.y, 2 * h.z * h.z - 1};
                if (l.z <= 0) continue;
                sum += radiance(truth, frame.to_world(l)) * l.z;
                weight += l.z;
            }
            const double exact = (sum / weight).y;
            // The sample counts a GlossyMap of 6 levels gives these roughnesses
            // (faces of 128, 32 and 8 texels).
            const int samples = roughness < 0.5 ? 64 : roughness < 0.9 ? 1024 : 16384;
            const double fast = prefiltered_radiance(sky, r, ggx_lobe(sky, roughness, samples)).y;
            EXPECT_NEAR(fast / exact, 1.0, 0.05) << roughness;
        }
}

// Broken directions and roughnesses read something finite: a NaN or zero
// direction, a NaN roughness, a NaN normal for Monte Carlo.
TEST(GlossyMap, BrokenDirectionsReadSomethingFinite) {
    const Environment sky(cube_map(Analytic::sky, 16, 1), MapFilter::seamless);
    const GlossyMap glossy(sky, {.levels = 3, .size = 8, .samples = 4});
    const float nan = std::nanf("");
    for (rl::vec3 d : {rl::vec3{nan, 0, 1}, rl::vec3{0, 0, 0}, rl::vec3{1, 0, 0}})
        for (float roughness : {nan, -1.0f, 0.0f, 0.5f, 1.0f, 2.0f}) {
            const rl::vec3 c = glossy.sample(d, roughness);
            EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
        }
    for (rl::vec3 n : {rl::vec3{nan, nan, nan}, rl::vec3{0, 1, 0}}) {
        const rl::vec3 c = glossy_monte_carlo(sky, n, {0, 0, 1}, 0.5f, kGoldF0, 16, 3);
        EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
    }
}

TEST(GlossyMap, OptionsOutsideTheirRangeAreRefused) {
    const Environment grey = constant({0.5, 0.5, 0.5});
    EXPECT_THROW(GlossyMap(grey, {.levels = 1}), std::invalid_argument);
    EXPECT_THROW(GlossyMap(grey, {.levels = kMaxGlossyLevels + 1}), std::invalid_argument);
    EXPECT_THROW(GlossyMap(grey, {.size = 4}), std::invalid_argument);
    EXPECT_THROW(GlossyMap(grey, {.samples = 0}), std::invalid_argument);
    // Each option within its range, together far over the work cap: refused
    // before any of it is built.
    EXPECT_THROW(GlossyMap(grey, {.levels = kMaxGlossyLevels,
                                  .size = kMaxGlossySize,
                                  .samples = kMaxGlossySamples}),
                 std::invalid_argument);
    RenderOptions options;
    options.roughness = std::nanf("");
    EXPECT_THROW(PreparedLight(grey, options, 2), std::invalid_argument);
    options.roughness = 1.5f;
    EXPECT_THROW(PreparedLight(grey, options, 2), std::invalid_argument);
}

// A sun 10^5 times the sky's horizon: the blurred maps and every pixel stay
// finite, and the rough metal turned to it is brighter than one turned away.
TEST(GlossyMap, ASunTenToTheFiveTimesTheSkyStaysFinite) {
    Sky blazing = default_sky();
    blazing.sun = {1e5, 1e5, 1e5};
    const Environment sky(cube_map([&](rl::dvec3 d) { return radiance(blazing, d); }, 64, 2),
                          MapFilter::seamless);
    const GlossyMap glossy(sky, {.levels = 4, .size = 32, .samples = 16});
    for (float roughness : {0.0f, 0.2f, 0.5f, 1.0f}) {
        const rl::vec3 towards = glossy.sample(rl::cast<float>(blazing.sun_direction), roughness);
        const rl::vec3 away = glossy.sample(rl::cast<float>(-blazing.sun_direction), roughness);
        EXPECT_TRUE(std::isfinite(towards.x) && std::isfinite(away.x)) << roughness;
        EXPECT_GT(towards.x, away.x) << roughness;
    }
    std::vector<std::string> warnings;
    const auto scene =
        load_scene(pipeline::ViewOptions{}, normal_mapping::TangentMethod::split, 48, 36, warnings);
    for (Glossy method : kGlossies) {
        RenderOptions options;
        options.material = Material::plastic;
        options.glossy = method;
        options.samples = 8;
        options.prefilter = {.levels = 3, .size = 16, .samples = 8};
        LightTarget frame = light_target(48, 36);
        render(scene.models, scene.camera, sky, options, frame);
        for (int y = 0; y < 36; ++y)
            for (int x = 0; x < 48; ++x) {
                const rl::vec3 c = frame.colour().get(x, y);
                ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z))
                    << name(method) << " " << x << ", " << y;
            }
    }
}

}  // namespace

namespace {

// Seen at a slant, a rough lobe leans towards the normal: the split sum
// read along the lean is closer to Monte Carlo's one bounce than read along
// the mirror direction, over a whole frame.
TEST(GlossyShader, ReadingAlongTheLeanIsCloserToTheReference) {
    using namespace environment;
    std::vector<std::string> warnings;
    const auto scene =
        load_scene(pipeline::ViewOptions{}, normal_mapping::TangentMethod::split, 64, 48, warnings);
    // No sun: Monte Carlo's reference converges (a 2-degree sun 400 times
    // the sky leaves any few thousand rays speckled).
    Sky sunless = default_sky();
    sunless.sun = sunless.corona = {0, 0, 0};
    const Environment sky(cube_map([&](rl::dvec3 d) { return radiance(sunless, d); }, 64, 2),
                          MapFilter::seamless);
    const auto frame_of = [&](Glossy method, Lookup lookup) {
        RenderOptions options;
        options.material = Material::rough_metal;
        options.roughness = 0.7f;
        options.glossy = method;
        options.lookup = lookup;
        options.samples = 2048;
        options.skybox = false;
        LightTarget frame = light_target(64, 48);
        render(scene.models, scene.camera, sky, options, frame);
        return frame;
    };
    const LightTarget reference = frame_of(Glossy::monte_carlo, Lookup::dominant);
    const auto error = [&](const LightTarget& frame) {
        double sum = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x)
                sum += rl::length(frame.colour().get(x, y) - reference.colour().get(x, y));
        return sum;
    };
    const double leaning = error(frame_of(Glossy::split_sum, Lookup::dominant));
    const double mirrored = error(frame_of(Glossy::split_sum, Lookup::mirror));
    std::printf("along the lean %.1f, along the mirror direction %.1f\n", leaning, mirrored);
    EXPECT_LT(leaning, 0.8 * mirrored);
}

}  // namespace

namespace {

// docs/09_environment.md's worked example: rough gold (roughness 1) seen
// head-on. One bounce returns 1 - ln 2 of a white world; the red channel
// (f0 = 1) gets the lost 0.693 back whole, 2.26 times its one bounce; the
// blue one (f0 = 0.29, f_avg = 0.324) only 0.29 times its one bounce.
TEST(Brdf, TheWorkedExample) {
    using namespace environment;
    const SplitSum one = split_sum(1.0, 1.0, 4096);
    const double e = 1 - std::log(2.0);
    EXPECT_NEAR(one.albedo(), e, 1e-3);
    const SpecularShares gold = specular_shares(kGoldF0, one);
    EXPECT_NEAR(gold.single.x + gold.multiple.x, 1.0, 1e-5);
    EXPECT_NEAR(gold.multiple.x / gold.single.x, (1 - e) / e, 0.01);
    const double f_avg = 0.29 + 0.71 / 21;
    EXPECT_NEAR(f_avg, 0.324, 5e-4);
    EXPECT_NEAR(gold.multiple.z / gold.single.z, f_avg * (1 - e) / (1 - (1 - e) * f_avg), 1e-3);
    EXPECT_NEAR(gold.multiple.z / gold.single.z, 0.29, 0.005);
}

}  // namespace
