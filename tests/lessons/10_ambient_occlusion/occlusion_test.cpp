// Lesson 10's tests: the screen's geometry, the horizon integral, every
// method on a lone floor (no self-occlusion, except Crytek's measured
// half), the range check against a far object's edge, the worked example
// (a floor point beside a wall) against its closed form, the truth, and
// extreme radii and views.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "10_ambient_occlusion/lab/tinyrenderer_ssao.hpp"
#include "10_ambient_occlusion/truths/ao_truth.hpp"
#include "rasterlab/transform.hpp"

namespace {

using namespace occlusion;
using normal_mapping::MappedModel;

constexpr float kPi = std::numbers::pi_v<float>;

MappedModel model(const char* name, const rl::Trs& trs) {
    std::vector<std::string> warnings;
    return normal_mapping::load_mapped_model(rl::project_model(name), rl::compose(trs),
                                             normal_mapping::TangentMethod::split, warnings);
}

// The floor: the square [-s, s]^2 of y = 0, facing +y.
MappedModel floor_of(float s) {
    return model("floor", {.scale = {s, s, s}});
}

// A wall: the plane x = d facing -x (towards the origin), 2s by 2s.
MappedModel wall_at(float d, float s) {
    return model(
        "floor",
        {.translation = {d, s, 0}, .rotation = rl::axis_angle({0, 0, 1}, 90), .scale = {s, s, s}});
}

pipeline::Camera camera_at(rl::vec3 eye, rl::vec3 target) {
    pipeline::Camera c;
    c.eye = eye, c.target = target, c.fov_y = 50, c.near = 0.1f, c.far = 100;
    return c;
}

struct Rendered {
    GBuffer g;
    Screen screen;
};

Rendered gbuffer_of(const std::vector<MappedModel>& models, const pipeline::Camera& camera,
                    int size) {
    shadows::ShadowOptions options;
    shadows::set_lights(options, pipeline::ViewOptions{}, false);
    const shadows::ShadowMap map = shadows::shadow_map_for(models, camera, 1, options);
    return {render_gbuffer(models, camera, options, map, size, size), Screen(camera, size, size)};
}

// The occlusion of a floor point at distance d from a wall, radius r: the
// rays that meet the wall within r are those whose direction leans towards
// it by more than d / r; cosine-weighted directions fall evenly on the unit
// disc below them, so the closed share is the disc's segment beyond c = d / r.
double floor_beside_wall(double d, double r) {
    const double c = std::min(d / r, 1.0);
    return 1 - (std::acos(c) - c * std::sqrt(1 - c * c)) / std::numbers::pi;
}

TEST(Screen, APixelsPointProjectsBackOntoIt) {
    const std::vector<MappedModel> scene = {floor_of(3)};
    const Rendered r = gbuffer_of(scene, camera_at({0.5f, 2, 3}, {0, 0, 0}), 64);
    int seen = 0;
    for (int y = 0; y < 64; y += 5)
        for (int x = 0; x < 64; x += 5) {
            const std::optional<rl::vec3> p = r.screen.position(r.g, x, y);
            if (!p) continue;
            ++seen;
            EXPECT_NEAR(p->y, 0.0f, 2e-4f);  // on the floor
            const rl::vec3 w = r.screen.project(*p);
            EXPECT_NEAR(w.x, x + 0.5f, 2e-3f);
            EXPECT_NEAR(w.y, y + 0.5f, 2e-3f);
        }
    EXPECT_GT(seen, 100);
    EXPECT_FALSE(r.screen.position(r.g, 0, 63));  // the sky above the horizon
}

TEST(SliceVisibility, IsTheCosineIntegralInClosedForm) {
    EXPECT_NEAR(slice_visibility(-kPi / 2, kPi / 2, 0), 1.0f, 1e-6f);
    EXPECT_NEAR(slice_visibility(0, 0, 0), 0.0f, 1e-6f);
    for (auto [h1, h2, gamma] :
         {std::tuple{-1.2f, 0.7f, 0.3f}, {-0.2f, 1.5f, -0.6f}, {-1.5f, 0.1f, 1.0f}}) {
        double sum = 0;
        const int n = 20000;
        for (int i = 0; i < n; ++i) {
            const double t = h1 + (h2 - h1) * (i + 0.5) / n;
            sum += std::cos(t - gamma) * std::fabs(std::sin(t)) * (h2 - h1) / n;
        }
        EXPECT_NEAR(slice_visibility(h1, h2, gamma), sum, 1e-4);
    }
}

TEST(HorizonSteps, SpendEverySampleUpToFourStepsASide) {
    for (auto [samples, slices, steps] :
         {std::tuple{1, 1, 1}, {4, 1, 2}, {8, 1, 4}, {16, 2, 4}, {128, 16, 4}}) {
        EXPECT_EQ(horizon_steps(samples).slices, slices) << samples;
        EXPECT_EQ(horizon_steps(samples).steps, steps) << samples;
    }
}

TEST(Rotation, TheTileHoldsEachTurnOnce) {
    std::vector<int> seen(16, 0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            ++seen[static_cast<std::size_t>(rotation_at(x, y) * 16)];
            EXPECT_EQ(rotation_at(x, y), rotation_at(x + 4, y + 8));
        }
    for (int count : seen) EXPECT_EQ(count, 1);
}

// A lone floor hides nothing from itself: the hemisphere and horizon
// methods find it open at every pixel (depth precision and the slant of the
// view included). Crytek's ball is half under the floor: it reads about half
// closed, which is that method's flaw, measured here, not hidden.
TEST(Occlusion, ALoneFloorIsOpen) {
    const std::vector<MappedModel> scene = {floor_of(4)};
    const Rendered r = gbuffer_of(scene, camera_at({0.3f, 1.5f, 3.5f}, {0, 0, 0}), 96);
    for (AoMethod m : kScreenSpaceAoMethods) {
        AoOptions o;
        o.method = m, o.samples = 16, o.radius = 0.5f;
        const rl::FloatImage ao = ambient_occlusion(r.g, r.screen, o);
        double sum = 0, lowest = 1;
        int pixels = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x) {
                if (!r.screen.position(r.g, x, y)) continue;
                sum += ao.get(x, y);
                lowest = std::min(lowest, static_cast<double>(ao.get(x, y)));
                ++pixels;
            }
        ASSERT_GT(pixels, 1000);
        if (m == AoMethod::crytek) {
            EXPECT_NEAR(sum / pixels, 0.5, 0.1) << name(m);
        } else {
            EXPECT_GE(lowest, 0.99) << name(m);
        }
    }
}

// With lesson 09's white furnace (radiance 1 from everywhere), E(n) = pi
// for every normal, so a point's light is its albedo times its occlusion,
// whatever the normal: the occlusion darkens the environment's diffuse
// light and nothing else (lesson 08's key light is left out).
TEST(EnvironmentLight, AWhiteSkyGivesAlbedoTimesTheOcclusion) {
    std::vector<std::string> warnings;
    const EnvironmentLighting white("white", warnings);
    SceneOptions options;
    options.environment = &white.light();
    const std::vector<MappedModel> scene = {
        floor_of(2), model("globe", {.translation = {0, 0.5f, 0}, .scale = {0.5f, 0.5f, 0.5f}})};
    const pipeline::Camera camera = camera_at({0.3f, 1.5f, 3}, {0, 0.3f, 0});
    const Frame f = render(scene, camera, options, 48, 48);
    int pixels = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x) {
            if (!(f.g.depth()->get(x, y) < f.g.depth_state.clear)) continue;
            const rl::vec3 albedo = f.g.colour<kAlbedo>().get(x, y);
            for (float open : {1.0f, 0.25f}) {
                const rl::vec3 l = light_at(f, options, x, y, open);
                ASSERT_NEAR(l.x, albedo.x * open, 0.01f * albedo.x + 1e-6f) << x << "," << y;
                ASSERT_NEAR(l.z, albedo.z * open, 0.01f * albedo.z + 1e-6f) << x << "," << y;
            }
            ++pixels;
        }
    EXPECT_GT(pixels, 400);
    // The environment behind the models needs the rays of the frame's screen.
    EXPECT_THROW(picture(f, options), std::invalid_argument);
    const Screen screen(camera, 48, 48);
    EXPECT_NO_THROW(picture(f, options, Show::image, &screen));
}

// The lab's port of tinyrenderer's SSAO, on the same lone floor: its box
// has no normal, so half of it lies under the floor and is hidden, and its
// darkening maps that half to smoothstep(1 - 0.4 / 2) = 0.896, not to 1.
// The page's anchor relies on the port doing what tinyrenderer does; the
// same seed gives the same picture, and where no model is it is open.
TEST(TinyrendererPort, ALoneFloorReadsNineTenths) {
    const std::vector<MappedModel> scene = {floor_of(4)};
    const Rendered r = gbuffer_of(scene, camera_at({0.3f, 1.5f, 3.5f}, {0, 0, 0}), 96);
    const Surfaces surfaces(r.g, r.screen);
    const rl::FloatImage ao = tinyrenderer_ssao(surfaces);
    double sum = 0;
    int pixels = 0;
    for (int y = 16; y < 56; ++y)  // the floor's near middle: the box stays on it
        for (int x = 24; x < 72; ++x) {
            ASSERT_TRUE(r.screen.position(r.g, x, y));
            sum += ao.get(x, y);
            ++pixels;
        }
    const float half = 1 - 0.4f * 0.5f;
    EXPECT_NEAR(sum / pixels, half * half * (3 - 2 * half), 0.02);
    const rl::FloatImage again = tinyrenderer_ssao(surfaces);
    int sky = 0;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 96; ++x) {
            ASSERT_EQ(ao.get(x, y), again.get(x, y));
            if (r.screen.position(r.g, x, y)) continue;
            EXPECT_EQ(ao.get(x, y), 1.0f);
            ++sky;
        }
    EXPECT_GT(sky, 1000);
}

// The worked example: a floor point 0.25 from a wall, radius 0.5, is open
// 1 - (acos(0.5) - 0.5 sqrt(0.75)) / pi = 0.8045. The truth's rays find
// it; the horizon method, from the depth buffer, comes close.
TEST(Occlusion, TheWorkedExampleAFloorBesideAWall) {
    EXPECT_NEAR(floor_beside_wall(0.25, 0.5), 0.8045, 5e-5);
    const std::vector<MappedModel> scene = {floor_of(4), wall_at(1, 4)};
    const RayTracedAo truth(scene);
    for (double d : {0.1, 0.25, 0.4, 0.6})
        EXPECT_NEAR(truth.at({1 - d, 0, 0.3}, {0, 1, 0}, 0.5, 4096, 7), floor_beside_wall(d, 0.5),
                    0.01)
            << d;
    // Looking along the wall from beside it: the floor's pixels at each distance.
    const pipeline::Camera camera = camera_at({-1.5f, 1.8f, 3.0f}, {0.6f, 0, 0});
    const Rendered r = gbuffer_of(scene, camera, 160);
    AoOptions o;
    o.method = AoMethod::horizon, o.samples = 64, o.radius = 0.5f, o.blur = 0;
    const rl::FloatImage ao = ambient_occlusion(r.g, r.screen, o);
    int checked = 0;
    for (int y = 0; y < 160; ++y)
        for (int x = 0; x < 160; ++x) {
            const std::optional<rl::vec3> p = r.screen.position(r.g, x, y);
            if (!p || std::fabs(p->y) > 1e-3f || p->x > 0.98f || std::fabs(p->z) > 1) continue;
            EXPECT_NEAR(ao.get(x, y), floor_beside_wall(1 - p->x, 0.5), 0.12) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, 500);
}

// A ball far in front of the floor covers part of it on screen. The floor
// next to the ball's outline is open (the ball is metres away), but its
// samples land behind the ball in the depth buffer. The hemisphere
// method's range check ignores what is that far; Crytek's, without one,
// darkens a halo around the outline.
TEST(Occlusion, TheRangeCheckKeepsAFarEdgeOffTheFloor) {
    const std::vector<MappedModel> scene = {
        floor_of(6), model("globe", {.translation = {0, 1.6f, 2.2f}, .scale = {0.4f, 0.4f, 0.4f}})};
    const pipeline::Camera camera = camera_at({0, 2, 4}, {0, 0, -1});
    const Rendered r = gbuffer_of(scene, camera, 128);
    const RayTracedAo truth(scene);
    const TruthFrame t = truth_frame(truth, camera, 128, 128, 0.5, 256);
    AoOptions o;
    o.samples = 32, o.radius = 0.5f, o.blur = 0;
    double error[2] = {0, 0};
    int pixels = 0;
    for (int i = 0; i < 2; ++i) {
        o.method = i == 0 ? AoMethod::hemisphere : AoMethod::crytek;
        const rl::FloatImage ao = ambient_occlusion(r.g, r.screen, o);
        for (int y = 1; y < 127; ++y)
            for (int x = 1; x < 127; ++x) {
                // Floor pixels with the ball's pixel beside them.
                const std::optional<rl::vec3> p = r.screen.position(r.g, x, y);
                if (!p || p->y > 1e-3f) continue;
                bool beside = false;
                for (auto [a, b] : {std::pair{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}}) {
                    const std::optional<rl::vec3> q = r.screen.position(r.g, a, b);
                    beside |= q && q->y > 0.5f;
                }
                if (!beside) continue;
                error[i] += std::fabs(ao.get(x, y) - t.ao.get(x, y));
                if (i == 0) ++pixels;
            }
    }
    ASSERT_GT(pixels, 40);
    EXPECT_LT(error[0] / pixels, 0.05);  // hemisphere: open, as the truth says
    EXPECT_GT(error[1] / pixels, 0.2);   // crytek: a dark halo
}

// A radius far larger than the scene, one far smaller than a pixel, a view
// from inside the ball, a view along the floor: every method gives shares
// in [0, 1], no NaN, and the lone floor's truth is exactly open.
TEST(Occlusion, ExtremeRadiiAndViewsGiveSharesInZeroToOne) {
    const std::vector<MappedModel> scene = {
        floor_of(2), model("globe", {.translation = {0, 0.5f, 0}, .scale = {0.5f, 0.5f, 0.5f}})};
    for (const pipeline::Camera& camera :
         {camera_at({0.3f, 1.5f, 3}, {0, 0, 0}), camera_at({0, 0.5f, 0.1f}, {0, 0.5f, -1}),
          camera_at({-3, 0.01f, 0}, {0, 0.01f, 0})})
        for (float radius : {1e-4f, 0.5f, 1e3f}) {
            const Rendered r = gbuffer_of(scene, camera, 48);
            for (AoMethod m : kScreenSpaceAoMethods) {
                AoOptions o;
                o.method = m, o.samples = 8, o.radius = radius;
                const rl::FloatImage ao = ambient_occlusion(r.g, r.screen, o);
                for (int y = 0; y < 48; ++y)
                    for (int x = 0; x < 48; ++x) {
                        const float a = ao.get(x, y);
                        ASSERT_TRUE(a >= 0 && a <= 1) << name(m) << " " << radius << ": " << a;
                    }
            }
        }
    const RayTracedAo lone({floor_of(2)});
    EXPECT_EQ(lone.at({0.3, 0, -0.2}, {0, 1, 0}, 10, 256, 3), 1.0);
}

// A wall seen exactly edge-on covers at most a pixel's column of the depth
// buffer (its plane holds the eye): every method still gives shares in
// [0, 1] and no NaN beside it, and the floor far from it stays open.
TEST(Occlusion, AWallSeenEdgeOnGivesSharesInZeroToOne) {
    const std::vector<MappedModel> scene = {floor_of(2), wall_at(0.25f, 0.5f)};
    const Rendered r = gbuffer_of(scene, camera_at({0.25f, 0.5f, 3}, {0.25f, 0.3f, 0}), 64);
    for (AoMethod m : kScreenSpaceAoMethods) {
        AoOptions o;
        o.method = m, o.samples = 16;
        const rl::FloatImage ao = ambient_occlusion(r.g, r.screen, o);
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const float a = ao.get(x, y);
                ASSERT_TRUE(a >= 0 && a <= 1) << name(m) << " at " << x << "," << y << ": " << a;
            }
        if (m == AoMethod::crytek) continue;
        // Floor pixels a metre or more from the wall's plane, on either side, are open.
        int far = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x)
                if (const std::optional<rl::vec3> p = r.screen.position(r.g, x, y))
                    if (std::fabs(p->x - 0.25f) > 1 && p->y < 1e-3f) {
                        EXPECT_GE(ao.get(x, y), 0.95f) << name(m) << " at " << x << "," << y;
                        ++far;
                    }
        EXPECT_GT(far, 100) << name(m);
    }
}

TEST(Occlusion, RefusesOptionsOutsideTheirRanges) {
    for (AoOptions o :
         {AoOptions{.samples = 0}, AoOptions{.samples = kMaxAoSamples + 1}, AoOptions{.radius = 0},
          AoOptions{.radius = NAN}, AoOptions{.blur = kMaxBlurRadius + 1}, AoOptions{.blur = -1}})
        EXPECT_THROW(check(o), std::invalid_argument);
}

}  // namespace

// Baking knows only its vertices. Beside the wall, the floor's vertices on
// the wall's line are half closed (the wall fills half of what they see,
// cosine-weighted; a quarter at its ends), the next ones, a metre away, are open; a point 0.25
// from the wall, between them, gets their blend, not its own 0.80.
TEST(Baked, KnowsOnlyItsVertices) {
    const std::vector<MappedModel> scene = {floor_of(4), wall_at(1, 4)};
    const RayTracedAo rays(scene);
    const BakedAo baked = bake_vertex_ao(scene, rays, 0.5, 1024);
    ASSERT_EQ(baked.corners.size(), 2u);
    const rl::Mesh& floor = scene[0].lit.model.mesh;
    int on_line = 0;
    for (std::size_t f = 0; f < floor.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const rl::vec3 q = 4.0f * floor.position(floor.faces[f], k);  // the model's scale
            const float x = q.x, a = baked.corners[0][3 * f + static_cast<std::size_t>(k)];
            if (std::fabs(q.z) > 3.9f) continue;  // the wall's ends: a quarter closed
            if (std::fabs(x - 1) < 1e-4f) {
                EXPECT_NEAR(a, 0.5, 0.03);
                ++on_line;
            } else {
                EXPECT_EQ(a, 1.0f) << x;
            }
        }
    EXPECT_GT(on_line, 8);
    // Drawn: the floor 0.25 from the wall reads the blend of 1 and 0.5.
    const pipeline::Camera camera = camera_at({-1.5f, 1.8f, 3.0f}, {0.6f, 0, 0});
    shadows::ShadowOptions options;
    shadows::set_lights(options, pipeline::ViewOptions{}, false);
    const shadows::ShadowMap map = shadows::shadow_map_for(scene, camera, 1, options);
    const rl::FloatImage ao = draw_baked(scene, camera, options, map, baked, 160, 160);
    const Rendered r = gbuffer_of(scene, camera, 160);
    int checked = 0;
    for (int y = 0; y < 160; ++y)
        for (int x = 0; x < 160; ++x) {
            const std::optional<rl::vec3> p = r.screen.position(r.g, x, y);
            if (!p || std::fabs(p->y) > 1e-3f || p->x < 0.02f || p->x > 0.98f ||
                std::fabs(p->z) > 2.9f)
                continue;
            EXPECT_NEAR(ao.get(x, y), 1 - 0.5 * p->x, 0.03) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, 200);
    EXPECT_NEAR(1 - 0.5 * 0.75, 0.625, 1e-9);  // against the truth's 0.8045 at 0.25
}

TEST(Baked, RefusesRaysOutsideTheCaps) {
    const std::vector<MappedModel> scene = {floor_of(1)};
    const RayTracedAo rays(scene);
    EXPECT_THROW(bake_vertex_ao(scene, rays, 0.5, 0), std::invalid_argument);
    EXPECT_THROW(bake_vertex_ao(scene, rays, 0.5, kMaxBakeRays + 1), std::invalid_argument);
    // 700 floors of 128 faces: 268800 corners x 4096 rays is past 2^30,
    // refused before a ray is cast.
    const std::vector<MappedModel> many(700, scene[0]);
    EXPECT_THROW(bake_vertex_ao(many, rays, 0.5, kMaxBakeRays), std::invalid_argument);
    EXPECT_NO_THROW(bake_vertex_ao(scene, rays, 0.5, 16));
}
