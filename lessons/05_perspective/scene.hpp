// Lesson 05's scene: textured models placed in the world, seen through a
// perspective camera, lit flat by lesson 02's Lambert term, drawn through the
// pipeline. Texture level of detail comes from each pixel's UV derivatives
// (or, to compare, lesson 04's per-triangle estimate).
//
//   std::vector<pipeline::TexturedModel> models = pipeline::default_scene(warnings);
//   pipeline::Camera camera = pipeline::frame_box(pipeline::scene_bounds(models), 50, 1);
//   pipeline::ColourTarget frame = pipeline::colour_target(800, 800);
//   pipeline::render(models, camera, {}, frame);
#pragma once

#include "rasterlab/named_enum.hpp"

#include <string>
#include <vector>

#include "02_triangles/flat_shading.hpp"
#include "04_textures/sampling.hpp"
#include "pipeline.hpp"
#include "view_options.hpp"

namespace pipeline {

struct TexturedModel {
    rl::Mesh mesh;
    rl::mat4 transform;  // model to world
    Box box;             // around the mesh, in model space
    textures::MipChain texture;
    std::string texture_name;  // for messages: the file, or "a plain default"
};

// Loads an OBJ and its diffuse texture (a plain one, with a warning, when it
// has none), placed by `transform`; the mip chain averages in `encoding`'s
// values (lesson 06 passes sRGB's; nullptr: the bytes).
TexturedModel load_model(const std::filesystem::path& path, const rl::mat4& transform,
                         std::vector<std::string>& warnings,
                         const textures::TexelEncoding* encoding = nullptr);

// The program's default: the floor (scaled 2.2x), the crate standing on it and
// the globe beside it, all from obj/.
std::vector<TexturedModel> default_scene(std::vector<std::string>& warnings);

Box scene_bounds(const std::vector<TexturedModel>& models);

// The camera a view asks for, framing `box` for a width x height image; the
// warning for a near / far ratio too small for depth precision, if any, is
// added to `warnings`. Throws std::invalid_argument naming the option for an
// unusable camera.
Camera view_camera(const ViewOptions& view, const Box& box, int width, int height,
                   std::vector<std::string>& warnings);

// What a lesson program draws: the lesson's default scene, or the view's
// models as stored (the identity model matrix), and the camera that frames
// them. Shared by the program and the Python module.
template <class Model>
struct ViewedScene {
    std::vector<Model> models;
    Camera camera;
};
ViewedScene<TexturedModel> load_scene(const ViewOptions& view, int width, int height,
                                      std::vector<std::string>& warnings);

// Where the mip level comes from: each pixel's own UV derivatives (exact
// under perspective), or one affine estimate per triangle as in lesson 04.
enum class LodMethod { pixel, triangle };
RASTERLAB_NAMED_ENUM(LodMethod, kLodMethods, {LodMethod::pixel, "pixel"},
                     {LodMethod::triangle, "triangle"});

struct RenderOptions {
    PipelineOptions pipeline;
    bool cull_objects = true;  // skip a model whose bounding box is outside the frustum
    textures::SamplerState sampler{textures::Filter::trilinear, textures::Wrap::repeat};
    LodMethod lod = LodMethod::pixel;
    rl::vec3 light = triangles::kDefaultLight;  // towards the light, world space
    bool lighting = true;
};

// The lesson's program: texture coordinates as the varyings, the texture
// sampled at each pixel and lit by the face's Lambert term.
struct TexturedProgram {
    rl::mat4 model_view_projection;
    const textures::MipChain& texture;
    textures::SamplerState sampler;
    LodMethod lod;
    const std::vector<float>& light;  // one per face
    using Varyings = rl::vec2;
    ClipVertex<rl::vec2> vertex(const MeshCorner& c) const {
        return {clip_position(model_view_projection, c.position()), c.uv()};
    }
    rl::Rgba fragment(const Fragment<rl::vec2>& f) const;
};

// Draws every model into the frame (width / height is the aspect ratio).
PipelineCounts render(const std::vector<TexturedModel>& models, const Camera& camera,
                      const RenderOptions& options, ColourTarget& frame);

}  // namespace pipeline
