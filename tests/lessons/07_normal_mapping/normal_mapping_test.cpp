// Lesson 07's stability cases and pitfalls: the globe's two normal maps
// agree under the OpenGL convention (and not with green flipped), mirrored
// UVs give left-handed frames, zero-area UV triangles and poles get finite
// frames, a model without UVs ignores its maps with a warning.
// docs/07_normal_mapping.md links each.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "05_perspective/truths/tile_check.hpp"
#include "05_perspective/view_options.hpp"
#include "07_normal_mapping/scene.hpp"

namespace {

using namespace normal_mapping;

// The varyings at the centre of face f: its corners' normals, tangents,
// handedness and texture coordinates averaged.
NormalMappedShader::Varyings face_centre(const MappedModel& globe, std::size_t f) {
    const rl::Mesh& mesh = globe.lit.model.mesh;
    NormalMappedShader::Varyings v{};
    for (std::size_t k = 0; k < 3; ++k) {
        v.normal += globe.lit.normals[3 * f + k] * (1.0f / 3);
        v.tangent += globe.tangents[3 * f + k].xyz() * (1.0f / 3);
        v.handedness += globe.tangents[3 * f + k].w / 3;
        v.uv += mesh.uvs[static_cast<std::size_t>(mesh.faces[f].corners[k].uv)] * (1.0f / 3);
    }
    return v;
}

double degrees_between(rl::vec3 a, rl::vec3 b) {
    return std::acos(std::clamp(double(rl::dot(a, b)), -1.0, 1.0)) * 180 / 3.14159265358979;
}

// Uniforms of an untransformed model seen from (0, 0, 5): object space is
// world space, so a shader's normals can be compared as they come.
shading::Uniforms identity_uniforms() {
    return {rl::mat4::identity(),
            rl::mat3::identity(),
            rl::mat4::identity(),
            {0, 0, 5},
            shading::default_lighting(rl::vec3{0, 0, 1}),
            nullptr,
            {},
            {}};
}

MappedModel load_globe(TangentMethod method) {
    std::vector<std::string> warnings;
    return load_mapped_model(rl::project_model("globe"), rl::mat4::identity(), method, warnings);
}

// Mean angle (degrees) between the object-space map and the tangent-space
// map turned into object space through the corner frames, at each face's
// centre; `flip_green` reads the tangent map with the DirectX convention.
double maps_disagree(TangentMethod method, bool flip_green) {
    const MappedModel globe = load_globe(method);
    textures::SamplerState sampler;  // bilinear, bytes as they are
    double sum = 0;
    for (std::size_t f = 0; f < globe.lit.model.mesh.faces.size(); ++f) {
        const NormalMappedShader::Varyings v = face_centre(globe, f);
        const rl::vec3 n = rl::normalize(v.normal);
        const rl::vec3 tangent = rl::normalize(v.tangent - n * rl::dot(n, v.tangent));
        const rl::vec3 b = rl::cross(n, tangent) * (v.handedness < 0 ? -1.0f : 1.0f);
        rl::vec3 m =
            decode_normal(textures::sample(*globe.maps.tangent_normals, v.uv, {}, sampler));
        if (flip_green) m.y = -m.y;
        const rl::vec3 from_tangent = rl::normalize(tangent * m.x + b * m.y + n * m.z);
        const rl::vec3 from_object = rl::normalize(
            decode_normal(textures::sample(*globe.maps.object_normals, v.uv, {}, sampler)));
        sum += degrees_between(from_tangent, from_object);
    }
    return sum / static_cast<double>(globe.lit.model.mesh.faces.size());
}

TEST(NormalMappingTest, TheGlobesTwoMapsAgreeUnderTheOpenGlConvention) {
    EXPECT_LT(maps_disagree(TangentMethod::split, false), 0.5);
    EXPECT_GT(maps_disagree(TangentMethod::split, true), 1.0);  // DirectX's green: they disagree
}

// The same agreement through the shader itself: NormalMappedShader::normal_at
// with the tangent-space map and with the object-space map gives the same
// normal at every face's centre of the globe. (Issue 18: the test above
// decodes the maps itself, so flipping green in normal_at passed it.)
TEST(NormalMappingTest, TheShadersTangentAndObjectSpaceNormalsAgreeOnTheGlobe) {
    const MappedModel globe = load_globe(TangentMethod::split);
    const shading::Uniforms u = identity_uniforms();
    NormalMappedShader tangent{
        u, globe.maps, NormalMap::tangent, shading::Specular::blinn_phong, 1.0f, &globe.tangents};
    NormalMappedShader object = tangent;
    object.source = NormalMap::object;
    tangent.map_filter = object.map_filter = textures::Filter::bilinear;
    double sum = 0;
    pipeline::Fragment<NormalMappedShader::Varyings> f{};
    const std::size_t faces = globe.lit.model.mesh.faces.size();
    for (std::size_t i = 0; i < faces; ++i) {
        f.varyings = face_centre(globe, i);
        sum += degrees_between(tangent.normal_at(f, {}, {}), object.normal_at(f, {}, {}));
    }
    EXPECT_LT(sum / static_cast<double>(faces), 0.5);
}

TEST(NormalMappingTest, MirroredUvsGetLeftHandedFrames) {
    // The crate's -x and -y faces have mirrored u: w = -1 there, +1 elsewhere.
    std::vector<std::string> warnings;
    const MappedModel crate = load_mapped_model(rl::project_model("crate"), rl::mat4::identity(),
                                                TangentMethod::split, warnings);
    const rl::Mesh& mesh = crate.lit.model.mesh;
    int left = 0, right = 0;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const FaceFrame frame = face_frame(mesh, mesh.faces[f]);
        ASSERT_TRUE(frame.valid);
        const rl::vec3 n = crate.lit.normals[3 * f];
        const bool mirrored = rl::dot(rl::cross(frame.tangent, frame.bitangent), n) < 0;
        for (std::size_t k = 0; k < 3; ++k) {
            const rl::vec4 t = crate.tangents[3 * f + k];
            EXPECT_EQ(t.w < 0, mirrored) << "face " << f;
            // B = w cross(N, T) points along +v, like the face's own bitangent.
            EXPECT_GT(
                rl::dot(rl::cross(crate.lit.normals[3 * f + k], t.xyz()) * t.w, frame.bitangent),
                0.0f);
        }
        (mirrored ? left : right)++;
    }
    EXPECT_EQ(left, 4);  // two faces of two triangles each
    EXPECT_EQ(right, 8);
}

void expect_orthonormal(const std::vector<rl::vec4>& t, const std::vector<rl::vec3>& n) {
    for (std::size_t i = 0; i < t.size(); ++i) {
        const rl::vec3 tangent = t[i].xyz();
        ASSERT_TRUE(std::isfinite(tangent.x) && std::isfinite(tangent.y) &&
                    std::isfinite(tangent.z));
        EXPECT_NEAR(rl::length(tangent), 1.0f, 1e-4f) << i;
        EXPECT_NEAR(rl::dot(tangent, n[i]), 0.0f, 1e-4f) << i;
        EXPECT_TRUE(t[i].w == 1.0f || t[i].w == -1.0f);
    }
}

// A flat strip of two squares sharing the edge x = 1 (its positions, not
// its UVs): the left square mapped with u = x, v = y; the right one with
// UVs `right` (per vertex 2, 5, 6, 3 of the strip).
rl::Mesh two_islands(const char* right) {
    return rl::parse_obj(std::string("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
                                     "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n") +
                             right + "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 2/5 5/6 6/7\nf 2/5 6/7 3/8\n",
                         "", "islands.obj");
}

// The largest angle (degrees) between a corner's frame and its own face's
// exact frame (the mesh is flat, so each face's frame is the truth), 180
// where the handedness is wrong.
double largest_frame_error(const rl::Mesh& mesh, TangentMethod method) {
    const std::vector<rl::vec3> normals = shading::corner_normals(mesh, shading::Weighting::angle);
    const std::vector<rl::vec4> t = corner_tangents(mesh, normals, method);
    double largest = 0;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const FaceFrame exact = face_frame(mesh, mesh.faces[f]);
        for (std::size_t k = 0; k < 3; ++k) {
            const rl::vec4 c = t[3 * f + k];
            const float w = rl::dot(rl::cross(normals[3 * f + k], exact.tangent), exact.bitangent);
            const double cosine = std::clamp(double(rl::dot(c.xyz(), exact.tangent)), -1.0, 1.0);
            largest = std::max(largest,
                               (c.w < 0) != (w < 0) ? 180.0 : std::acos(cosine) * 180 / 3.14159265);
        }
    }
    return largest;
}

// Where two UV islands meet on shared positions, split frames keep each
// island's own frame and averaged ones do not: a mirrored island (u runs the
// other way) and one turned 90 degrees (issue 17: the split test passed a
// T + B dot product of exactly 0 there, the frames were averaged, 45 degrees
// wrong at the seam). Issue 18: making split frames behave like unsplit ones
// passed every test before this one.
TEST(NormalMappingTest, SplitFramesKeepEachIslandsFrameAtMirroredAndTurnedSeams) {
    const rl::Mesh mirrored = two_islands("vt 1 0\nvt 0 0\nvt 0 1\nvt 1 1\n");  // u = 2 - x
    const rl::Mesh turned = two_islands("vt 0 1\nvt 0 0\nvt 1 0\nvt 1 1\n");    // u = y, v = 2 - x
    for (const rl::Mesh* mesh : {&mirrored, &turned}) {
        EXPECT_LT(largest_frame_error(*mesh, TangentMethod::split), 0.1);
        EXPECT_GT(largest_frame_error(*mesh, TangentMethod::vertex), 10.0);
        EXPECT_LT(largest_frame_error(*mesh, TangentMethod::face), 0.1);
    }
}

// One face far past a float's squared range (edges of 3e19: the cross
// product is 1e39) sharing a vertex with an ordinary face: every normal and
// frame stays finite and unit, and the ordinary face keeps its own normal at
// its other corners (issue 17: the shared vertex's normal was infinite and
// the neighbour drawn unlit). A UV of 2.6e34 likewise keeps the frames finite.
TEST(NormalMappingTest, AHugeFaceOrUvCannotPoisonItsNeighboursNormalsOrFrames) {
    const rl::Mesh mesh = rl::parse_obj(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -3e19 0 0\nv 0 -3e19 1e19\n"
        "vt 0 0\nvt 1 0\nvt 0 1\nvt 2.6e34 0\n"
        "f 1/1 2/2 3/3\nf 1/1 4/4 5/3\n",
        "", "huge.obj");
    for (shading::Weighting w : {shading::Weighting::angle, shading::Weighting::area}) {
        const std::vector<rl::vec3> normals = shading::corner_normals(mesh, w);
        for (const rl::vec3& n : normals) EXPECT_NEAR(rl::length(n), 1.0f, 1e-5f) << n;
        EXPECT_NEAR(normals[1].z, 1.0f, 1e-6f);  // the ordinary face's own corners
        EXPECT_NEAR(normals[2].z, 1.0f, 1e-6f);
        for (TangentMethod m : kTangentMethods)
            expect_orthonormal(corner_tangents(mesh, normals, m), normals);
    }
}

TEST(NormalMappingTest, ZeroAreaUvTrianglesGetAFallbackFrame) {
    const rl::Mesh mesh = rl::parse_obj(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n", "", "flat.obj");
    EXPECT_FALSE(face_frame(mesh, mesh.faces[0]).valid);
    const std::vector<rl::vec3> normals = shading::corner_normals(mesh, shading::Weighting::angle);
    for (TangentMethod m : kTangentMethods)
        expect_orthonormal(corner_tangents(mesh, normals, m), normals);
}

// docs/07_normal_mapping.md, "A worked example": every number of it.
TEST(WorkedExample, TheTangentFrameAndTexelOfThePage) {
    const rl::Mesh mesh = rl::parse_obj(
        "v 0 0 0\nv 2 0 0\nv 0 0 -1\nvt 0 0\nvt 0.5 0\nvt 0 0.25\n"
        "vn 0 1 0\nf 1/1/1 2/2/1 3/3/1\n",
        "", "worked.obj");
    const FaceFrame frame = face_frame(mesh, mesh.faces[0]);
    ASSERT_TRUE(frame.valid);
    EXPECT_NEAR(rl::length(frame.tangent - rl::vec3{1, 0, 0}), 0, 1e-6f) << frame.tangent;
    EXPECT_NEAR(rl::length(frame.bitangent - rl::vec3{0, 0, -1}), 0, 1e-6f) << frame.bitangent;
    const std::vector<rl::vec3> normals = shading::corner_normals(mesh, shading::Weighting::angle);
    const rl::vec4 t = corner_tangents(mesh, normals, TangentMethod::split)[0];
    EXPECT_EQ(t, (rl::vec4{1, 0, 0, 1}));  // T' and w = +1: right-handed
    const rl::vec3 m = decode_normal({191 / 255.0f, 128 / 255.0f, 221 / 255.0f, 1});
    EXPECT_NEAR(m.x, 0.498f, 5e-4f);
    EXPECT_NEAR(m.y, 0.004f, 5e-4f);
    EXPECT_NEAR(m.z, 0.733f, 5e-4f);
    EXPECT_NEAR(rl::length(m), 0.886f, 5e-4f);
    // The shader's sum (normal_mapped.hpp): B rebuilt as w (N x T').
    const rl::vec3 n{0, 1, 0}, tangent{t.x, t.y, t.z}, b = rl::cross(n, tangent) * t.w;
    const rl::vec3 world = (tangent * m.x + b * m.y + n * m.z) / rl::length(m);
    EXPECT_NEAR(world.x, 0.562f, 5e-4f);
    EXPECT_NEAR(world.y, 0.827f, 5e-4f);
    EXPECT_NEAR(world.z, -0.004f, 5e-4f);
    EXPECT_NEAR(std::acos(world.y) * 180 / 3.14159265f, 34.2f, 0.05f);
    const rl::vec3 light = rl::normalize(rl::vec3{0.3f, 0.5f, 1});
    EXPECT_NEAR(rl::dot(world, light), 0.499f, 5e-4f);
    EXPECT_NEAR(rl::dot(n, light), 0.432f, 5e-4f);
}

TEST(NormalMappingTest, SeamsAndPolesOfTheGlobeGetFiniteOrthonormalFrames) {
    std::vector<std::string> warnings;
    const rl::Mesh globe = rl::load_obj(rl::project_model("globe"), &warnings);
    const std::vector<rl::vec3> normals = shading::corner_normals(globe, shading::Weighting::angle);
    for (TangentMethod m : kTangentMethods)
        expect_orthonormal(corner_tangents(globe, normals, m), normals);
}

TEST(NormalMappingTest, AModelWithoutNormalsGetsComputedNormalsAndFrames) {
    const rl::Mesh mesh = rl::parse_obj(
        "v 0 0 0\nv 1 0 0\nv 1 1 0.2\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n",
        "", "no_normals.obj");
    std::size_t computed = 0;
    const std::vector<rl::vec3> normals =
        shading::corner_normals(mesh, shading::Weighting::angle, &computed);
    EXPECT_EQ(computed, 6u);
    for (TangentMethod m : kTangentMethods)
        expect_orthonormal(corner_tangents(mesh, normals, m), normals);
}

TEST(NormalMappingTest, AModelWithoutUvsIgnoresItsMapsWithAWarning) {
    const auto dir = std::filesystem::temp_directory_path() / "rasterlab_07_no_uvs";
    std::filesystem::create_directories(dir);
    {
        std::ofstream obj(dir / "plain.obj");
        obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    }
    std::filesystem::copy_file(std::filesystem::path(RASTERLAB_OBJ_DIR) / "crate_nm_tangent.tga",
                               dir / "plain_nm_tangent.tga",
                               std::filesystem::copy_options::overwrite_existing);
    std::vector<std::string> warnings;
    const MappedModel m =
        load_mapped_model(dir / "plain.obj", rl::mat4::identity(), TangentMethod::split, warnings);
    EXPECT_FALSE(m.maps.tangent_normals.has_value());
    bool warned = false;
    for (const std::string& w : warnings)
        warned |= w.find("no texture coordinates") != std::string::npos;
    EXPECT_TRUE(warned);
    std::filesystem::remove_all(dir);
}

// A map texel at the middle grey (a 127/128 checker filtered to its
// average decodes to 0) holds no direction: the interpolated normal is kept,
// in both kinds of map, rather than the pixel going unlit or lit at random.
TEST(NormalMappingTest, AMapNormalTooShortToHoldADirectionKeepsTheInterpolatedNormal) {
    rl::Image checker(2, 2, rl::Rgba{127, 127, 127, 255});
    checker.at(1, 0) = checker.at(0, 1) = rl::Rgba{128, 128, 128, 255};
    Maps maps;
    maps.tangent_normals = textures::MipChain(checker);
    maps.object_normals = textures::MipChain(checker);
    const shading::Uniforms u = identity_uniforms();
    const std::vector<rl::vec4> tangents(3, rl::vec4{1, 0, 0, 1});
    pipeline::Fragment<NormalMappedShader::Varyings> f{};
    f.varyings = {{0, 0, 0}, {0, 0.6f, 0.8f}, {1, 0, 0}, 1, {0.5f, 0.5f}};  // between the 4 texels
    for (NormalMap source : {NormalMap::tangent, NormalMap::object}) {
        NormalMappedShader shader{u, maps, source, shading::Specular::blinn_phong, 1.0f, &tangents};
        shader.map_filter = textures::Filter::bilinear;
        const rl::vec3 n = shader.normal_at(f, {}, {});
        EXPECT_NEAR(n.y, 0.6f, 1e-6f) << name(source);
        EXPECT_NEAR(n.z, 0.8f, 1e-6f) << name(source);
    }
}

TEST(NormalMappingTest, DefaultSceneTileByTileEqualsOneDraw) {
    std::vector<std::string> warnings;
    const std::vector<MappedModel> models = default_scene(TangentMethod::split, warnings);
    pipeline::Box box;
    for (const MappedModel& m : models)
        box.add(pipeline::bounds(m.lit.model.mesh, m.lit.model.transform));
    const pipeline::Camera camera = pipeline::resolve_camera({}, box, 1.5f);
    EXPECT_TRUE(pipeline::tiles_add_up(300, 200, 64, [&](pipeline::ColourTarget& frame, auto tile) {
        RenderOptions options;
        options.pipeline.tile = tile;
        render(models, camera, options, frame);
    }));
}

}  // namespace
