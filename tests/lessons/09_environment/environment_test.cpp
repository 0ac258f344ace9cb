// Lesson 09's optics, tone maps, sky pass and environments: Snell's law and
// total internal reflection, Fresnel's ends, the tone maps' shapes, the
// sky behind the models only, and broken .hdr files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../../unit/temp_dir.hpp"
#include "09_environment/glossy_map.hpp"
#include "09_environment/optics.hpp"
#include "09_environment/scene.hpp"
#include "09_environment/tone_map.hpp"
#include "rasterlab/file_io.hpp"
#include "rasterlab/image_io.hpp"

namespace {

using namespace environment;

TEST(Optics, ReflectionKeepsTheAngleAndFlipsTheNormalPart) {
    const rl::vec3 n{0, 1, 0};
    const rl::vec3 d = rl::normalize(rl::vec3{1, -1, 0});
    const rl::vec3 r = reflect(d, n);
    EXPECT_NEAR(r.x, d.x, 1e-6f);
    EXPECT_NEAR(r.y, -d.y, 1e-6f);
}

// Snell: n1 sin(theta_i) = n2 sin(theta_t); from glass to air past the
// critical angle (asin(1 / 1.5) = 41.8 degrees) nothing gets through.
TEST(Optics, SnellsLawAndTotalInternalReflection) {
    const rl::vec3 n{0, 1, 0};
    for (float degrees : {0.0f, 20.0f, 45.0f, 80.0f}) {
        const float a = rl::radians(degrees);
        const rl::vec3 d{std::sin(a), -std::cos(a), 0};
        const std::optional<rl::vec3> t = refract(d, n, 1 / 1.5f);
        ASSERT_TRUE(t);
        EXPECT_NEAR(rl::length(*t), 1, 1e-5f);
        EXPECT_NEAR(1.5f * t->x, d.x, 1e-5f) << degrees;  // sin(theta_t) * 1.5 = sin(theta_i)
        EXPECT_LT(t->y, 0);                               // on through the surface
    }
    const float critical = std::asin(1 / 1.5f);
    const rl::vec3 below{std::sin(critical - 0.01f), -std::cos(critical - 0.01f), 0};
    const rl::vec3 beyond{std::sin(critical + 0.01f), -std::cos(critical + 0.01f), 0};
    EXPECT_TRUE(refract(below, n, 1.5f));
    EXPECT_FALSE(refract(beyond, n, 1.5f));
}

TEST(Optics, FresnelFromFourPercentHeadOnToAllAtGrazing) {
    EXPECT_NEAR(reflectance_at_normal(1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(schlick(1, 0.04f), 0.04f, 1e-7f);
    EXPECT_NEAR(schlick(0, 0.04f), 1.0f, 1e-7f);
    float previous = 0;
    for (int k = 10; k >= 0; --k) {  // rising as the view grazes
        const float f = schlick(k / 10.0f, 0.04f);
        EXPECT_GE(f, previous);
        previous = f;
    }
}

TEST(ToneMap, ShapesExposureAndBrokenLight) {
    EXPECT_EQ(tone_map(4.0f, {ToneMap::clamp, 0}), 1.0f);
    EXPECT_NEAR(tone_map(1.0f, {ToneMap::reinhard, 0}), 0.5f, 1e-7f);
    EXPECT_NEAR(tone_map(0.5f, {ToneMap::reinhard, 1}), 0.5f, 1e-7f);  // one stop up: 0.5 -> 1
    EXPECT_LT(tone_map(1e6f, {ToneMap::reinhard, 0}), 1.0f);
    EXPECT_EQ(tone_map(1e6f, {ToneMap::aces, 0}), 1.0f);
    float previous = -1;
    for (float light = 0; light < 20; light += 0.25f) {  // every curve rises
        const float v = tone_map(light, {ToneMap::aces, 0});
        EXPECT_GE(v, previous);
        previous = v;
    }
    for (float bad : {NAN, -1.0f, INFINITY})
        for (ToneMap curve : kToneMaps) EXPECT_EQ(tone_map(bad, {curve, 0}), 0.0f);
}

// Without HDR the frame keeps the exposed light as linear bytes: dark
// light falls onto 1/255 steps (the first of them already 13 of 255 once
// encoded to sRGB), and all light above 1 is the same white, whatever the
// tone map would have made of it.
TEST(ToneMap, ABytesFrameBandsTheDarkAndCutsAtOne) {
    const Exposure bytes{ToneMap::clamp, 0, FrameStore::bytes};
    EXPECT_EQ(tone_map(0.0015f, bytes), 0.0f);  // under half a step: black
    EXPECT_EQ(tone_map(0.0025f, bytes), 1.0f / 255);
    EXPECT_EQ(tone_map(0.0045f, bytes), 1.0f / 255);  // one step holds both
    EXPECT_EQ(
        shading::encode(rl::vec3{1, 1, 1} * tone_map(0.0025f, bytes), shading::Output::srgb).r, 13);
    EXPECT_NE(tone_map(0.0025f, {ToneMap::clamp, 0}), tone_map(0.0045f, {ToneMap::clamp, 0}));
    // The exposure comes first: four stops down, a light of 0.1 is 0.00625.
    EXPECT_EQ(tone_map(0.1f, {ToneMap::clamp, -4, FrameStore::bytes}), 2.0f / 255);
    // Above 1: a Reinhard curve sees the cut value.
    EXPECT_NEAR(tone_map(5.0f, {ToneMap::reinhard, 0, FrameStore::bytes}), 0.5f, 1e-7f);
    EXPECT_NEAR(tone_map(5.0f, {ToneMap::reinhard, 0}), 5.0f / 6, 1e-6f);
}

// The ray through a pixel goes where the camera's projection sends it: a
// point along it projects back onto that pixel's centre.
TEST(Skybox, ThePixelRayIsTheProjectionsInverse) {
    pipeline::Camera camera;
    camera.eye = {0.3f, 0.35f, 3.8f};
    camera.target = {0.1f, -0.2f, 0};
    camera.fov_y = 50;
    const int width = 160, height = 90;
    const rl::mat4 vp = pipeline::view_projection(camera, float(width) / height);
    for (auto [x, y] : {std::pair{0.5f, 0.5f}, {80.0f, 45.0f}, {159.5f, 10.5f}, {33.5f, 89.5f}}) {
        const rl::vec3 p = camera.eye + pixel_ray(camera, width, height, x, y) * 5.0f;
        const rl::vec4 clip = vp * rl::vec4{p.x, p.y, p.z, 1};
        EXPECT_NEAR((clip.x / clip.w + 1) / 2 * width, x, 2e-3f);
        EXPECT_NEAR((clip.y / clip.w + 1) / 2 * height, y, 2e-3f);
    }
}

// The sky fills exactly the pixels no model covers: a model's pixels keep
// their colour, and every other pixel is the environment along its ray.
TEST(Skybox, FillsOnlyWhatTheModelsLeft) {
    std::vector<std::string> warnings;
    const Environment env = make_environment({.size = 16}, warnings);
    pipeline::ViewOptions view;
    const auto scene = load_scene(view, normal_mapping::TangentMethod::split, 64, 48, warnings);
    LightTarget frame = light_target(64, 48);
    RenderOptions options;
    options.skybox = false;
    render(scene.models, scene.camera, env, options, frame);
    const LightTarget models_only = frame;
    draw_skybox(env, scene.camera, frame);
    int sky = 0, models = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            if (frame.depth()->get(x, y) != frame.depth_state.clear) {
                ++models;
                EXPECT_EQ(frame.colour().get(x, y), models_only.colour().get(x, y));
            } else {
                ++sky;
                const rl::vec3 expected =
                    env.sample(pixel_ray(scene.camera, 64, 48, x + 0.5f, y + 0.5f));
                EXPECT_EQ(frame.colour().get(x, y), expected);
            }
        }
    EXPECT_GT(models, 300);
    EXPECT_GT(sky, 1000);
}

// The white furnace through the whole render: in an environment of
// radiance 1 everywhere a diffuse surface reflects its albedo exactly, by
// every irradiance method; so the frame equals lesson 07's with no light but
// an ambient term of 1 (which is albedo times 1), to a level.
TEST(Diffuse, TheWhiteFurnaceGivesBackTheAlbedo) {
    std::vector<std::string> warnings;
    pipeline::ViewOptions view;
    const auto scene = load_scene(view, normal_mapping::TangentMethod::split, 64, 48, warnings);
    normal_mapping::RenderOptions ambient_only;
    ambient_only.lighting.lights.clear();
    ambient_only.lighting.ambient = {1, 1, 1};
    ambient_only.lighting.specular = {0, 0, 0};
    pipeline::ColourTarget lesson07 = pipeline::colour_target(64, 48, rl::Rgba{0, 0, 0, 255});
    normal_mapping::render(scene.models, scene.camera, ambient_only, lesson07);
    const Environment white(cube_map(
                                [](rl::dvec3) {
                                    return rl::dvec3{1, 1, 1};
                                },
                                8, 1),
                            MapFilter::seamless);
    for (Irradiance method : kIrradiances) {
        RenderOptions options;
        options.material = Material::diffuse;
        options.irradiance = method;
        options.samples = 4;
        options.skybox = false;
        LightTarget frame = light_target(64, 48);
        render(scene.models, scene.camera, white, options, frame);
        const rl::Image picture = tone_mapped(frame.colour(), {ToneMap::clamp, 0});
        int drawn = 0, off = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x) {
                if (frame.depth()->get(x, y) == frame.depth_state.clear) continue;
                ++drawn;
                const rl::Rgba a = picture.get(x, y), b = lesson07.colour().get(x, y);
                off +=
                    std::abs(a.r - b.r) > 1 || std::abs(a.g - b.g) > 1 || std::abs(a.b - b.b) > 1;
            }
        EXPECT_GT(drawn, 300);
        EXPECT_EQ(off, 0) << name(method);
    }
}

TEST(Environments, SizesOutsideTheCapAreRefused) {
    std::vector<std::string> warnings;
    EXPECT_THROW(make_environment({.size = 0}, warnings), std::invalid_argument);
    EXPECT_THROW(make_environment({.size = kMaxMapSize + 1}, warnings), std::invalid_argument);
}

// A .hdr with texels beyond any real light (RGBE's largest exponents) is
// read with those texels set to 0 and a warning that counts them; the rest
// of the map stays as stored.
TEST(Environments, AnHdrWithAbsurdTexelsIsCleanedWithAWarning) {
    const rl_test::TempDir dir;
    rl::HdrImage image(8, 4, rl::vec4{0.5f, 0.5f, 0.5f, 1});
    image.set(2, 1, rl::vec4{1e30f, 0.5f, 0.5f, 1});
    image.set(5, 3, rl::vec4{0.5f, 3e37f, 0.5f, 1});
    const std::filesystem::path path = dir.path() / "broken.hdr";
    rl_test::write_bytes(path, rl::encode_hdr(path, image));
    std::vector<std::string> warnings;
    const Environment env =
        make_environment({.source = path.string(), .layout = Layout::latlong, .size = 4}, warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("2 texels were negative, not a number or above"), std::string::npos)
        << warnings[0];
    const rl::HdrImage& stored = env.latlong()->map().level(0);
    EXPECT_EQ(stored.get(2, 1).x, 0.0f);
    EXPECT_NEAR(stored.get(0, 0).x, 0.5f, 0.01f);
}

// The maps a render reads, written as .hdr files: every cube face of every
// mip level and every blurred level, or the lat-long map's levels; a
// written lat-long map read back (--environment) is the map it was, to
// RGBE's 8 bits of mantissa.
TEST(Environments, WrittenMapsReadBackAsTheyWere) {
    std::vector<std::string> warnings;
    const Environment cube = make_environment({.size = 16}, warnings);
    const GlossyMap glossy(cube, {.levels = 3, .size = 8, .samples = 4});
    const std::vector<MapFile> files = map_files(cube, &glossy);
    ASSERT_EQ(files.size(), 6u * 5 + 6u * 2);  // levels 16, 8, 4, 2, 1; two blurred levels
    EXPECT_EQ(files.front().name, "cube_px_0.hdr");
    EXPECT_EQ(files[5].name, "cube_nz_0.hdr");
    EXPECT_EQ(files.back().name, "glossy_2_nz.hdr");

    const Environment latlong = make_environment({.layout = Layout::latlong, .size = 16}, warnings);
    const std::vector<MapFile> rows = map_files(latlong);
    ASSERT_EQ(rows.size(), 6u);  // 32x16 down to 1x1
    EXPECT_EQ(rows[0].name, "latlong_0.hdr");
    const rl_test::TempDir dir;
    const std::filesystem::path path = dir.path() / rows[0].name;
    rl_test::write_bytes(path, rl::encode_hdr(path, *rows[0].image));
    const Environment back = make_environment(
        {.source = path.string(), .layout = Layout::latlong, .size = 16}, warnings);
    EXPECT_TRUE(warnings.empty());
    for (rl::vec3 d : {rl::vec3{0, 1, 0}, rl::vec3{0.3f, -0.4f, 0.8f}, rl::vec3{-1, 0.1f, 0}}) {
        const rl::vec3 a = latlong.sample(d), b = back.sample(d);
        EXPECT_NEAR(b.x / a.x, 1.0, 0.01);
        EXPECT_NEAR(b.z / a.z, 1.0, 0.01);
    }
}

TEST(Environments, AMissingHdrIsAFileErrorNamingIt) {
    std::vector<std::string> warnings;
    try {
        make_environment({.source = "/no/such/sky.hdr"}, warnings);
        FAIL() << "no error";
    } catch (const rl::FileError& e) {
        EXPECT_NE(std::string(e.what()).find("/no/such/sky.hdr"), std::string::npos);
    }
}

}  // namespace
