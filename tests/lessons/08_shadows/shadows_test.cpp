// Lesson 08's stability cases and pitfalls: the light's view, the shadow
// map's bias, the lookup's filters, and the edge cases of the issue (a
// grazing light, a light inside the scene, an empty scene, a caster thinner
// than a texel, a caster touching its receiver).
#include <gtest/gtest.h>

#include "rasterlab/checkpoint.hpp"

#include <cmath>

#include "08_shadows/scene.hpp"
#include "rasterlab/transform.hpp"

namespace {

using namespace shadows;
using normal_mapping::MappedModel;

MappedModel model(const char* name, const rl::Trs& trs) {
    std::vector<std::string> warnings;
    return normal_mapping::load_mapped_model(rl::project_model(name), rl::compose(trs),
                                             normal_mapping::TangentMethod::split, warnings);
}

// The floor (the square [-s, s]^2 of y = 0), and optionally the crate
// standing on it at the origin (edge 1.1).
std::vector<MappedModel> floor_scene(bool with_crate, float scale = 3) {
    std::vector<MappedModel> models;
    models.push_back(model("floor", {.scale = {scale, scale, scale}}));
    if (with_crate) models.push_back(model("crate", {.translation = {0, 0.55f, 0}}));
    return models;
}

ShadowMap map_of(const std::vector<MappedModel>& models, rl::vec3 towards_light,
                 const ShadowMapOptions& options) {
    const ShadowLight light{LightType::directional, rl::normalize(towards_light)};
    return render_shadow_map(models, light_view(light, scene_box(models)), options);
}

// The share of a grid of floor points (|x|, |z| <= extent, y = 0, normal +y)
// that the map shadows, and the mean light that reaches them.
struct FloorShadow {
    double shadowed = 0, mean_light = 0;
};
FloorShadow floor_shadow(const ShadowMap& map, const ShadowLookup& lookup, float x0, float x1,
                         float z0, float z1) {
    FloorShadow out;
    const int n = 60;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const rl::vec3 p{x0 + (x1 - x0) * (i + 0.37f) / n, 0, z0 + (z1 - z0) * (j + 0.61f) / n};
            const float lit = visibility(map, p, {0, 1, 0}, lookup);
            out.shadowed += lit < 1;
            out.mean_light += lit;
        }
    out.shadowed /= n * n;
    out.mean_light /= n * n;
    return out;
}

// The orthographic projection sends its box's corners to the NDC cube's.
TEST(ShadowsTest, OrthographicSendsItsBoxToTheCube) {
    const rl::mat4 m = orthographic(-2, 4, -1, 3, 1, 11);
    const rl::vec4 low = m * rl::vec4{-2, -1, -1, 1}, high = m * rl::vec4{4, 3, -11, 1};
    EXPECT_NEAR(low.x, -1, 1e-6f);
    EXPECT_NEAR(low.y, -1, 1e-6f);
    EXPECT_NEAR(low.z, -1, 1e-6f);
    EXPECT_NEAR(high.x, 1, 1e-6f);
    EXPECT_NEAR(high.y, 1, 1e-6f);
    EXPECT_NEAR(high.z, 1, 1e-6f);
    EXPECT_EQ(low.w, 1.0f);
}

// The page's worked example (docs/08_shadows.md#light-space): a light
// straight above the box [-2, 2] x [0, 1] x [-2, 2], an 8 x 8 map. The point
// (0.6, 0.25, -1.1) lands at u = 2.8, v = 1.8 (texel (2, 1)) at depth 0.75;
// a plate at height 0.5 stored 0.5 there, so the point is in shadow.
TEST(ShadowsTest, TheWorkedExampleOfThePage) {
    pipeline::Box box;
    box.add(rl::vec3{-2, 0, -2});
    box.add(rl::vec3{2, 1, 2});
    ShadowMap map;
    map.light = light_view({LightType::directional, {0, 1, 0}}, box);
    map.depth = rl::FloatImage(8, 8, 1.0f);
    const MapPoint p = to_map(map, {0.6f, 0.25f, -1.1f});
    EXPECT_NEAR(p.u, 2.8f, 1e-5f);
    EXPECT_NEAR(p.v, 1.8f, 1e-5f);
    EXPECT_NEAR(p.depth, 0.75f, 1e-4f);  // (the box's depth has a 10^-4 margin each side)
    EXPECT_NEAR(to_map(map, {0.6f, 0.5f, -1.1f}).depth, 0.5f, 1e-4f);  // the plate above it
    EXPECT_NEAR(map.light.texel_size({0, 0, 0}, 8), 0.5f, 1e-6f);      // 4 units over 8 texels
    map.depth.at(2, 1) = 0.5f;
    EXPECT_EQ(visibility(map, {0.6f, 0.25f, -1.1f}, {0, 1, 0}, {ShadowFilter::hard, 0}), 0.0f);
    EXPECT_EQ(visibility(map, {0.6f, 0.5f, -1.1f}, {0, 1, 0}, {ShadowFilter::hard, 0}), 1.0f);
}

// Every corner of the covered box lands inside the light's clip volume.
TEST(ShadowsTest, TheLightsViewHoldsTheWholeBox) {
    pipeline::Box box;
    box.add(rl::vec3{-1, 0, -2});
    box.add(rl::vec3{3, 1, 2});
    for (const ShadowLight& light :
         {ShadowLight{LightType::directional, rl::normalize(rl::vec3{-0.7f, 1, 0.4f})},
          ShadowLight{LightType::directional, {0, 1, 0}},  // straight down: up must change
          ShadowLight{LightType::spot, rl::normalize(rl::vec3{1, 2, 1}), {4, 6, 3}, 90}}) {
        const LightView view = light_view(light, box);
        for (int i = 0; i < 8; ++i) {
            const rl::vec4 c = view.view_projection * rl::extend(box.corner(i), 1.0f);
            ASSERT_GT(c.w, 0) << name(light.type);
            for (int k = 0; k < 3; ++k) {
                EXPECT_LE(std::abs(c[static_cast<std::size_t>(k)] / c.w), 1.0001f)
                    << name(light.type) << " corner " << i << " axis " << k;
            }
        }
    }
}

// Pitfall: shadow acne. Without any bias a lit surface shadows itself in
// stripes: its depth between two texel centres differs from what the map
// stored at the centre by up to half a texel times its slope. The slope
// bias and the normal offset remove it, at the light's grazing angle too.
TEST(ShadowsTest, WithoutBiasALitFloorShadowsItself) {
    const std::vector<MappedModel> floor = floor_scene(false);
    for (const rl::vec3 light : {rl::vec3{1, 1, 0}, rl::vec3{1, 0.15f, 0.2f}}) {
        const ShadowMap bare = map_of(floor, light, {.size = 256, .slope_bias = 0});
        const FloorShadow acne =
            floor_shadow(bare, {ShadowFilter::hard, 0}, -2.5f, 2.5f, -2.5f, 2.5f);
        EXPECT_GT(acne.shadowed, 0.2) << light;
        // Each of the two defaults alone fixes it, on the hard test: the slope
        // bias stored in the map, and the normal offset at the lookup.
        const ShadowMap sloped = map_of(floor, light, {.size = 256, .slope_bias = 1});
        EXPECT_EQ(floor_shadow(sloped, {ShadowFilter::hard, 0}, -2.5f, 2.5f, -2.5f, 2.5f).shadowed,
                  0)
            << light;
        EXPECT_EQ(floor_shadow(bare, {ShadowFilter::hard, 1}, -2.5f, 2.5f, -2.5f, 2.5f).shadowed, 0)
            << light;
        const ShadowMap biased = map_of(floor, light, {.size = 256});
        const FloorShadow fixed = floor_shadow(biased, {}, -2.5f, 2.5f, -2.5f, 2.5f);
        EXPECT_EQ(fixed.shadowed, 0) << light;
    }
}

// Pitfall: peter-panning. A constant bias large enough to hide any acne
// also lifts the shadow off a caster close to its receiver: a plate 0.1
// above the floor casts no shadow at all with a bias of 0.05 (a quarter of
// a world unit of depth here).
TEST(ShadowsTest, TooMuchBiasDetachesTheShadowFromItsCaster) {
    std::vector<MappedModel> scene = floor_scene(false);
    scene.push_back(model("floor", {.translation = {0, 0.1f, 0}, .scale = {0.5f, 0.5f, 0.5f}}));
    const rl::vec3 light{-1, 1, 0};  // the plate's shadow falls on x in [-0.4, 0.6]
    const ShadowMap right = map_of(scene, light, {.size = 512});
    const ShadowMap lifted = map_of(scene, light, {.size = 512, .constant_bias = 0.05f});
    EXPECT_EQ(floor_shadow(right, {}, -0.2f, 0.4f, -0.3f, 0.3f).mean_light, 0.0);
    EXPECT_EQ(floor_shadow(lifted, {}, -0.2f, 0.4f, -0.3f, 0.3f).mean_light, 1.0);
}

// The price of back faces in the map: a single-sided caster has none, so
// it casts no shadow at all (the plate of the test above, its floor lit).
TEST(ShadowsTest, ABackFaceMapLosesSingleSidedCasters) {
    std::vector<MappedModel> scene = floor_scene(false);
    scene.push_back(model("floor", {.translation = {0, 0.1f, 0}, .scale = {0.5f, 0.5f, 0.5f}}));
    const rl::vec3 light{-1, 1, 0};
    const ShadowMap front = map_of(scene, light, {.size = 512});
    const ShadowMap back = map_of(scene, light, {.size = 512, .cull = pipeline::Cull::front});
    EXPECT_EQ(floor_shadow(front, {}, -0.2f, 0.4f, -0.3f, 0.3f).mean_light, 0.0);
    EXPECT_EQ(floor_shadow(back, {}, -0.2f, 0.4f, -0.3f, 0.3f).mean_light, 1.0);
}

// A map made by hand: identity light matrix (the cube [-1, 1]^3 is the
// light's clip space), 2 x 2 texels, the left column near (0.2), the right
// far (0.9).
ShadowMap two_by_two() {
    ShadowMap map;
    map.light.view_projection = rl::mat4::identity();
    map.light.width = 2;
    map.depth = rl::FloatImage(2, 2, 0.9f);
    map.depth.at(0, 0) = map.depth.at(0, 1) = 0.2f;
    return map;
}

// Pitfall: filter the comparisons, not the depths. Between a near texel
// (0.2) and a far one (0.9), a point at depth 0.5 is shadowed by the first
// and lit by the second: half lit. The depths' average, 0.55, would call it
// wholly lit.
TEST(ShadowsTest, PercentageCloserFilteringAveragesTheAnswersNotTheDepths) {
    const ShadowMap map = two_by_two();
    // World (0, 0, 0): NDC z 0 is window depth 0.5; u = v = 1, between the texels.
    EXPECT_NEAR(visibility(map, {0, 0, 0}, {0, 0, 1}, {ShadowFilter::pcf2, 0}), 0.5f, 1e-6f);
    EXPECT_EQ(visibility(map, {-0.5f, 0, 0}, {0, 0, 1}, {ShadowFilter::hard, 0}), 0.0f);
    EXPECT_EQ(visibility(map, {0.5f, 0, 0}, {0, 0, 1}, {ShadowFilter::hard, 0}), 1.0f);
}

// Outside the map, past its far plane, and behind a spot light nothing is in shadow.
TEST(ShadowsTest, PointsTheMapDoesNotCoverAreLit) {
    ShadowMap map = two_by_two();
    map.depth = rl::FloatImage(2, 2, 0.0f);  // everything shadowed where the map reaches
    EXPECT_EQ(visibility(map, {3, 0, 0}, {0, 0, 1}, {ShadowFilter::pcf5, 0}), 1.0f);
    EXPECT_EQ(visibility(map, {0, 0, 2}, {0, 0, 1}, {ShadowFilter::hard, 0}), 1.0f);  // beyond far
    EXPECT_EQ(visibility(map, {-0.5f, 0, 0}, {0, 0, 1}, {ShadowFilter::hard, 0}), 0.0f);
    map.light.view_projection = rl::perspective(90, 1, 0.1f, 10);  // a spot at the origin, down -z
    map.light.type = LightType::spot;
    EXPECT_EQ(visibility(map, {0, 0, 1}, {0, 0, 1}, {ShadowFilter::hard, 0}), 1.0f);  // behind it
}

// Every filter is lit in the open and shadowed deep under the crate's shadow.
TEST(ShadowsTest, EveryFilterAgreesAwayFromShadowEdges) {
    const std::vector<MappedModel> scene = floor_scene(true);
    const ShadowMap map = map_of(scene, {-1, 1, 0}, {.size = 512});
    for (ShadowFilter filter : kShadowFilters) {
        EXPECT_EQ(floor_shadow(map, {filter, 1}, -2.5f, -1.0f, -2.5f, 2.5f).mean_light, 1.0)
            << name(filter);
        EXPECT_EQ(floor_shadow(map, {filter, 1}, 0.8f, 1.3f, -0.3f, 0.3f).mean_light, 0.0)
            << name(filter);
    }
}

// A spot light inside the scene's box still gets a depth range and a map.
TEST(ShadowsTest, ASpotLightInsideTheSceneStillCastsShadows) {
    const std::vector<MappedModel> scene = floor_scene(true);
    // Inside the scene's box (x, z in [-3, 3], y in [0, 1.1]), below the crate's top.
    ShadowLight spot{LightType::spot, rl::normalize(rl::vec3{-1, 1, 0}), {-1.5f, 0.8f, 0}, 120};
    const ShadowMap map =
        render_shadow_map(scene, light_view(spot, scene_box(scene)), {.size = 256});
    // The crate shadows the floor behind it, away from the light.
    EXPECT_LT(floor_shadow(map, {}, 0.9f, 1.2f, -0.2f, 0.2f).mean_light, 0.05);
    EXPECT_EQ(floor_shadow(map, {}, -2.5f, -2.0f, -0.5f, 0.5f).mean_light, 1.0);
}

// A light straight down the crate's walls: they are edge-on to the map
// and get no direct light; the floor beside the crate stays lit and the
// floor under it shadowed.
TEST(ShadowsTest, ALightStraightDownAWallShadowsOnlyWhatIsUnderIt) {
    const std::vector<MappedModel> scene = floor_scene(true);
    const ShadowMap map = map_of(scene, {0, 1, 0}, {.size = 512});
    EXPECT_EQ(floor_shadow(map, {}, 0.7f, 2.5f, -0.4f, 0.4f).mean_light, 1.0);   // beside it
    EXPECT_EQ(floor_shadow(map, {}, -0.4f, 0.4f, -0.4f, 0.4f).mean_light, 0.0);  // under it
    const float on_wall = visibility(map, {0.55f, 0.5f, 0}, {1, 0, 0}, {});
    EXPECT_TRUE(std::isfinite(on_wall));
}

// A caster thinner than a texel: a sliver 0.02 wide, 0.5 above the floor,
// the light straight down. The map rasterizes it only where it covers a
// texel's centre: at 64 texels over 6 units (0.094 a texel) it covers none
// and its shadow is gone; at 2048 (0.003 a texel) it is all there.
TEST(ShadowsTest, ACasterThinnerThanATexelLosesItsShadow) {
    std::vector<MappedModel> scene = floor_scene(false);
    MappedModel sliver = model("floor", {});
    rl::Mesh& mesh = sliver.lit.model.mesh;
    mesh.positions = {{-0.01f, 0.5f, 1}, {0.01f, 0.5f, 1}, {0.01f, 0.5f, -1}, {-0.01f, 0.5f, -1}};
    mesh.uvs = {{0, 0}};
    mesh.normals = {{0, 1, 0}};
    const auto corner = [](int i) { return rl::Corner{i, 0, 0}; };
    mesh.faces = {{{corner(0), corner(1), corner(2)}, 0}, {{corner(0), corner(2), corner(3)}, 0}};
    sliver.lit.normals = shading::corner_normals(mesh, shading::Weighting::angle);
    sliver.lit.model.box = pipeline::bounds(mesh, rl::mat4::identity());
    sliver.tangents = normal_mapping::corner_tangents(mesh, sliver.lit.normals,
                                                      normal_mapping::TangentMethod::split);
    scene.push_back(std::move(sliver));
    const auto found = [&](int size) {  // the share of the shadow's centre line in shadow
        const ShadowMap map = map_of(scene, {0, 1, 0}, {.size = size, .slope_bias = 0});
        return 1 -
               floor_shadow(map, {ShadowFilter::hard, 0}, -0.001f, 0.001f, -0.9f, 0.9f).mean_light;
    };
    EXPECT_EQ(found(64), 0.0);
    EXPECT_EQ(found(2048), 1.0);
}

// An empty scene renders (its map holds nothing), and a zero light direction is refused.
TEST(ShadowsTest, AnEmptySceneHasAnEmptyMapAndAZeroLightIsRefused) {
    const std::vector<MappedModel> none;
    pipeline::Camera camera;
    ShadowOptions options;
    const ShadowMap map = shadow_map_for(none, camera, 1, options);
    for (float d : map.depth.pixels()) ASSERT_EQ(d, 1.0f);
    pipeline::ColourTarget frame = pipeline::colour_target(16, 16);
    EXPECT_EQ(render(none, camera, options, map, frame).shaded, 0u);
    pipeline::Box box;
    box.add(rl::vec3{0, 0, 0});
    EXPECT_THROW(light_view({LightType::directional, {0, 0, 0}}, box), std::invalid_argument);
    EXPECT_THROW(light_view({LightType::directional, {INFINITY, 1, 0}}, box),
                 std::invalid_argument);
    EXPECT_THROW(light_view({LightType::spot, {0, 1, 0}, {NAN, 0, 0}}, box), std::invalid_argument);
    EXPECT_THROW(render_shadow_map(none, light_view({}, box), {.size = 0}), std::invalid_argument);
    EXPECT_THROW(render_shadow_map(none, light_view({}, box), {.size = kMaxShadowMapSize + 1}),
                 std::invalid_argument);
}

// Fitting to the view gives the map a smaller box than the scene's when the
// camera sees part of it, and never a larger one.
TEST(ShadowsTest, FittingToTheViewCoversNoMoreThanTheScene) {
    pipeline::Box scene;
    scene.add(rl::vec3{-10, 0, -10});
    scene.add(rl::vec3{10, 1, 10});
    pipeline::Camera camera;
    camera.eye = {0, 1, 8};
    camera.target = {0, 0, 5};
    camera.near = 0.1f;
    camera.far = 6;
    const pipeline::Box seen = visible_box(camera, 1, scene);
    ASSERT_FALSE(seen.empty());
    EXPECT_GE(seen.min.x, scene.min.x);
    EXPECT_LE(seen.max.z, scene.max.z);
    EXPECT_LT(seen.max.x - seen.min.x, scene.max.x - scene.min.x);
}

// A camera low over the floor, looking away from the crate into its shadow:
// the crate is outside the view, yet it stands between the light and
// every floor point the view holds. Fitting the map to the view must keep
// it (the near plane moves towards the light over the scene's box), so the
// view fit shadows those points as the scene fit does.
TEST(ShadowsTest, FittingToTheViewKeepsCastersOutsideTheView) {
    const std::vector<MappedModel> models = floor_scene(true);
    pipeline::Camera camera;
    camera.eye = {-0.2f, 0.3f, -0.8f};
    camera.target = {-0.2f, 0, -1.6f};
    camera.near = 0.05f;
    camera.far = 2;
    ShadowOptions options;
    options.light.direction = rl::normalize(rl::vec3{0.3f, 0.5f, 1.0f});
    const pipeline::Box seen = visible_box(camera, 1, scene_box(models));
    ASSERT_LT(seen.max.z, -0.55f) << "the crate must be outside the view for this test";
    options.fit = Fit::view;
    const ShadowMap view_map = shadow_map_for(models, camera, 1, options);
    options.fit = Fit::scene;
    const ShadowMap scene_map = shadow_map_for(models, camera, 1, options);
    // Floor points in the view and in the crate's shadow.
    const FloorShadow by_scene = floor_shadow(scene_map, options.lookup, -0.5f, 0.1f, -2.0f, -1.2f);
    const FloorShadow by_view = floor_shadow(view_map, options.lookup, -0.5f, 0.1f, -2.0f, -1.2f);
    EXPECT_GT(by_scene.shadowed, 0.99);
    EXPECT_GT(by_view.shadowed, 0.99);
}

// Pitfall: the shadow darkens the key light only. The ambient term and the
// fill light stand for light from everywhere else, which one map cannot
// test: a point in the crate's shadow is lit exactly as lesson 07 lights
// it without the key light, and no pixel is darker than that.
// The floor with the crate, seen from above and in front, lit from the
// right by a key light and lesson 07's fill light.
struct LitFloor {
    std::vector<MappedModel> models = floor_scene(true);
    pipeline::Camera camera{
        .eye = {2.5f, 3.0f, 3.5f}, .target = {0, 0, 0}, .near = 0.5f, .far = 20};
    ShadowOptions options;
    LitFloor() {
        options.light.direction = rl::normalize(rl::vec3{1.0f, 0.6f, 0.6f});
        options.render.lighting = shading::default_lighting(options.light.direction);
    }
};

TEST(ShadowsTest, AShadowDarkensTheKeyLightOnly) {
    LitFloor scene;
    const std::vector<MappedModel>& models = scene.models;
    const pipeline::Camera& camera = scene.camera;
    ShadowOptions& options = scene.options;
    ASSERT_GE(options.render.lighting.lights.size(), 2u) << "the test wants a fill light too";
    const ShadowMap map = shadow_map_for(models, camera, 1, options);
    pipeline::ColourTarget shadowed = pipeline::colour_target(96, 96);
    render(models, camera, options, map, shadowed);
    normal_mapping::RenderOptions without_key = options.render;
    without_key.lighting.lights.erase(without_key.lighting.lights.begin());
    pipeline::ColourTarget unlit = pipeline::colour_target(96, 96);
    normal_mapping::render(models, camera, without_key, unlit);
    int in_shadow = 0, darker = 0;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 96; ++x) {
            const rl::Rgba a = shadowed.colour().get(x, y), b = unlit.colour().get(x, y);
            const int d[3] = {a.r - b.r, a.g - b.g, a.b - b.b};
            darker += d[0] < -1 || d[1] < -1 || d[2] < -1;
            in_shadow += std::abs(d[0]) <= 1 && std::abs(d[1]) <= 1 && std::abs(d[2]) <= 1 &&
                         a != rl::kBackground;
        }
    EXPECT_EQ(darker, 0);
    EXPECT_GT(in_shadow, 40) << "the crate's shadow should cover some of the floor (78 pixels)";
}

// --show unshadowed, the page's "before" picture: the same light with
// nothing in its map is lesson 07's render, every light whole.
TEST(ShadowsTest, WithoutCastersTheImageIsLessonSevens) {
    LitFloor scene;
    const std::vector<MappedModel>& models = scene.models;
    const pipeline::Camera& camera = scene.camera;
    ShadowOptions& options = scene.options;
    options.casters = false;
    const ShadowMap map = shadow_map_for(models, camera, 1, options);
    pipeline::ColourTarget unshadowed = pipeline::colour_target(96, 96);
    render(models, camera, options, map, unshadowed);
    pipeline::ColourTarget lesson07 = pipeline::colour_target(96, 96);
    normal_mapping::render(models, camera, options.render, lesson07);
    int differing = 0, drawn = 0;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 96; ++x) {
            const rl::Rgba a = unshadowed.colour().get(x, y), b = lesson07.colour().get(x, y);
            differing +=
                std::abs(a.r - b.r) > 1 || std::abs(a.g - b.g) > 1 || std::abs(a.b - b.b) > 1;
            drawn += a != rl::kBackground;
        }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(drawn, 96 * 96 / 4);
    options.casters = true;  // and with them the crate shadows the floor
    pipeline::ColourTarget shadowed = pipeline::colour_target(96, 96);
    render(models, camera, options, shadow_map_for(models, camera, 1, options), shadowed);
    EXPECT_NE(shadowed.colour(), unshadowed.colour());
}

// The shadow map's pass is capped in texels visited, whatever the map's
// size (sized by the map alone, an 8192² map allowed 16 times the work of a
// 2048² one). The floor's two triangles cover a map fitted to it twice over:
// under a cap of half a map's texels they are refused, naming the cap.
TEST(ShadowsTest, TheShadowPassRefusesMoreWorkThanItsCap) {
    const std::vector<MappedModel> floor = floor_scene(false);
    ShadowMapOptions options{.size = 256};
    EXPECT_NO_THROW(map_of(floor, {0, 1, 0}, options));
    options.max_samples = 0.5 * 256 * 256;
    try {
        map_of(floor, {0, 1, 0}, options);
        ADD_FAILURE() << "a pass over its cap was drawn";
    } catch (const pipeline::OverdrawError& e) {
        EXPECT_NE(std::string(e.what()).find("shadow map's pass"), std::string::npos) << e.what();
        EXPECT_NE(
            std::string(e.what()).find("3.28e+04 texels, the cap (0.5 layers of this 256x256"),
            std::string::npos)
            << e.what();
    }
}

// Counts the checkpoints the drawing passes (one or more per triangle drawn).
int g_checkpoints = 0;
void count_checkpoint() {
    ++g_checkpoints;
}

TEST(ShadowsTest, APassOverItsCapIsRefusedBeforeAnyOfItIsDrawn) {
    const std::vector<MappedModel> floor = floor_scene(false);
    ShadowMapOptions options{.size = 256};
    options.max_samples = 0.5 * 256 * 256;
    g_checkpoints = 0;
    rl::set_checkpoint_hook(count_checkpoint);
    EXPECT_THROW(map_of(floor, {0, 1, 0}, options), pipeline::OverdrawError);
    const int drawing_refused = g_checkpoints;
    options.max_samples = kMaxShadowPassSamples;
    map_of(floor, {0, 1, 0}, options);
    rl::set_checkpoint_hook(nullptr);
    EXPECT_EQ(drawing_refused, 0);  // refused by its set-up's count, nothing drawn
    EXPECT_GT(g_checkpoints, 0);    // (the hook does see a drawing)
}

}  // namespace
