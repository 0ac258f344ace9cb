#include "scene.hpp"
#include "rasterlab/texture_files.hpp"

#include "rasterlab/transform.hpp"

namespace shading {

LitModel load_lit_model(const std::filesystem::path& path, const rl::mat4& transform, Output output,
                        Weighting weighting, std::vector<std::string>& warnings) {
    LitModel lit{pipeline::load_model(path, transform, warnings,
                                      output == Output::srgb ? &srgb_texels() : nullptr),
                 {},
                 0};
    lit.normals = corner_normals(lit.model.mesh, weighting, &lit.computed_normals);
    return lit;
}

std::vector<LitModel> default_scene(Output output, Weighting weighting,
                                    std::vector<std::string>& warnings) {
    std::vector<LitModel> models;
    const auto add = [&](const char* name, const rl::Trs& trs) {
        models.push_back(
            load_lit_model(rl::project_model(name), rl::compose(trs), output, weighting, warnings));
    };
    add("floor", {.scale = {1.7f, 1.7f, 1.7f}});
    add("globe",
        {.translation = {-0.8f, 0.9f, -0.25f}, .rotation = rl::axis_angle({0, 1, 0}, -40)});
    add("torus", {.translation = {0.8f, 0.92f, 0.35f}, .rotation = rl::axis_angle({0, 1, 0}, -25)});
    return models;
}

pipeline::ViewedScene<LitModel> load_scene(const pipeline::ViewOptions& view, Output output,
                                           Weighting weighting, int width, int height,
                                           std::vector<std::string>& warnings) {
    const rl::TexelBudget budget;  // for the textures of all the models together
    pipeline::ViewedScene<LitModel> scene;
    if (view.models.empty()) scene.models = default_scene(output, weighting, warnings);
    for (const std::string& path : view.models)
        scene.models.push_back(
            load_lit_model(path, rl::mat4::identity(), output, weighting, warnings));
    pipeline::Box box;
    for (const LitModel& m : scene.models)
        box.add(pipeline::bounds(m.model.mesh, m.model.transform));
    scene.camera = pipeline::view_camera(view, box, width, height, warnings);
    return scene;
}

std::optional<Placed> place(const LitModel& lit, const rl::mat4& view_projection,
                            const pipeline::Camera& camera, const Lighting<float>& lighting,
                            const textures::SamplerState& sampler, bool cull_objects,
                            pipeline::PipelineCounts& counts) {
    const pipeline::TexturedModel& m = lit.model;
    const rl::mat4 mvp = view_projection * m.transform;
    if (cull_objects && pipeline::outside_frustum(m.box, mvp)) {
        ++counts.objects_culled;
        return std::nullopt;
    }
    const std::optional<rl::mat3> normals = normal_matrix(m.transform);
    if (!normals) return std::nullopt;  // a flattened model (a zero scale) has no surface to light
    // Member by member: a trailing {} by position would zero `colour` (0.8
    // by default, the albedo without a texture).
    Uniforms u;
    u.model_matrix = m.transform;
    u.normal_matrix = *normals;
    u.model_view_projection = mvp;
    u.eye = camera.eye;
    u.lighting = lighting;
    u.texture = &m.texture;
    u.sampler = sampler;
    return Placed{u, Surface(m.mesh, lit.normals, m.transform)};
}

// [doc:render-lit]
pipeline::PipelineCounts render(const std::vector<LitModel>& models, const pipeline::Camera& camera,
                                const ShadingOptions& options, pipeline::ColourTarget& frame) {
    const float aspect = static_cast<float>(frame.width()) / static_cast<float>(frame.height());
    const rl::mat4 view_projection = pipeline::view_projection(camera, aspect);
    textures::SamplerState sampler;
    sampler.filter = options.filter;
    sampler.encoding = options.output == Output::srgb ? &srgb_texels() : nullptr;
    pipeline::PipelineCounts counts;
    for (const LitModel& lit : models)
        if (const std::optional<Placed> p = place(lit, view_projection, camera, options.lighting,
                                                  sampler, options.cull_objects, counts))
            counts += draw_model(options.model, p->surface, p->uniforms, frame, options.pipeline,
                                 options.output);
    return counts;
}
// [/doc:render-lit]

}  // namespace shading
