// Finding and loading the texture files that go with a mesh (the sampling of
// textures is lesson 04's, in lessons/04_textures/sampling.hpp).
//
//   rl::TexelBudget budget;  // for the whole scene: 2^28 texels at most
//   const rl::Texture normals =
//       rl::load_texture(mesh, face.material, rl::TextureRole::normal_tangent, warnings);
//   if (normals.is_default) { /* no map found: the neutral 1x1 stand-in */ }
//   const auto spec = rl::find_texture(mesh, face.material, rl::TextureRole::specular);
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rasterlab/image.hpp"
#include "rasterlab/mesh.hpp"

namespace rl {

enum class TextureRole { diffuse, normal_tangent, normal_object, specular };

// The file-name suffix tinyrenderer's models use for each role: "diffuse",
// "nm_tangent", "nm", "spec".
const char* texture_suffix(TextureRole role);

struct Texture {
    Image image;
    std::filesystem::path source;  // empty for a default
    bool is_default = false;
};

// Where the texture for `role` is: the file the material's MTL entry names,
// or else `<obj stem>_<suffix>` beside the OBJ with .tga, .png or .jpg.
// Empty when neither exists.
std::optional<std::filesystem::path> find_texture(const Mesh& mesh, int material, TextureRole role);

// A 1x1 stand-in that leaves shading as if the map were absent: white
// diffuse, flat normal (0, 0, 1) in tangent space, no specular. An
// object-space normal map has no neutral value; its default is marked
// is_default so that lessons fall back to the interpolated normal.
Texture default_texture(TextureRole role);

// The texels the textures of one scene may hold together: 2^28, 1 GiB as
// 8-bit RGBA before the lessons' own copies (mip levels, decoded sRGB,
// lesson 12's packing), so that a few huge maps cannot take gigabytes (four
// 16384² maps of 3.1 MB on disk cost lesson 12 9.8 GB). A scene loader opens
// a TexelBudget for its models (an inner one joins the outer); load_texture()
// counts each texture it keeps against it, and past it keeps the neutral
// default with a warning naming the budget.
inline constexpr std::uint64_t kMaxSceneTexels = std::uint64_t{1} << 28;

class TexelBudget {
  public:
    explicit TexelBudget(std::uint64_t texels = kMaxSceneTexels);
    ~TexelBudget();
    TexelBudget(const TexelBudget&) = delete;
    TexelBudget& operator=(const TexelBudget&) = delete;
    // Counts `texels` if they fit, and says whether they did.
    bool take(std::uint64_t texels);
    std::uint64_t limit() const { return limit_; }
    std::uint64_t used() const { return used_; }
    // The budget open on this thread, or nullptr.
    static TexelBudget* current();

  private:
    std::uint64_t limit_, used_ = 0;
    bool opened_ = false;  // false: it joined an outer budget
};

// Finds and loads a texture. A missing or unreadable file is not fatal: it
// adds a warning and returns default_texture(role), so rendering goes on;
// so does a texture past the open TexelBudget.
Texture load_texture(const Mesh& mesh, int material, TextureRole role,
                     std::vector<std::string>& warnings);

}  // namespace rl
