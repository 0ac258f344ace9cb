// Lesson 06's stability cases and pitfalls: sRGB round trips, mip chains in
// linear light, normals (degenerate faces, zero length, weighting, the normal
// matrix under non-uniform and negative scale), renormalising interpolated
// normals, grazing light and extreme exponents, flat varyings, discarding
// shaders, and linear light against the analytic sphere.
// docs/06_shading.md links each.
#include <gtest/gtest.h>

#include <cmath>

#include "03_zbuffer/hidden_surfaces.hpp"
#include "05_perspective/truths/tile_check.hpp"
#include "05_perspective/view_options.hpp"
#include "06_shading/scene.hpp"
#include "06_shading/truths/sphere_truth.hpp"
#include "rasterlab/texture_files.hpp"
#include "rasterlab/transform.hpp"

namespace {

using namespace shading;

TEST(ShadingTest, EverySrgbByteDecodesAndEncodesBackToItself) {
    for (int i = 0; i < 256; ++i) {
        const float linear = srgb_texels().value[static_cast<std::size_t>(i)];
        EXPECT_EQ(srgb_texels().to_byte(linear), i);
    }
    EXPECT_EQ(encode({0.5f, 0.5f, 0.5f}, Output::srgb).r, 188);  // half the light is byte 188
    EXPECT_EQ(encode({0.5f, 0.5f, 0.5f}, Output::naive).r, 128);
}

TEST(ShadingTest, MipChainsInLinearLightKeepTheCheckersBrightness) {
    std::vector<std::string> warnings;
    const rl::Mesh floor = rl::load_obj(rl::project_model("floor"), &warnings);
    const rl::Texture t = rl::load_texture(floor, 0, rl::TextureRole::diffuse, warnings);
    ASSERT_FALSE(t.is_default);
    const textures::MipChain bytes(t.image), linear(t.image, &srgb_texels());
    const rl::Rgba a = bytes.level(bytes.levels() - 1).get(0, 0);
    const rl::Rgba b = linear.level(linear.levels() - 1).get(0, 0);
    EXPECT_NEAR(a.r, 137, 1) << int(a.g) << " " << int(a.b);  // the byte average: too dark
    EXPECT_NEAR(b.r, 162, 1) << int(b.g) << " " << int(b.b);  // the light it reflects, on average
}

rl::Mesh parse(const std::string& obj) {
    return rl::parse_obj(obj, "", "test.obj");
}

TEST(ShadingTest, ZeroLengthNormalsFallBackToComputedOnes) {
    const rl::Mesh mesh = parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n");
    std::size_t computed = 0;
    const std::vector<rl::vec3> n = corner_normals(mesh, Weighting::angle, &computed);
    EXPECT_EQ(computed, 3u);
    for (const rl::vec3& v : n) EXPECT_NEAR(v.z, 1.0f, 1e-6f);
}

TEST(ShadingTest, DegenerateFacesAddNothingToVertexNormals) {
    // A unit square in z = 0, then a zero-area face on its corner, and a face
    // with a repeated vertex: no NaN, and the same normals as without them.
    const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
    for (Weighting w : kWeightings) {
        const std::vector<rl::vec3> clean = vertex_normals(parse(square), w);
        const std::vector<rl::vec3> dirty =
            vertex_normals(parse(square + "v 2 0 0\nf 1 2 5\nf 1 1 3\n"), w);
        for (int i = 0; i < 4; ++i) {
            EXPECT_TRUE(std::isfinite(dirty[static_cast<std::size_t>(i)].z)) << name(w);
            EXPECT_NEAR(dirty[static_cast<std::size_t>(i)].z, clean[static_cast<std::size_t>(i)].z,
                        1e-6f)
                << name(w);
        }
    }
}

// The corner of a cube: three faces, each a square cut into two triangles,
// either both touching the corner or only one of them. The angle-weighted
// normal is (1, 1, 1)/sqrt(3) either way; the area-weighted one depends on
// the cut.
TEST(ShadingTest, AngleWeightingDoesNotDependOnHowFacesAreCut) {
    const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\n";
    // Faces around vertex 1 (the origin), outward normals -x, -y, -z.
    const std::string through = "f 1 4 3\nf 1 3 2\nf 1 5 7\nf 1 7 4\nf 1 2 6\nf 1 6 5\n";
    const std::string beside = "f 1 4 2\nf 4 3 2\nf 1 5 7\nf 1 7 4\nf 1 2 6\nf 1 6 5\n";
    const float k = -1.0f / std::sqrt(3.0f);
    for (const std::string& faces : {through, beside}) {
        const rl::vec3 n = vertex_normals(parse(v + faces), Weighting::angle)[0];
        EXPECT_NEAR(n.x, k, 1e-5f);
        EXPECT_NEAR(n.y, k, 1e-5f);
        EXPECT_NEAR(n.z, k, 1e-5f);
    }
    const rl::vec3 a = vertex_normals(parse(v + through), Weighting::area)[0];
    const rl::vec3 b = vertex_normals(parse(v + beside), Weighting::area)[0];
    EXPECT_GT(rl::length(a - b), 0.01f);
}

// Largest angle (degrees) between a transformed normal and the true normal
// of the transformed sphere, over all vertices.
double worst_normal_error(const rl::mat4& model, bool use_normal_matrix) {
    const rl::Mesh sphere = uv_sphere(32);
    const rl::mat3 m = rl::linear_part(model);
    const rl::mat3 n = use_normal_matrix ? *normal_matrix(model) : m;
    const std::optional<rl::mat3> inverse = rl::inverse(m);
    double worst = 0;
    for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
        // The image of the unit sphere is {q : |M^-1 q| = 1}; its gradient
        // there, M^-T M^-1 q = M^-T p, is the true normal.
        const rl::vec3 truth = rl::normalize(rl::transpose(*inverse) * sphere.positions[i]);
        const rl::vec3 got = rl::normalize(n * sphere.normals[i]);
        worst = std::max(worst, std::acos(std::clamp(double(rl::dot(truth, got)), -1.0, 1.0)) *
                                    180 / 3.14159265358979);
    }
    return worst;
}

TEST(ShadingTest, NormalMatrixKeepsNormalsPerpendicularUnderNonUniformScale) {
    const rl::mat4 squash =
        rl::compose({.rotation = rl::axis_angle({0, 0, 1}, 30), .scale = {2.0f, 0.5f, 1.0f}});
    EXPECT_LT(worst_normal_error(squash, true), 0.1);    // float rounding
    EXPECT_GT(worst_normal_error(squash, false), 30.0);  // the model matrix itself: wrong
}

// A camera 4 units up the z axis, looking at the unit sphere at the origin.
pipeline::Camera camera_on_z_axis() {
    pipeline::Camera camera;
    camera.eye = {0, 0, 4};
    camera.near = 1;
    camera.far = 10;
    return camera;
}

TEST(ShadingTest, NormalsStillPointOutUnderNegativeScale) {
    const rl::mat4 mirror = rl::compose({.scale = {-1.5f, 1.0f, 0.7f}});
    EXPECT_LT(worst_normal_error(mirror, true), 0.1);
    // Drawn: a mirrored model turns its faces clockwise; the surface knows,
    // so front faces are still drawn and the lit side still faces the light.
    const rl::Mesh sphere = uv_sphere(32);
    const std::vector<rl::vec3> normals = corner_normals(sphere, Weighting::angle);
    const pipeline::Camera camera = camera_on_z_axis();
    const rl::mat4 mvp = pipeline::view_projection(camera, 1.0f) * mirror;
    Uniforms u{.model_matrix = mirror,
               .normal_matrix = *normal_matrix(mirror),
               .model_view_projection = mvp,
               .eye = camera.eye,
               .lighting = default_lighting(rl::vec3{1, 0, 0.3f})};
    u.lighting.lights.resize(1);
    pipeline::ColourTarget frame = pipeline::colour_target(64, 64);
    const pipeline::PipelineCounts counts = draw_model(
        ShadingModel::blinn_phong, Surface(sphere, normals, mirror), u, frame, {}, Output::srgb);
    EXPECT_GT(counts.shaded, 1000u);
    // Lit from +x: the right half is brighter than the left.
    EXPECT_GT(frame.colour().get(44, 32).r, frame.colour().get(20, 32).r + 40);
}

TEST(ShadingTest, AModelWithoutATextureIsDrawnInItsColour) {
    // Uniforms named member by member leave `colour` at its default, 0.8
    // grey; a trailing {} by position zeroed it (latent while every model
    // had a texture). Lit head-on by one white light, no ambient and no
    // specular, seen from the light: the nearest point's light is the albedo.
    const rl::Mesh sphere = uv_sphere(64);
    const std::vector<rl::vec3> normals = corner_normals(sphere, Weighting::angle);
    const pipeline::Camera camera = camera_on_z_axis();
    Lighting<float> lighting;
    lighting.lights.push_back({{0, 0, 1}, {1, 1, 1}});
    lighting.ambient = {};
    lighting.specular = {};
    const Uniforms u{.model_matrix = rl::mat4::identity(),
                     .normal_matrix = rl::mat3::identity(),
                     .model_view_projection = pipeline::view_projection(camera, 1.0f),
                     .eye = camera.eye,
                     .lighting = lighting};
    pipeline::ColourTarget frame = pipeline::colour_target(65, 65);
    draw_model(ShadingModel::phong, Surface(sphere, normals), u, frame, {}, Output::srgb);
    const rl::Rgba centre = frame.colour().get(32, 32);
    const double grey = 255.0 * linear_to_srgb(0.8);
    EXPECT_NEAR(centre.r, grey, 2);
    EXPECT_EQ(centre.g, centre.r);
    EXPECT_EQ(centre.b, centre.r);
}

TEST(ShadingTest, InterpolatedNormalsAreRenormalised) {
    // Halfway between two unit normals 90 degrees apart, the interpolated
    // normal has length 0.71: lit as it is, the light would dim by 29%.
    const Lighting<float> lighting = [] {
        Lighting<float> l;
        l.lights.push_back({rl::normalize(rl::vec3{1, 1, 0}), {1, 1, 1}});
        l.ambient = {};
        return l;
    }();
    Uniforms u{.model_matrix = rl::mat4::identity(),
               .normal_matrix = rl::mat3::identity(),
               .model_view_projection = rl::mat4::identity(),
               .eye = {0, 0, 5},
               .lighting = lighting,
               .colour = {1, 1, 1}};
    const PhongShader shader{u, Specular::blinn_phong};
    const pipeline::TriangleSetup<PhongShader::Varyings> setup{};
    const PhongShader::Varyings halfway{
        {0, 0, 0}, rl::vec3{1, 0, 0} * 0.5f + rl::vec3{0, 1, 0} * 0.5f, {}};
    const rl::vec3 c = shader.fragment({0, 0, 0.5f, halfway, 1.0f, &setup});
    const float expected = 1.0f;  // n = l: full diffuse light (plus the highlight, >= 0)
    EXPECT_GE(c.x, expected - 1e-5f);
}

TEST(ShadingTest, GrazingLightAndExtremeExponentsStayFinite) {
    for (float shininess : {0.0f, 1.0f, 1e6f}) {
        Lighting<float> l = default_lighting(rl::vec3{1, 1e-7f, 0});  // grazing a +y normal
        l.shininess = shininess;
        for (Specular s : {Specular::phong, Specular::blinn_phong}) {
            const rl::vec3 c =
                reflected(l, {0, 1, 0}, rl::normalize(rl::vec3{0, 1, 1}), {0.5f, 0.5f, 0.5f}, s);
            EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
            EXPECT_GE(c.x, 0.0f);
        }
    }
    // Exponent 0: the highlight is the whole specular colour wherever lit.
    Lighting<float> l;
    l.lights.push_back({{0, 0, 1}, {1, 1, 1}});
    l.shininess = 0;
    l.ambient = {};
    EXPECT_NEAR(reflected(l, {0, 0, 1}, {1, 0, 0}, {0, 0, 0}, Specular::phong).x, l.specular.x,
                1e-6f);
}

// Where the reflected light points away from the eye (r . v < 0) there is
// no highlight: the base of pow is clamped to 0 first. Unclamped, an even
// exponent turns the negative base into a spurious highlight and a
// fractional one into NaN (issue 18: dropping the clamp passed every test,
// whose r . v was +7e-8 and whose exponents were integers).
TEST(ShadingTest, NoHighlightWhereTheReflectionPointsAwayFromTheEye) {
    for (float shininess : {32.0f, 32.5f, 2.0f}) {
        Lighting<float> l;
        l.lights.push_back({rl::normalize(rl::vec3{1, 0, 1}), {1, 1, 1}});
        l.shininess = shininess;
        l.ambient = {};
        // n = +z, l = (1, 0, 1) / sqrt 2: r = (-1, 0, 1) / sqrt 2, and r . v = -0.71 for v = +x.
        const Reflection<float> r = reflection(l, {0, 0, 1}, {1, 0, 0}, Specular::phong);
        EXPECT_EQ(r.specular.x, 0.0f) << shininess;
        EXPECT_TRUE(std::isfinite(r.diffuse.x)) << shininess;
        EXPECT_NEAR(r.diffuse.x, std::sqrt(0.5f), 1e-6f);  // the diffuse light is all there is
    }
}

// A direction is a direction: --light 1 1 1 and --light 3 3 3 light alike,
// the fill light included (issue 17: its direction was built from the raw
// vector, and the two differed by up to 40 levels).
TEST(ShadingTest, TheLightsDependOnlyOnTheLightsDirectionNotItsLength) {
    for (const rl::vec3& d : {rl::vec3{1, 1, 1}, rl::vec3{0.3f, 0.5f, 1}, rl::vec3{-2, 0.1f, 4}}) {
        const Lighting<float> unit = default_lighting(rl::normalize(d)),
                              longer = default_lighting(d * 3.0f),
                              shorter = default_lighting(d * 0.01f);
        ASSERT_EQ(unit.lights.size(), longer.lights.size());
        for (std::size_t i = 0; i < unit.lights.size(); ++i)
            for (std::size_t k = 0; k < 3; ++k) {
                EXPECT_NEAR(longer.lights[i].direction[k], unit.lights[i].direction[k], 1e-6f) << d;
                EXPECT_NEAR(shorter.lights[i].direction[k], unit.lights[i].direction[k], 1e-6f)
                    << d;
            }
    }
}

// A shader that discards every pixel must leave the depth buffer alone, so
// that what lies behind is still drawn (the late depth test).
struct DiscardEverything {
    rl::mat4 mvp;
    using Varyings = float;
    static constexpr bool may_discard = true;
    pipeline::ClipVertex<float> vertex(const SurfaceCorner& in) const {
        return {pipeline::clip_position(mvp, in.position()), 0.0f};
    }
    std::optional<rl::vec3> fragment(const pipeline::Fragment<float>&) const {
        return std::nullopt;
    }
};

TEST(ShadingTest, DiscardedPixelsLeaveTheDepthBufferAlone) {
    const rl::Mesh quad = parse("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    const std::vector<rl::vec3> normals = corner_normals(quad, Weighting::area);
    const rl::mat4 near = rl::compose({.translation = {0, 0, 0.5f}});
    const rl::mat4 far = rl::compose({.translation = {0, 0, -0.5f}});
    const rl::mat4 ortho = rl::mat4::identity();
    pipeline::ColourTarget frame = pipeline::colour_target(16, 16);
    const Surface surface{quad, normals};
    draw(surface, DiscardEverything{ortho * near}, frame, {}, Output::naive);
    const pipeline::PipelineCounts counts =
        draw(surface, UnlitShader{ortho * far, {1, 0, 0}}, frame, {}, Output::naive);
    EXPECT_EQ(counts.shaded, 256u);
    EXPECT_EQ(frame.colour().get(8, 8).r, 255);
}

TEST(ShadingTest, LinearLightIsCloserToTheTruthThanNaiveBytes) {
    pipeline::Camera camera;
    camera.eye = {0, 0, 3.2f};
    camera.fov_y = 45;
    camera.near = 1;
    camera.far = 10;
    const Lighting<float> lighting = default_lighting(rl::vec3{0.5f, 0.6f, 1.0f});
    const rl::vec3 albedo{0.8f, 0.35f, 0.2f};
    const rl::Image truth =
        sphere_truth(camera, 96, 96, lighting, albedo, Specular::blinn_phong, rl::kBackground);
    const rl::Mesh sphere = uv_sphere(64);
    const std::vector<rl::vec3> normals = corner_normals(sphere, Weighting::angle);
    double error[2];
    for (Output o : kOutputs) {
        Uniforms u{rl::mat4::identity(),
                   rl::mat3::identity(),
                   pipeline::view_projection(camera, 1.0f),
                   camera.eye,
                   lighting,
                   nullptr,
                   {},
                   albedo};
        if (o == Output::naive)
            u.colour = {linear_to_srgb(albedo.x), linear_to_srgb(albedo.y),
                        linear_to_srgb(albedo.z)};
        pipeline::ColourTarget frame = pipeline::colour_target(96, 96);
        draw_model(ShadingModel::blinn_phong, Surface{sphere, normals}, u, frame, {}, o);
        error[o == Output::srgb ? 0 : 1] =
            compare_spheres(truth, frame.colour(), rl::kBackground).interior_rmse;
    }
    EXPECT_LT(error[0], 3.0);
    EXPECT_GT(error[1], 4 * error[0]);
}

TEST(ShadingTest, DefaultSceneTileByTileEqualsOneDraw) {
    std::vector<std::string> warnings;
    const std::vector<LitModel> models = default_scene(Output::srgb, Weighting::angle, warnings);
    pipeline::Box box;
    for (const LitModel& m : models) box.add(pipeline::bounds(m.model.mesh, m.model.transform));
    const pipeline::Camera camera = pipeline::resolve_camera({}, box, 1.5f);
    EXPECT_TRUE(pipeline::tiles_add_up(300, 200, 64, [&](pipeline::ColourTarget& frame, auto tile) {
        ShadingOptions options;
        options.pipeline.tile = tile;
        render(models, camera, options, frame);
    }));
}

}  // namespace
