// OBJ loading: triangulation, index forms, and malformed files.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <cstdlib>

#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/mesh.hpp"
#include "rasterlab/texture_files.hpp"
#include "temp_dir.hpp"

namespace {

using rl::Mesh;

constexpr const char* kSquare = R"(# a unit square as one quad
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
f 1/1/1 2/2/1 3/3/1 4/4/1
)";

TEST(Mesh, QuadBecomesTwoTriangles) {
    const Mesh mesh = rl::parse_obj(kSquare, "", "square.obj");
    ASSERT_EQ(mesh.faces.size(), 2u);
    EXPECT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.uvs.size(), 4u);
    EXPECT_EQ(mesh.normals.size(), 1u);
    for (const rl::Face& t : mesh.faces)
        for (const rl::Corner& c : t.corners) {
            EXPECT_EQ(c.position, c.uv);  // the file pairs v i with vt i
            EXPECT_EQ(c.normal, 0);
        }
    // The two triangles cover the square: their areas add up to 1.
    float area = 0;
    for (const rl::Face& t : mesh.faces)
        area += 0.5f * rl::length(rl::cross(mesh.position(t, 1) - mesh.position(t, 0),
                                            mesh.position(t, 2) - mesh.position(t, 0)));
    EXPECT_FLOAT_EQ(area, 1.0f);
}

TEST(Mesh, PolygonsAreFannedIntoNMinusTwoTriangles) {
    const Mesh mesh = rl::parse_obj(R"(
v 1 0 0
v 0.309 0.951 0
v -0.809 0.588 0
v -0.809 -0.588 0
v 0.309 -0.951 0
f 1 2 3 4 5
)",
                                    "", "pentagon.obj");
    EXPECT_EQ(mesh.faces.size(), 3u);
}

TEST(Mesh, NegativeIndicesCountBackFromTheLatestVertex) {
    const Mesh mesh = rl::parse_obj(R"(
v 0 0 0
v 1 0 0
v 0 1 0
f -3 -2 -1
v 5 5 5
f 1 2 -1
)",
                                    "", "relative.obj");
    ASSERT_EQ(mesh.faces.size(), 2u);
    EXPECT_EQ(mesh.faces[0].corners[2].position, 2);
    EXPECT_EQ(mesh.faces[1].corners[2].position, 3);
}

TEST(Mesh, MissingUvsAndNormalsAreMinusOne) {
    const Mesh mesh =
        rl::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n", "", "no-uv.obj");
    ASSERT_EQ(mesh.faces.size(), 1u);
    EXPECT_EQ(mesh.faces[0].corners[0].uv, -1);
    EXPECT_EQ(mesh.faces[0].corners[0].normal, 0);
    const Mesh bare = rl::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "", "bare.obj");
    EXPECT_EQ(bare.faces[0].corners[1].normal, -1);
}

struct BadObj {
    const char* name;
    const char* text;
    const char* problem;
};

void PrintTo(const BadObj& bad, std::ostream* out) {
    *out << bad.name;
}

class MalformedObj : public testing::TestWithParam<BadObj> {};

TEST_P(MalformedObj, IsRefusedWithAClearMessage) {
    const BadObj& bad = GetParam();
    try {
        rl::parse_obj(bad.text, "", bad.name);
        FAIL() << "loaded a malformed OBJ";
    } catch (const rl::MeshError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(bad.name, 0), 0u) << message;
        EXPECT_NE(message.find(bad.problem), std::string::npos) << message;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Corpus, MalformedObj,
    testing::Values(
        BadObj{"index_zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
               "line 4: vertex index 0 is out of range"},
        BadObj{"index_too_big.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "out of range"},
        BadObj{"uv_too_big.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/4\n",
               "texture coordinate index 4 is out of range"},
        BadObj{"quad_too_big.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 7\n",
               "vertex index 7 is out of range (the file defines 3)"},
        BadObj{"two_vertices.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "three or more"},
        BadObj{"no_faces.obj", "v 0 0 0\nv 1 0 0\n", "holds no faces"},
        BadObj{"empty.obj", "", "holds no faces"},
        // Values tinyobjloader itself reads silently wrong.
        BadObj{"nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
               "line 1: 'nan' is not a finite number"},
        BadObj{"inf.obj", "v 0 0 0\nv 1 -inf 0\nv 0 1 0\nf 1 2 3\n",
               "line 2: '-inf' is not a finite number"},
        BadObj{"overflow.obj", "v 0 0 0\nv 1 0 0\nv 0 1 1e400\nf 1 2 3\n",
               "'1e400' is beyond the range of a float"},
        BadObj{"beyond_float.obj", "v 0 0 0\nv 1 0 0\nv 0 1 1e39\nf 1 2 3\n",
               "'1e39' is beyond the range of a float"},
        BadObj{"garbage.obj", "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n", "'zero' is not a number"},
        BadObj{"nan_normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 nan\nf 1 2 3\n",
               "line 4: 'nan' is not a finite number"},
        BadObj{"inf_uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt inf 0\nf 1 2 3\n",
               "line 4: 'inf' is not a finite number"},
        BadObj{"index_wraps.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967297\n",
               "vertex index 4294967297 is out of range"},
        BadObj{"index_20_digits.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 18446744073709551619\n",
               "vertex index 18446744073709551619 is out of range"},
        BadObj{"index_int_max_plus_one.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2147483648\n",
               "vertex index 2147483648 is out of range"},
        BadObj{"relative_too_far.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n",
               "line 3: vertex index -3 is out of range (the file defines 2 before "
               "this line)"},
        BadObj{"normal_index_wraps.obj",
               "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//4294967297\n",
               "normal index 4294967297 is out of range"},
        BadObj{"index_not_integer.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3.5\n",
               "vertex index '3.5' is not an integer"}),
    [](const auto& param_info) {
        std::string name = param_info.param.name;
        return name.substr(0, name.find('.'));
    });

// Texture coordinates far from 0 lose their digits when read (a float at
// 65536 steps by 1/128 of the texture): the load says so, naming the file
// and the step; coordinates in the hundreds are kept quietly.
TEST(Mesh, CoarseTextureCoordinatesAreWarnedOf) {
    const auto warnings_for = [](const char* vt) {
        std::vector<std::string> warnings;
        rl::parse_obj(std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\n") + vt + "\nf 1/1 2/1 3/1\n", "",
                      "far_uv.obj", &warnings);
        return warnings;
    };
    EXPECT_TRUE(warnings_for("vt 100.25 -300.5").empty());
    const std::vector<std::string> far = warnings_for("vt 65536.3 0.5");
    ASSERT_EQ(far.size(), 1u);
    EXPECT_NE(far[0].find("far_uv.obj: texture coordinates reach 65536.3"), std::string::npos)
        << far[0];
    EXPECT_NE(far[0].find("steps by 0.0078125 of the texture's width"), std::string::npos)
        << far[0];
}

// One budget of texels for all the textures of a scene: a texture past it
// is kept out (the neutral default, a warning naming the budget), the ones
// before it are kept, an inner budget joins the outer one, and without a
// budget nothing is counted.
TEST(Mesh, TexturesPastTheScenesTexelBudgetAreKeptOut) {
    const rl::Mesh crate = rl::load_obj(rl::project_model("crate"));
    std::vector<std::string> warnings;
    const rl::Texture alone = rl::load_texture(crate, 0, rl::TextureRole::diffuse, warnings);
    ASSERT_FALSE(alone.is_default);
    const auto texels = static_cast<std::uint64_t>(alone.image.width()) *
                        static_cast<std::uint64_t>(alone.image.height());
    {
        const rl::TexelBudget budget(texels + texels / 2);  // room for one, not two
        EXPECT_FALSE(rl::load_texture(crate, 0, rl::TextureRole::diffuse, warnings).is_default);
        const rl::TexelBudget inner;  // joins the outer budget
        EXPECT_EQ(rl::TexelBudget::current(), &budget);
        warnings.clear();
        EXPECT_TRUE(rl::load_texture(crate, 0, rl::TextureRole::diffuse, warnings).is_default);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_NE(warnings[0].find("past the budget of"), std::string::npos) << warnings[0];
        EXPECT_NE(warnings[0].find("for all the maps of all the models together"),
                  std::string::npos)
            << warnings[0];
    }
    EXPECT_EQ(rl::TexelBudget::current(), nullptr);
    EXPECT_FALSE(rl::load_texture(crate, 0, rl::TextureRole::diffuse, warnings).is_default);
}

TEST(Mesh, UnknownLinesAndCommentsDoNotStopLoading) {
    std::vector<std::string> warnings;
    const Mesh mesh = rl::parse_obj(
        "v 0 0 0 # origin\nv 1 0 0\r\nv +0 1 0\nfrobnicate 1 2 3\n\n# f 9 9 9\nf 1 2 3\n", "",
        "unknown.obj", &warnings);
    EXPECT_EQ(mesh.faces.size(), 1u);
}

TEST(Mesh, FacesBeyondTheVertexCapAreRefusedQuickly) {
    // tinyobjloader's ear clipping is quadratic: 10^5 vertices took 23 s.
    auto polygon = [](std::size_t n) {
        std::string text;
        for (std::size_t i = 0; i < n; ++i) {
            const double a = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
            text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
        }
        text += "f";
        for (std::size_t i = 1; i <= n; ++i) text += ' ', text += std::to_string(i);
        return text + "\n";
    };
    EXPECT_EQ(rl::parse_obj(polygon(rl::kMaxFaceVertices), "", "cap.obj").faces.size(),
              rl::kMaxFaceVertices - 2);
    try {
        rl::parse_obj(polygon(100000), "", "huge_face.obj");
        FAIL() << "loaded a face of 10^5 vertices";
    } catch (const rl::MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("more than the 4096"), std::string::npos) << e.what();
    }
}

TEST(Mesh, FilesOverTheSizeCapAreRefusedNamingTheOverride) {
    rl_test::TempDir dir;
    const auto path = dir.path() / "big.obj";
    rl_test::write_text(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" + std::string(2u << 20, '#'));
    ::setenv("RASTERLAB_MAX_OBJ_MB", "1", 1);
    try {
        rl::load_obj(path);
        ADD_FAILURE() << "loaded a file over the cap";
    } catch (const rl::MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("RASTERLAB_MAX_OBJ_MB"), std::string::npos)
            << e.what();
    }
    ::setenv("RASTERLAB_MAX_OBJ_MB", "3", 1);
    EXPECT_EQ(rl::load_obj(path).faces.size(), 1u);
    ::unsetenv("RASTERLAB_MAX_OBJ_MB");
    EXPECT_EQ(rl::max_obj_bytes(), rl::kDefaultMaxObjBytes);
}

TEST(Mesh, DevicesAsMaterialFilesAreWarnedAbout) {
    rl_test::TempDir dir;
    std::filesystem::create_symlink("/dev/zero", dir.path() / "zero.mtl");
    rl_test::write_text(dir.path() / "m.obj",
                        "mtllib zero.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    std::vector<std::string> warnings;
    EXPECT_EQ(rl::load_obj(dir.path() / "m.obj", &warnings).faces.size(), 1u);
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings[0].find("not a regular file"), std::string::npos) << warnings[0];
}

// Each MTL file is read once however many mtllib lines name it, and all of
// a model's MTL files together define at most kMaxMaterials (issue 17: a
// 74-byte OBJ naming a 16 MiB MTL of bare newmtl lines took 3.85 GB and
// 14 s, and each further mtllib of it as much again).
TEST(Mesh, MaterialFilesAreReadOnceAndBoundedTogether) {
    rl_test::TempDir dir;
    rl_test::write_text(dir.path() / "one.mtl", "newmtl red\nKd 1 0 0\n");
    std::string many;
    for (std::size_t i = 0; i <= rl::kMaxMaterials; ++i)
        many += "newmtl m", many += std::to_string(i), many += '\n';
    rl_test::write_text(dir.path() / "many.mtl", many);
    std::string obj;
    for (int i = 0; i < 1000; ++i) obj += "mtllib one.mtl\n";
    obj += "mtllib many.mtl\nmtllib many.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
    rl_test::write_text(dir.path() / "m.obj", obj);
    std::vector<std::string> warnings;
    const Mesh mesh = rl::load_obj(dir.path() / "m.obj", &warnings);
    EXPECT_EQ(mesh.materials.size(), 1u);  // one.mtl once; many.mtl skipped
    std::size_t skipped = 0;
    for (const std::string& w : warnings)
        skipped += w.find("materials, past the 4096") != std::string::npos;
    EXPECT_EQ(skipped, 1u);  // many.mtl is read (and skipped) once too
}

// 50 000 mtllib lines naming a missing file printed 100 001 warnings (issue
// 17): each distinct warning is printed once with its count, and after ten
// distinct ones the rest are counted.
TEST(Warnings, RepeatedOnesArePrintedOnceAndTheRestCounted) {
    std::vector<std::string> warnings(50000, "m.obj: material file x.mtl: cannot open");
    for (int i = 0; i < 30; ++i) warnings.push_back(std::to_string(i) + ": another warning");
    std::ostringstream captured;
    std::streambuf* const old = std::cerr.rdbuf(captured.rdbuf());
    rl::print_warnings("prog", warnings);
    std::cerr.rdbuf(old);
    const std::string text = captured.str();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 11) << text;
    EXPECT_NE(text.find("prog: warning: m.obj: material file x.mtl: cannot open (50000 times)\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("prog: warning: and 21 more warnings like these\n"), std::string::npos)
        << text;
}

TEST(Mesh, UnreadableFileIsNamed) {
    rl_test::TempDir dir;
    EXPECT_THROW(rl::load_obj(dir.path() / "absent.obj"), rl::MeshError);
    EXPECT_THROW(rl::load_obj(dir.path()), rl::MeshError);
}

TEST(Mesh, MaterialTexturesResolveAgainstTheObjFolder) {
    rl_test::TempDir dir;
    rl_test::write_text(dir.path() / "box.mtl",
                        "newmtl wood\nmap_Kd wood.png\nmap_Ks wood_s.png\nbump wood_n.png\n"
                        "norm wood_o.png\n");
    rl_test::write_text(dir.path() / "box.obj",
                        "mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl wood\nf 1 2 3\n");
    const Mesh mesh = rl::load_obj(dir.path() / "box.obj");
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.faces[0].material, 0);
    EXPECT_EQ(mesh.materials[0].diffuse, dir.path() / "wood.png");
    EXPECT_EQ(mesh.materials[0].specular, dir.path() / "wood_s.png");
    EXPECT_EQ(mesh.materials[0].normal_tangent, dir.path() / "wood_n.png");
    EXPECT_EQ(mesh.materials[0].normal_object, dir.path() / "wood_o.png");
}

TEST(Textures, FoundByTinyrendererNamesBesideTheObj) {
    rl_test::TempDir dir;
    rl_test::write_text(dir.path() / "head.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    rl::save_image(dir.path() / "head_diffuse.tga", rl::Image(2, 2, rl::Rgba{10, 20, 30, 255}));
    rl::save_image(dir.path() / "head_nm_tangent.png", rl::Image(2, 2, rl::Rgba{1, 2, 3, 255}));
    const Mesh mesh = rl::load_obj(dir.path() / "head.obj");

    std::vector<std::string> warnings;
    const rl::Texture diffuse = rl::load_texture(mesh, -1, rl::TextureRole::diffuse, warnings);
    EXPECT_FALSE(diffuse.is_default);
    EXPECT_EQ(diffuse.image.get(1, 1), (rl::Rgba{10, 20, 30, 255}));
    const rl::Texture normals =
        rl::load_texture(mesh, -1, rl::TextureRole::normal_tangent, warnings);
    EXPECT_EQ(normals.source, dir.path() / "head_nm_tangent.png");
    EXPECT_TRUE(warnings.empty());
}

TEST(Textures, MissingOrBrokenTexturesWarnAndFallBack) {
    rl_test::TempDir dir;
    rl_test::write_text(dir.path() / "m.mtl", "newmtl a\nmap_Kd gone.tga\n");
    rl_test::write_text(dir.path() / "m.obj",
                        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    rl_test::write_text(dir.path() / "m_spec.tga", "definitely not a TGA");
    const Mesh mesh = rl::load_obj(dir.path() / "m.obj");

    std::vector<std::string> warnings;
    const rl::Texture diffuse = rl::load_texture(mesh, 0, rl::TextureRole::diffuse, warnings);
    EXPECT_TRUE(diffuse.is_default);
    EXPECT_EQ(diffuse.image.get(0, 0), (rl::Rgba{255, 255, 255, 255}));
    const rl::Texture spec = rl::load_texture(mesh, 0, rl::TextureRole::specular, warnings);
    EXPECT_TRUE(spec.is_default);
    const rl::Texture nm = rl::load_texture(mesh, 0, rl::TextureRole::normal_tangent, warnings);
    EXPECT_EQ(nm.image.get(0, 0), (rl::Rgba{128, 128, 255, 255}));  // flat: (0, 0, 1)
    ASSERT_EQ(warnings.size(), 3u);
    EXPECT_NE(warnings[0].find("gone.tga"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[1].find("m_spec.tga"), std::string::npos) << warnings[1];
    EXPECT_NE(warnings[2].find("no nm_tangent texture"), std::string::npos) << warnings[2];
}

TEST(Textures, OtherFormatsThanPngJpegBmpAndTgaAreRefused) {
    // stb_image would decode these; rasterlab keeps its decoders out of reach.
    rl_test::TempDir dir;
    const std::pair<const char*, const char*> others[] = {
        {"a.gif", "GIF89a\x01\x00\x01\x00\x00\x00\x00;"},
        {"a.psd", "8BPS\x00\x01"},
        {"a.hdr", "#?RADIANCE\n"},
        {"a.ppm", "P6\n1 1\n255\n\x01\x02\x03"}};
    for (const auto& [name, bytes] : others) {
        rl_test::write_text(dir.path() / name, bytes);
        try {
            rl::load_image(dir.path() / name);
            ADD_FAILURE() << name << " was decoded";
        } catch (const rl::FileError& e) {
            EXPECT_NE(std::string(e.what()).find("not a PNG, JPEG, BMP or TGA file"),
                      std::string::npos)
                << e.what();
        }
    }
    rl::save_image(dir.path() / "fine.png", rl::Image(2, 2, rl::Rgba{1, 2, 3, 255}));
    EXPECT_EQ(rl::load_image(dir.path() / "fine.png").get(1, 1), (rl::Rgba{1, 2, 3, 255}));
}

TEST(Textures, DevicesFifosAndHugeFilesFallBackWithAWarning) {
    rl_test::TempDir dir;
    ASSERT_EQ(::mkfifo((dir.path() / "pipe.png").c_str(), 0600), 0);
    rl_test::write_text(dir.path() / "m.mtl",
                        "newmtl a\nmap_Kd /dev/zero\nmap_Ks pipe.png\nbump /dev/urandom\n");
    rl_test::write_text(dir.path() / "m.obj",
                        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    const Mesh mesh = rl::load_obj(dir.path() / "m.obj");
    std::vector<std::string> warnings;
    for (rl::TextureRole role :
         {rl::TextureRole::diffuse, rl::TextureRole::specular, rl::TextureRole::normal_tangent})
        EXPECT_TRUE(rl::load_texture(mesh, 0, role, warnings).is_default);
    ASSERT_EQ(warnings.size(), 3u);
    for (const std::string& w : warnings)
        EXPECT_NE(w.find("not a regular file"), std::string::npos) << w;
}

}  // namespace
