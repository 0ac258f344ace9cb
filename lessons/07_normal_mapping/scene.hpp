// Lesson 07's scene: lesson 06's lit models with their tangent frames and
// maps, and the render of all of it.
//
//   auto models = normal_mapping::default_scene(TangentMethod::split, warnings);
//   normal_mapping::render(models, camera, options, frame);
#pragma once

#include <functional>

#include "06_shading/scene.hpp"
#include "normal_mapped.hpp"

namespace normal_mapping {

struct MappedModel {
    shading::LitModel lit;
    std::vector<rl::vec4> tangents;  // 3 per face
    Maps maps;
};

// The diffuse texture is decoded as sRGB unless the output is naive (as in
// lesson 06); `only` loads just the normal map a render will use.
MappedModel load_mapped_model(const std::filesystem::path& path, const rl::mat4& transform,
                              TangentMethod method, std::vector<std::string>& warnings,
                              shading::Output output = shading::Output::srgb,
                              std::optional<NormalMap> only = std::nullopt);

// The default: the globe (diffuse, tangent- and object-space normal maps,
// specular map) and the crate (mirrored UVs on two faces) on the floor.
std::vector<MappedModel> default_scene(TangentMethod method, std::vector<std::string>& warnings,
                                       shading::Output output = shading::Output::srgb,
                                       std::optional<NormalMap> only = std::nullopt);

struct RenderOptions {
    pipeline::PipelineOptions pipeline;
    bool cull_objects = true;  // skip a model whose bounding box is outside the frustum
    NormalMap normal_map = NormalMap::tangent;
    shading::Specular specular = shading::Specular::blinn_phong;
    shading::Lighting<float> lighting = shading::default_lighting(rl::vec3{0.3f, 0.5f, 1.0f});
    textures::Filter filter = textures::Filter::trilinear;  // every map's
    shading::Output output = shading::Output::srgb;         // naive: the bytes lit as if linear
};

// The shader that draws a placed model with these options (later lessons
// wrap it).
NormalMappedShader shader_for(const MappedModel& model, const shading::Placed& placed,
                              const RenderOptions& options);

// The box around every model, in world space.
pipeline::Box scene_box(const std::vector<MappedModel>& models);

// What lesson 07's program is asked for (by its command line, mapped_cli.hpp,
// or the Python module's keywords): the view, the render options, the tangent
// frames, sRGB or naive output, one light or two.
struct MappedView {
    pipeline::ViewOptions view;
    RenderOptions options;
    TangentMethod tangents = TangentMethod::split;
    bool naive = false, one_light = false;
    bool every_normal_map = false;  // load both maps, not just options.normal_map's (to switch)
};

// Sets the lighting and the output the view asks for in `request.options`,
// loads the default scene (or the view's models, as stored) and frames the
// camera for a width x height image. Throws std::invalid_argument (naming
// the option) for a camera it cannot use.
pipeline::ViewedScene<MappedModel> load_scene(MappedView& request, int width, int height,
                                              std::vector<std::string>& warnings);

// The models a view asks for: `default_models(warnings)` when it names
// none, else its files as stored (the identity model matrix, with
// `tangents`), and the camera framing them for a width x height image.
// Lessons 08 and 09 load their scenes with it.
pipeline::ViewedScene<MappedModel> load_view(
    const pipeline::ViewOptions& view, TangentMethod tangents, int width, int height,
    std::vector<std::string>& warnings,
    const std::function<std::vector<MappedModel>(std::vector<std::string>&)>& default_models);

// Builds every texture's smaller mip levels now (they are built on first
// use otherwise), so that a timed render of trilinear lookups times
// rendering alone.
void build_mip_levels(const std::vector<MappedModel>& models);

pipeline::PipelineCounts render(const std::vector<MappedModel>& models,
                                const pipeline::Camera& camera, const RenderOptions& options,
                                pipeline::ColourTarget& frame);

}  // namespace normal_mapping
