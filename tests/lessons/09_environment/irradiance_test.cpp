// Lesson 09's diffuse light: the white furnace (a white surface in a white
// world reflects exactly what arrives, by every method), the texels' solid
// angles, spherical harmonics exact where they should be, and each method
// against the sky's irradiance by quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "09_environment/irradiance.hpp"
#include "09_environment/truths/irradiance_truth.hpp"

namespace {

using namespace environment;

constexpr double kPi = std::numbers::pi;

std::function<rl::vec3(rl::vec3)> sampled(const CubeMap& cube) {
    return [&cube](rl::vec3 d) { return cube.sample(d, MapFilter::seamless); };
}

const std::vector<rl::vec3> kNormals = {{0, 1, 0},           {0, -1, 0},          {1, 0, 0},
                                        {0.3f, 0.5f, -0.8f}, {-0.6f, 0.1f, 0.2f}, {1, 1, 1}};

TEST(Irradiance, TheSolidAnglesOfTheTexelsCoverTheSphere) {
    for (int size : {1, 3, 16}) {
        double face = 0;
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) face += texel_solid_angle(i, j, size);
        EXPECT_NEAR(6 * face, 4 * kPi, 1e-12) << size;
    }
    // A corner texel subtends less than a central one.
    EXPECT_LT(texel_solid_angle(0, 0, 16), texel_solid_angle(8, 8, 16));
}

// The white furnace: in an environment of radiance 1 everywhere, E = pi for
// every normal, so a white Lambert surface (albedo / pi times E) reflects
// exactly 1: no method may create or lose light.
TEST(Irradiance, TheWhiteFurnaceReflectsExactlyWhatArrives) {
    const CubeMap white = cube_map([](rl::dvec3) { return rl::dvec3{1, 1, 1}; }, 8, 1);
    const CubeMap convolved = irradiance_map(white, 4);
    for (int order : {1, 2, 3}) {
        const ShLight sh = project_sh(white, order);
        for (rl::vec3 n : kNormals)
            EXPECT_NEAR(irradiance(sh, n).x / kPi, 1.0, 1e-6) << "order " << order;
    }
    for (rl::vec3 n : kNormals) {
        // The convolution counts each source texel by its centre, so the
        // texels a normal's horizon cuts in two are all in or all out:
        // 0.07% with 8 texels a side, measured.
        EXPECT_NEAR(convolved.sample(n, MapFilter::seamless).y / kPi, 1.0, 1e-3);
        EXPECT_NEAR(irradiance_monte_carlo(sampled(white), n, 16, 7).z / kPi, 1.0, 1e-6);
    }
}

// An environment linear in direction (1 + w.x) has only bands 0 and 1: order
// 2 holds it whole, and E(n) = pi + (2 pi / 3) n.x exactly.
TEST(Irradiance, TwoBandsHoldALinearEnvironmentExactly) {
    const CubeMap linear = cube_map(
        [](rl::dvec3 d) {
            const double x = rl::normalize(d).x;
            return rl::dvec3{1 + x, 1 + x, 1 + x};
        },
        64, 2);
    const ShLight sh = project_sh(linear, 2);
    for (rl::vec3 n : kNormals) {
        const double expected = kPi + 2 * kPi / 3 * rl::normalize(n).x;
        EXPECT_NEAR(irradiance(sh, n).x, expected, 2e-3 * expected);
    }
}

// The sky (a sun 400 times its horizon): against the quadrature's E, the
// convolved map and 9 harmonics come within a few percent; Monte Carlo's
// error falls with its samples.
TEST(Irradiance, EachMethodAgainstTheSkysIrradiance) {
    const CubeMap sky = cube_map(Analytic::sky, 64, 4);
    const ShLight sh1 = project_sh(sky, 1), sh3 = project_sh(sky, 3);
    const CubeMap convolved = irradiance_map(sky, 16);
    double worst_sh1 = 0, worst_sh3 = 0, worst_map = 0;
    for (rl::vec3 n : kNormals) {
        const rl::dvec3 truth = exact_irradiance(
            [](rl::dvec3 d) { return radiance(Analytic::sky, d); }, rl::cast<double>(n), 256);
        auto relative = [&](rl::vec3 e) {
            return rl::length(rl::cast<double>(e) - truth) / rl::length(truth);
        };
        worst_sh1 = std::max(worst_sh1, relative(irradiance(sh1, n)));
        worst_sh3 = std::max(worst_sh3, relative(irradiance(sh3, n)));
        worst_map = std::max(worst_map, relative(convolved.sample(n, MapFilter::seamless)));
    }
    EXPECT_LT(worst_map, 0.05);
    EXPECT_LT(worst_sh3, 0.15);
    EXPECT_LT(worst_sh3, 0.5 * worst_sh1) << "nine harmonics must beat one";
    const rl::vec3 n{0.3f, 0.5f, -0.8f};
    const rl::dvec3 truth = exact_irradiance([](rl::dvec3 d) { return radiance(Analytic::sky, d); },
                                             rl::cast<double>(n), 256);
    auto mc_error = [&](int samples) {
        double sum = 0;
        for (std::uint32_t seed = 0; seed < 32; ++seed)
            sum += rl::length(
                rl::cast<double>(irradiance_monte_carlo(sampled(sky), n, samples, seed)) - truth);
        return sum / 32 / rl::length(truth);
    };
    EXPECT_LT(mc_error(1024), 0.5 * mc_error(16));
}

TEST(Irradiance, OrdersAndSizesOutsideTheirRangesAreRefused) {
    const CubeMap tiny = cube_map(Analytic::sky, 2, 1);
    EXPECT_THROW(project_sh(tiny, 0), std::invalid_argument);
    EXPECT_THROW(project_sh(tiny, 4), std::invalid_argument);
    EXPECT_THROW(irradiance_map(tiny, 0), std::invalid_argument);
    EXPECT_THROW(irradiance_map(tiny, 257), std::invalid_argument);
    // A zero or NaN normal reads as up, not NaN.
    const ShLight sh = project_sh(tiny, 3);
    EXPECT_EQ(irradiance(sh, {0, 0, 0}).x, irradiance(sh, {0, 1, 0}).x);
    EXPECT_FALSE(std::isnan(irradiance_monte_carlo(sampled(tiny), {NAN, 0, 0}, 4, 1).x));
}

}  // namespace
