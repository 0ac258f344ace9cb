// The fast path's shadow map pass against lesson 08's: the same map, texel
// for texel, whatever the light, the map's size, the bias, the faces kept
// and the thread count; the same refusals. Then the second pass: the fast
// path's picture with the map, against lesson 08's.
#include <gtest/gtest.h>

#include <string>

#include "rasterlab/image_metrics.hpp"

#include "08_shadows/scene.hpp"
#include "12_fast/shadow_pass.hpp"
#include "rasterlab/transform.hpp"

namespace {

using normal_mapping::MappedModel;

// Lesson 08's scene, and a mirrored copy of its crate (the matrix flips the
// winding: the cull must follow lesson 05's MeshView).
std::vector<MappedModel> scene() {
    std::vector<std::string> warnings;
    std::vector<MappedModel> models = shadows::default_scene(warnings);
    models.push_back(normal_mapping::load_mapped_model(
        rl::project_model("crate"),
        rl::compose({.translation = {-1.2f, 0.4f, 0.8f}, .scale = {-0.5f, 0.5f, 0.5f}}),
        normal_mapping::TangentMethod::split, warnings));
    return models;
}

// Lesson 07's globe, and a copy of it larger by a thousandth drawn after
// it: each small triangle of the copy lies just in front of the first
// globe's, nearer by less than a bias of -0.004 moves both.
std::vector<MappedModel> two_globes() {
    std::vector<std::string> warnings;
    std::vector<MappedModel> models;
    for (float scale : {1.0f, 1.001f})
        models.push_back(normal_mapping::load_mapped_model(
            rl::project_model("globe"), rl::compose({.scale = {scale, scale, scale}}),
            normal_mapping::TangentMethod::split, warnings));
    return models;
}

// The texels where the two maps differ (0 for the same map), and how many
// texels hold something (so that a test of two empty maps cannot pass).
struct Compared {
    int different = 0, covered = 0;
};
Compared compare(const rl::FloatImage& fast, const rl::FloatImage& lesson08) {
    Compared out;
    for (int y = 0; y < fast.height(); ++y)
        for (int x = 0; x < fast.width(); ++x) {
            out.different += fast.at(x, y) != lesson08.at(x, y);
            out.covered += lesson08.at(x, y) < 1;
        }
    return out;
}

TEST(ShadowPass, TheMapIsLessonEightsTexelForTexel) {
    const std::vector<MappedModel> models = scene();
    const pipeline::Box box = shadows::scene_box(models);
    struct Case {
        rl::vec3 towards_light;
        shadows::ShadowMapOptions map;
    };
    const Case cases[] = {
        {shadows::kSceneLight, {.size = 256}},  // lesson 08's default bias (slope 1)
        {{0.3f, 0.5f, 1.0f}, {.size = 1000, .constant_bias = 0.002f, .slope_bias = 2}},
        // A negative bias: a block's nearest depth must move with it.
        {{-0.7f, 0.4f, 0.2f}, {.size = 333, .constant_bias = -0.004f, .slope_bias = 0}},
        {{0.05f, 1.0f, 0.02f}, {.size = 37, .slope_bias = 0}},  // no bias, one tile, part blocks
        {shadows::kSceneLight, {.size = 512, .cull = pipeline::Cull::front}},
        {{1.0f, 0.02f, 0.1f}, {.size = 200, .slope_bias = 1}},  // a grazing light
    };
    for (const Case& c : cases) {
        const shadows::LightView light = shadows::light_view(
            {shadows::LightType::directional, rl::normalize(c.towards_light)}, box);
        const shadows::ShadowMap lesson08 = shadows::render_shadow_map(models, light, c.map);
        for (int threads : {1, 2}) {
            fast::ShadowPass pass(models, c.map, threads);
            for (int again = 0; again < 2; ++again) {  // a second frame reuses the buffers
                const Compared compared = compare(pass.render(light).depth, lesson08.depth);
                EXPECT_EQ(compared.different, 0)
                    << "map " << c.map.size << ", " << threads << " thread(s), frame " << again;
                EXPECT_GT(compared.covered, c.map.size * c.map.size / 20) << c.map.size;
            }
        }
    }
}

// A block skipped by the hierarchical test must be skipped for the biased
// depths: with a negative bias, a triangle's unbiased nearest depth lies
// behind what it would store.
TEST(ShadowPass, ABlockIsSkippedOnlyWhereTheBiasedTriangleCannotPass) {
    const std::vector<MappedModel> models = two_globes();
    const shadows::ShadowLight towards{shadows::LightType::directional,
                                       rl::normalize(rl::vec3{0.3f, 0.5f, 1.0f})};
    const shadows::LightView light = shadows::light_view(towards, shadows::scene_box(models));
    const shadows::ShadowMapOptions map{.size = 512, .constant_bias = -0.004f, .slope_bias = 0};
    const shadows::ShadowMap lesson08 = shadows::render_shadow_map(models, light, map);
    fast::ShadowPass pass(models, map, 2);
    const Compared compared = compare(pass.render(light).depth, lesson08.depth);
    EXPECT_EQ(compared.different, 0);
    EXPECT_GT(compared.covered, 0);
}

// A spot light (a perspective projection from a point) and the map fitted
// to what a camera sees: lesson 08's program's own light view.
TEST(ShadowPass, TheMapIsLessonEightsForASpotLightAndAFittedView) {
    const std::vector<MappedModel> models = scene();
    std::vector<std::string> warnings;
    pipeline::ViewOptions view;
    const pipeline::ViewedScene<MappedModel> viewed =
        shadows::load_scene(view, normal_mapping::TangentMethod::split, 320, 240, warnings);
    shadows::ShadowOptions options;
    options.map.size = 640;
    const shadows::LightView fitted =
        shadows::light_view_for(models, viewed.camera, 320.0f / 240.0f, options);
    shadows::ShadowLight spot{shadows::LightType::spot, rl::normalize(shadows::kSceneLight)};
    spot.position = shadows::default_spot_position(shadows::scene_box(models), spot.direction);
    const shadows::LightView spot_view = shadows::light_view(spot, shadows::scene_box(models));
    for (const shadows::LightView& light : {fitted, spot_view}) {
        const shadows::ShadowMap lesson08 = shadows::render_shadow_map(models, light, options.map);
        fast::ShadowPass pass(models, options.map, 2);
        const Compared compared = compare(pass.render(light).depth, lesson08.depth);
        EXPECT_EQ(compared.different, 0);
        EXPECT_GT(compared.covered, 0);
    }
}

// The renderer's own depth pass without the vertex cache (every corner in
// the surface's order, as the lab runs it): the same map, the mirrored
// crate included.
TEST(ShadowPass, WithoutTheVertexCacheTheMapIsLessonEights) {
    const std::vector<MappedModel> models = scene();
    const shadows::ShadowMapOptions map{.size = 256};
    const shadows::LightView light =
        shadows::light_view({shadows::LightType::directional, rl::normalize(shadows::kSceneLight)},
                            shadows::scene_box(models));
    const shadows::ShadowMap lesson08 = shadows::render_shadow_map(models, light, map);
    fast::FastOptions o;
    o.depth_only = true, o.vertex_cache = false, o.threads = 2;
    o.slope_bias = map.slope_bias;
    o.render.pipeline = shadows::map_pipeline(map);
    fast::Renderer renderer(models, 256, 256, o);
    rl::FloatImage depth(256, 256);
    renderer.render_depth(light.view_projection, depth);
    const Compared compared = compare(depth, lesson08.depth);
    EXPECT_EQ(compared.different, 0);
    EXPECT_GT(compared.covered, 0);
}

TEST(ShadowPass, RefusesWhatLessonEightRefuses) {
    const std::vector<MappedModel> models = scene();
    EXPECT_THROW(fast::ShadowPass(models, {.size = 0}), std::invalid_argument);
    EXPECT_THROW(fast::ShadowPass(models, {.size = shadows::kMaxShadowMapSize + 1}),
                 std::invalid_argument);
    const shadows::LightView light = shadows::light_view({}, shadows::scene_box(models));
    // Caps from a tenth of a layer of the map to eight layers: each refused
    // by both, in lesson 08's words, or by neither (lesson 08 caps each model
    // on its own, not the scene).
    int refused = 0, drawn = 0;
    for (double layers : {0.0, 0.1, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 8.0}) {
        shadows::ShadowMapOptions options{.size = 256};
        options.max_samples = layers * 256 * 256;
        std::string lesson08, ours;
        try {
            shadows::render_shadow_map(models, light, options);
        } catch (const pipeline::OverdrawError& e) {
            lesson08 = e.what();
        }
        try {
            fast::ShadowPass(models, options, 2).render(light);
        } catch (const pipeline::OverdrawError& e) {
            ours = e.what();
        }
        EXPECT_EQ(ours, lesson08) << layers << " layers";
        ++(lesson08.empty() ? drawn : refused);
    }
    EXPECT_GT(refused, 0);
    EXPECT_GT(drawn, 0);
}

// The fast path prepared for a scene at a picture's size, on `threads` threads.
fast::Renderer fast_renderer(const pipeline::ViewedScene<MappedModel>& s,
                             const shadows::ShadowOptions& o, int width, int height, int threads) {
    fast::FastOptions f;
    f.threads = threads;
    f.render = o.render;
    return fast::Renderer(s.models, width, height, f);
}

// Lesson 08's second pass, both ways: its own renderer's picture and, with
// the same map, options and lights, the picture of each fast renderer given
// (prepared for the scene at one size: a renderer prepares its models once).
struct SecondPass {
    rl::Image lesson08;
    std::vector<rl::Image> fast;
};
SecondPass second_pass(const pipeline::ViewedScene<MappedModel>& s, const shadows::ShadowOptions& o,
                       std::initializer_list<fast::Renderer*> renderers) {
    const rl::Image& size = (*renderers.begin())->frame();
    const float aspect = static_cast<float>(size.width()) / static_cast<float>(size.height());
    const shadows::ShadowMap map = shadows::shadow_map_for(s.models, s.camera, aspect, o);
    pipeline::ColourTarget target = pipeline::colour_target(size.width(), size.height());
    shadows::render(s.models, s.camera, o, map, target);
    SecondPass pictures{target.colour(), {}};
    for (fast::Renderer* renderer : renderers) {
        renderer->set_shadow_map(&map, o.lookup);
        renderer->render(s.camera);
        renderer->set_shadow_map(nullptr);  // the map ends here
        pictures.fast.push_back(renderer->frame());
    }
    return pictures;
}

// The pixels where two pictures differ at all.
int differing(const rl::Image& a, const rl::Image& b) {
    return static_cast<int>(rl::compare_images(a, b, 0).share_over * a.width() * a.height() + 0.5);
}

// Lesson 08's scene from its camera, with its lights.
struct LitScene {
    pipeline::ViewedScene<MappedModel> scene;
    shadows::ShadowOptions options;
    LitScene(int width, int height) {
        std::vector<std::string> warnings;
        pipeline::ViewOptions view;
        view.light = {shadows::kSceneLight.x, shadows::kSceneLight.y, shadows::kSceneLight.z};
        scene = shadows::load_scene(view, normal_mapping::TangentMethod::split, width, height,
                                    warnings);
        shadows::set_lights(options, view, false);
    }
};

// The page's promise: lesson 08's picture, to within one level at every
// pixel, for every filter of the lookup and at any thread count; and the
// shadows are there (the picture is not lesson 07's).
TEST(ShadowPass, ThePictureIsLessonEightsForEveryFilter) {
    LitScene lit(160, 120);
    fast::Renderer one = fast_renderer(lit.scene, lit.options, 160, 120, 1);
    fast::Renderer two = fast_renderer(lit.scene, lit.options, 160, 120, 2);
    for (const shadows::ShadowFilter filter : shadows::kShadowFilters) {
        lit.options.lookup.filter = filter;
        const SecondPass p = second_pass(lit.scene, lit.options, {&one, &two});
        for (int threads : {1, 2}) {
            const rl::ImageDiff d = rl::compare_images(p.lesson08, p.fast[threads - 1], 1);
            EXPECT_LE(d.max_abs, 1) << shadows::name(filter) << ", " << threads << " threads";
        }
    }
    shadows::ShadowOptions unshadowed = lit.options;
    unshadowed.casters = false;
    const SecondPass lesson07 = second_pass(lit.scene, unshadowed, {&one});
    const SecondPass shadowed = second_pass(lit.scene, lit.options, {&one});
    EXPECT_GT(differing(lesson07.fast[0], shadowed.fast[0]), 300);  // 480 of 19200 pixels
}

// A spot light's key light comes from its position, dimmed by its cone:
// not the first light's direction the fast shader lights with. Refused.
TEST(ShadowPass, ThePictureRefusesASpotLightsMap) {
    LitScene lit(32, 32);
    lit.options.light.type = shadows::LightType::spot;
    shadows::place_spot(lit.options, shadows::scene_box(lit.scene.models), {});
    const shadows::ShadowMap map =
        shadows::shadow_map_for(lit.scene.models, lit.scene.camera, 1.0f, lit.options);
    fast::Renderer renderer(lit.scene.models, 32, 32, {});
    EXPECT_THROW(renderer.set_shadow_map(&map, lit.options.lookup), std::invalid_argument);
}

}  // namespace
