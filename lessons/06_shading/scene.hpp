// Lesson 06's scene: lesson 05's models with a normal at every corner, lit
// by the shading model of your choice in linear light (or naively, to see
// the difference).
//
//   std::vector<shading::LitModel> models =
//       shading::default_scene(Output::srgb, Weighting::angle, warnings);
//   shading::render(models, camera, options, frame);
#pragma once

#include "05_perspective/scene.hpp"
#include "shaders.hpp"

namespace shading {

struct LitModel {
    pipeline::TexturedModel model;
    std::vector<rl::vec3> normals;     // 3 per face
    std::size_t computed_normals = 0;  // corners the OBJ gave no (usable) normal for
};

// Textures are decoded as sRGB when the output is sRGB (linear light), and
// read as plain bytes when it is naive.
LitModel load_lit_model(const std::filesystem::path& path, const rl::mat4& transform, Output output,
                        Weighting weighting, std::vector<std::string>& warnings);

// The default: the floor, the globe and the torus standing beside it.
std::vector<LitModel> default_scene(Output output, Weighting weighting,
                                    std::vector<std::string>& warnings);

// The default scene (or the view's models, as stored) and the camera framing
// it, as lesson 06's program draws them.
pipeline::ViewedScene<LitModel> load_scene(const pipeline::ViewOptions& view, Output output,
                                           Weighting weighting, int width, int height,
                                           std::vector<std::string>& warnings);

struct ShadingOptions {
    pipeline::PipelineOptions pipeline;
    bool cull_objects = true;  // skip a model whose bounding box is outside the frustum
    ShadingModel model = ShadingModel::blinn_phong;
    Output output = Output::srgb;
    Lighting<float> lighting = default_lighting(rl::vec3{0.3f, 0.5f, 1.0f});
    textures::Filter filter = textures::Filter::trilinear;
};

// A model as one frame draws it: its uniforms (model, normal and
// model-view-projection matrices, the eye, the lights, its texture sampled by
// `sampler`) and its surface. Empty when the model's box lies outside the
// frustum (counted in `counts`, if `cull_objects`) or its model matrix
// flattens it (no normal matrix, nothing to light).
struct Placed {
    Uniforms uniforms;
    Surface surface;
};
std::optional<Placed> place(const LitModel& lit, const rl::mat4& view_projection,
                            const pipeline::Camera& camera, const Lighting<float>& lighting,
                            const textures::SamplerState& sampler, bool cull_objects,
                            pipeline::PipelineCounts& counts);

pipeline::PipelineCounts render(const std::vector<LitModel>& models, const pipeline::Camera& camera,
                                const ShadingOptions& options, pipeline::ColourTarget& frame);

}  // namespace shading
