// The models in obj/ load without warnings and find every texture they name.
#include <gtest/gtest.h>

#include <cmath>

#include "rasterlab/mesh.hpp"
#include "rasterlab/texture_files.hpp"

namespace {

struct Asset {
    const char* name;
    std::vector<rl::TextureRole> textures;
};

void PrintTo(const Asset& asset, std::ostream* out) {
    *out << asset.name;
}

class ObjAsset : public testing::TestWithParam<Asset> {};

TEST_P(ObjAsset, LoadsCleanlyFitsTheUnitCubeAndHasItsTextures) {
    const Asset& asset = GetParam();
    std::vector<std::string> warnings;
    const rl::Mesh mesh = rl::load_obj(
        std::filesystem::path(RASTERLAB_OBJ_DIR) / (std::string(asset.name) + ".obj"), &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_GT(mesh.faces.size(), 0u);
    for (const rl::vec3& p : mesh.positions)
        for (int i = 0; i < 3; ++i) ASSERT_LE(std::abs(p[static_cast<std::size_t>(i)]), 1.0f);
    for (const rl::Face& t : mesh.faces)
        for (const rl::Corner& c : t.corners) {
            ASSERT_GE(c.uv, 0);
            ASSERT_GE(c.normal, 0);
        }
    for (rl::TextureRole role : asset.textures) {
        const rl::Texture texture = rl::load_texture(mesh, 0, role, warnings);
        EXPECT_FALSE(texture.is_default) << rl::texture_suffix(role);
        EXPECT_GE(texture.image.width(), 512);
    }
    EXPECT_TRUE(warnings.empty()) << warnings.front();
}

using R = rl::TextureRole;
INSTANTIATE_TEST_SUITE_P(
    Obj, ObjAsset,
    testing::Values(Asset{"globe", {R::diffuse, R::normal_tangent, R::normal_object, R::specular}},
                    Asset{"crate", {R::diffuse, R::normal_tangent, R::specular}},
                    Asset{"floor", {R::diffuse}},
                    Asset{"torus", {R::diffuse, R::normal_tangent, R::specular}},
                    Asset{"rock", {R::diffuse, R::normal_tangent}}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
