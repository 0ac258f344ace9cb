// Lesson 04's stability cases: coordinates far outside [0, 1], negative and
// NaN coordinates, tiny and odd-sized textures, and the mip chain.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "04_textures/lab/footprint.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/image_metrics.hpp"
#include "rasterlab/mesh.hpp"

namespace {

using namespace textures;

// A texture whose texel (i, j) has red = i and green = j, so a sample tells
// which texel it came from.
rl::Image coordinates_texture(int w, int h) {
    rl::Image image(w, h);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            image.set(i, j, {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(j), 0, 255});
    return image;
}

// Any encoding: float texels refuse one.
const TexelEncoding& shading_like_encoding() {
    static const TexelEncoding identity = [] {
        TexelEncoding e{};
        for (int i = 0; i < 256; ++i) e.value[static_cast<std::size_t>(i)] = i / 255.0f;
        e.to_byte = [](float v) { return static_cast<std::uint8_t>(v * 255); };
        return e;
    }();
    return identity;
}

std::pair<int, int> texel_hit(const MipChain& chain, rl::vec2 uv, Wrap wrap) {
    SamplerState state;
    state.filter = Filter::nearest;
    state.wrap = wrap;
    const rl::Rgba c = to_rgba(sample(chain, uv, {}, state));
    return {c.r, c.g};
}

TEST(Wrap, EveryModeMapsTexelIndicesAsDefined) {
    EXPECT_EQ(wrap_texel(-1, 4, Wrap::repeat), 3);
    EXPECT_EQ(wrap_texel(9, 4, Wrap::repeat), 1);
    EXPECT_EQ(wrap_texel(-1, 4, Wrap::mirror), 0);
    EXPECT_EQ(wrap_texel(4, 4, Wrap::mirror), 3);
    EXPECT_EQ(wrap_texel(8, 4, Wrap::mirror), 0);
    EXPECT_EQ(wrap_texel(-5, 4, Wrap::clamp), 0);
    EXPECT_EQ(wrap_texel(7, 4, Wrap::clamp), 3);
    EXPECT_EQ(wrap_texel(-1, 4, Wrap::border), -1);
    EXPECT_EQ(wrap_texel(3, 4, Wrap::border), 3);
}

TEST(Sampling, NegativeCoordinatesRepeatAndMirror) {
    const MipChain chain(coordinates_texture(8, 8));
    EXPECT_EQ(texel_hit(chain, {-0.2f, 0.3f}, Wrap::repeat),
              (std::pair{6, 2}));  // -0.2 = 0.8 (mod 1)
    EXPECT_EQ(texel_hit(chain, {-0.2f, 0.3f}, Wrap::mirror), (std::pair{1, 2}));  // mirrored: 0.2
}

TEST(Sampling, BilinearHitsTexelCentresExactly) {
    const MipChain chain(coordinates_texture(8, 8));
    SamplerState state;
    for (int i = 0; i < 8; ++i) {
        const rl::Rgba c = to_rgba(sample(chain, {(i + 0.5f) / 8, (2 + 0.5f) / 8}, {}, state));
        EXPECT_EQ(c.r, i);  // the centre of texel i: no blending with its neighbours
        EXPECT_EQ(c.g, 2);
    }
}

TEST(Sampling, NanAndInfinityGiveTheBorderColour) {
    const MipChain chain(coordinates_texture(4, 4));
    SamplerState state;
    state.border = {0.25f, 0.5f, 0.75f, 1.0f};
    const float nan = std::numeric_limits<float>::quiet_NaN(),
                inf = std::numeric_limits<float>::infinity();
    for (Filter f : kFilters) {
        state.filter = f;
        for (rl::vec2 uv : {rl::vec2{nan, 0.5f}, rl::vec2{0.5f, inf}, rl::vec2{-inf, nan}}) {
            const rl::vec4 c = sample(chain, uv, {{nan, 0}, {0, inf}}, state);
            EXPECT_EQ(c, state.border) << name(f);
        }
    }
}

TEST(Sampling, RepeatAtLargeCoordinatesIsLimitedByTheFloatItself) {
    // At u = 10^4 a float still resolves about 0.001, half a texel of a
    // 512-texel texture; at 10^6 only 0.0625, 32 texels.
    const MipChain chain(coordinates_texture(256, 2));
    auto texel_error = [&](float whole) {
        int worst = 0;
        for (int i = 0; i < 256; i += 7) {
            const float u = whole + (i + 0.5f) / 256.0f;
            worst = std::max(worst, std::abs(texel_hit(chain, {u, 0.25f}, Wrap::repeat).first - i));
        }
        return worst;
    };
    EXPECT_EQ(texel_error(0.0f), 0);
    EXPECT_LE(texel_error(1e4f), 1);
    EXPECT_GE(texel_error(1e6f), 8);  // the failure, measured: many texels off
}

TEST(MipChain, OddAndNonPowerOfTwoSizesGoDownToOneTexel) {
    const MipChain chain(coordinates_texture(37, 23));
    ASSERT_EQ(chain.levels(), 6);  // 37x23, 18x11, 9x5, 4x2, 2x1, 1x1
    EXPECT_EQ(chain.level(1).width(), 18);
    EXPECT_EQ(chain.level(1).height(), 11);
    EXPECT_EQ(chain.level(5).width(), 1);
    EXPECT_EQ(chain.level(5).height(), 1);
    // The area-weighted box filter keeps the mean: the 1x1 level is the average texel.
    const rl::Rgba last = chain.level(5).get(0, 0);
    EXPECT_NEAR(last.r, 18, 1);  // mean of 0..36
    EXPECT_NEAR(last.g, 11, 1);  // mean of 0..22
}

// Float texels keep what bytes cannot: a texel of 1000 beside one of 0.001
// filters and averages to their true means (lesson 09's skies), where bytes
// would clip the first to 1 and round the second to 0.
TEST(MipChain, FloatTexelsFilterAndAverageTheirValues) {
    rl::Grid<rl::vec4> sky(2, 1, rl::vec4{0.001f, 0.001f, 0.001f, 1});
    sky.set(0, 0, rl::vec4{1000, 500, 250, 1});
    const HdrMipChain chain(sky);
    ASSERT_EQ(chain.levels(), 2);
    EXPECT_FLOAT_EQ(chain.level(1).get(0, 0).x, 500.0005f);  // the area average
    SamplerState bilinear;
    bilinear.wrap = Wrap::clamp;
    // Halfway between the two texel centres: the mean of the two.
    const rl::vec4 middle = sample(chain, {0.5f, 0.5f}, {}, bilinear);
    EXPECT_FLOAT_EQ(middle.x, 500.0005f);
    EXPECT_FLOAT_EQ(middle.y, 250.0005f);
    // Trilinear far away: the top level, the whole texture's mean.
    bilinear.filter = Filter::trilinear;
    EXPECT_FLOAT_EQ(sample(chain, {0.25f, 0.5f}, {{8, 0}, {0, 8}}, bilinear).z, 125.0005f);
    bilinear.filter = Filter::nearest;  // and nearest gives the texel itself
    EXPECT_FLOAT_EQ(sample(chain, {0.75f, 0.5f}, {}, bilinear).x, 0.001f);
    EXPECT_THROW(HdrMipChain(sky, &shading_like_encoding()), std::invalid_argument);
}

// The limitation lesson 06 removes: the chain averages the texture's bytes,
// which are sRGB-encoded, not the light they stand for. On the floor's
// checker the top level is the byte mean, about 137; averaged in linear light
// and encoded again, the same texels give about 162.
TEST(MipChain, AveragesEncodedBytesNotLinearLight) {
    const rl::Image floor =
        rl::load_image(rl::project_model("floor").replace_extension() += "_diffuse.tga");
    const MipChain chain(floor);
    const rl::Rgba top = chain.level(chain.levels() - 1).get(0, 0);
    double bytes = 0, light = 0;
    for (const rl::Rgba& p : floor.pixels()) {
        const double c = p.r / 255.0;
        bytes += p.r;
        light += c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    }
    const double n = static_cast<double>(floor.pixels().size());
    const double linear = light / n,
                 encoded =
                     255.0 * (linear <= 0.0031308 ? linear * 12.92
                                                  : 1.055 * std::pow(linear, 1 / 2.4) - 0.055);
    EXPECT_NEAR(top.r, bytes / n, 2.0);
    EXPECT_NEAR(top.r, 137, 2);
    EXPECT_NEAR(encoded, 162, 2);
}

// The flipped-texture pitfall: v = 0 must sample the image's bottom row,
// for a file stored top row first (PNG) as for one stored bottom first (TGA).
TEST(Sampling, VZeroSamplesTheBottomRowOfTheFile) {
    rl::Image picture(4, 4, rl::Rgba{0, 0, 255, 255});  // blue, with a red bottom row
    for (int x = 0; x < 4; ++x) picture.set(x, 0, {255, 0, 0, 255});
    const auto folder = std::filesystem::temp_directory_path();
    for (const char* name : {"rasterlab-v-zero.png", "rasterlab-v-zero.tga"}) {
        const auto path = folder / name;
        rl::save_image(path, picture);
        const MipChain chain(rl::load_image(path));
        std::filesystem::remove(path);
        for (Filter f : kFilters) {
            const SamplerState state{f, Wrap::clamp, {}};
            EXPECT_EQ(to_rgba(sample(chain, {0.5f, 0.01f}, {}, state)), (rl::Rgba{255, 0, 0, 255}))
                << name << " " << textures::name(f);
            EXPECT_EQ(to_rgba(sample(chain, {0.5f, 0.99f}, {}, state)), (rl::Rgba{0, 0, 255, 255}))
                << name << " " << textures::name(f);
        }
    }
}

TEST(MipChain, OneTexelTexturesSampleToThatTexel) {
    const MipChain chain(rl::Image(1, 1, rl::Rgba{10, 20, 30, 255}));
    EXPECT_EQ(chain.levels(), 1);
    for (Filter f : kFilters)
        for (Wrap w : {Wrap::repeat, Wrap::mirror, Wrap::clamp}) {
            SamplerState state{f, w, {}};
            EXPECT_EQ(to_rgba(sample(chain, {3.7f, -12.2f}, {{0.5f, 0}, {0, 0.5f}}, state)),
                      (rl::Rgba{10, 20, 30, 255}));
        }
    // Border: the texel at its centre, the border colour outside.
    for (Filter f : kFilters) {
        SamplerState state{f, Wrap::border, {0.0f, 1.0f, 0.0f, 1.0f}};
        EXPECT_EQ(to_rgba(sample(chain, {0.5f, 0.5f}, {{0.5f, 0}, {0, 0.5f}}, state)),
                  (rl::Rgba{10, 20, 30, 255}))
            << name(f);
        EXPECT_EQ(to_rgba(sample(chain, {3.7f, -12.2f}, {{0.5f, 0}, {0, 0.5f}}, state)),
                  (rl::Rgba{0, 255, 0, 255}))
            << name(f);
    }
}

TEST(Sampling, ClampAndBorderHoldAtCoordinatesBeyondIntRange) {
    // u * width passed 2^31 at u = 10^7 (a 1024-texel texture): converting it
    // to int was undefined and drew black instead of the edge texel.
    const MipChain chain(coordinates_texture(1024, 4));
    for (Filter f : {Filter::nearest, Filter::bilinear}) {
        SamplerState state{f, Wrap::clamp, {0.0f, 0.0f, 1.0f, 1.0f}};
        for (float big : {1e7f, 3e9f, 1e30f}) {
            // Row 0's centre (v = 1/8), so bilinear takes that row alone.
            const rl::Rgba right = to_rgba(sample(chain, {big, 0.125f}, {}, state));
            EXPECT_EQ(right, (rl::Rgba{255, 0, 0, 255})) << name(f) << " u=" << big;  // i = 1023
            const rl::Rgba left = to_rgba(sample(chain, {-big, 0.125f}, {}, state));
            EXPECT_EQ(left, (rl::Rgba{0, 0, 0, 255})) << name(f) << " u=" << -big;
            state.wrap = Wrap::border;
            EXPECT_EQ(to_rgba(sample(chain, {big, 0.125f}, {}, state)), (rl::Rgba{0, 0, 255, 255}));
            state.wrap = Wrap::clamp;
        }
    }
}

TEST(LevelOfDetail, FollowsTheLongerSideOfTheFootprint) {
    EXPECT_FLOAT_EQ(level_of_detail({{1.0f / 256, 0}, {0, 1.0f / 256}}, 256, 256),
                    0.0f);  // 1 texel per pixel
    EXPECT_FLOAT_EQ(level_of_detail({{8.0f / 256, 0}, {0, 1.0f / 256}}, 256, 256),
                    3.0f);  // 8 along x
}

TEST(Filters, TrilinearBeatsBilinearUnderMinification) {
    rl::Image checker(64, 64);
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i)
            checker.set(i, j,
                        ((i + j) % 2) ? rl::Rgba{255, 255, 255, 255} : rl::Rgba{0, 0, 0, 255});
    const MipChain chain(checker);
    const AffineScene scene = minification_scene(checker, 24);
    const rl::Image truth = footprint_average(checker, scene, 24);
    SamplerState bilinear{Filter::bilinear, Wrap::repeat, {}},
        trilinear{Filter::trilinear, Wrap::repeat, {}};
    const double error_bilinear =
        rl::compare_images(truth, render_scene(chain, scene, bilinear)).rmse;
    const double error_trilinear =
        rl::compare_images(truth, render_scene(chain, scene, trilinear)).rmse;
    EXPECT_LT(error_trilinear, 0.5 * error_bilinear);
}

}  // namespace
