#include "scene.hpp"
#include "rasterlab/texture_files.hpp"

#include <new>
#include <stdexcept>

#include "rasterlab/transform.hpp"

namespace normal_mapping {

MappedModel load_mapped_model(const std::filesystem::path& path, const rl::mat4& transform,
                              TangentMethod method, std::vector<std::string>& warnings,
                              shading::Output output, std::optional<NormalMap> only) {
    // A loader names its own file when it runs out of memory; what is left
    // (the normals, the tangents, the maps' sRGB decoding) is named here.
    try {
        MappedModel m{
            shading::load_lit_model(path, transform, output, shading::Weighting::angle, warnings),
            {},
            {}};
        m.tangents = corner_tangents(m.lit.model.mesh, m.lit.normals, method);
        m.maps = load_maps(m.lit.model.mesh, warnings, only);
        return m;
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(path.string() +
                                 ": out of memory loading this model, its normals, tangents and "
                                 "maps (the image's size is not the cause: the model and its "
                                 "textures are)");
    }
}

std::vector<MappedModel> default_scene(TangentMethod method, std::vector<std::string>& warnings,
                                       shading::Output output, std::optional<NormalMap> only) {
    std::vector<MappedModel> models;
    const auto add = [&](const char* name, const rl::Trs& trs) {
        models.push_back(load_mapped_model(rl::project_model(name), rl::compose(trs), method,
                                           warnings, output, only));
    };
    add("floor", {.scale = {1.7f, 1.7f, 1.7f}});
    add("globe", {.translation = {-0.75f, 0.9f, -0.2f}, .rotation = rl::axis_angle({0, 1, 0}, 20)});
    add("crate", {.translation = {0.85f, 0.55f, 0.35f}, .rotation = rl::axis_angle({0, 1, 0}, 35)});
    return models;
}

pipeline::Box scene_box(const std::vector<MappedModel>& models) {
    pipeline::Box box;
    for (const MappedModel& m : models)
        box.add(pipeline::bounds(m.lit.model.mesh, m.lit.model.transform));
    return box;
}

pipeline::ViewedScene<MappedModel> load_scene(MappedView& request, int width, int height,
                                              std::vector<std::string>& warnings) {
    const rl::TexelBudget budget;  // for the textures of all the models together
    RenderOptions& options = request.options;
    options.lighting = shading::default_lighting(pipeline::light_direction(request.view));
    if (request.one_light) options.lighting.lights.resize(1);
    options.output = request.naive ? shading::Output::naive : shading::Output::srgb;
    pipeline::ViewedScene<MappedModel> scene;
    const std::optional<NormalMap> only =
        request.every_normal_map ? std::nullopt : std::optional(options.normal_map);
    if (request.view.models.empty())
        scene.models = default_scene(request.tangents, warnings, options.output, only);
    for (const std::string& path : request.view.models)  // as stored: the identity model matrix
        scene.models.push_back(load_mapped_model(path, rl::mat4::identity(), request.tangents,
                                                 warnings, options.output, only));
    scene.camera =
        pipeline::view_camera(request.view, scene_box(scene.models), width, height, warnings);
    return scene;
}

pipeline::ViewedScene<MappedModel> load_view(
    const pipeline::ViewOptions& view, TangentMethod tangents, int width, int height,
    std::vector<std::string>& warnings,
    const std::function<std::vector<MappedModel>(std::vector<std::string>&)>& default_models) {
    const rl::TexelBudget budget;  // for the textures of all the models together
    pipeline::ViewedScene<MappedModel> scene;
    if (view.models.empty()) scene.models = default_models(warnings);
    for (const std::string& path : view.models)  // as stored: the identity model matrix
        scene.models.push_back(load_mapped_model(path, rl::mat4::identity(), tangents, warnings));
    scene.camera = pipeline::view_camera(view, scene_box(scene.models), width, height, warnings);
    return scene;
}

void build_mip_levels(const std::vector<MappedModel>& models) {
    for (const MappedModel& m : models) {
        try {
            m.lit.model.texture.levels();
            for (const auto* map :
                 {&m.maps.tangent_normals, &m.maps.object_normals, &m.maps.specular})
                if (*map) (*map)->levels();
        } catch (const std::bad_alloc&) {
            throw std::runtime_error(m.lit.model.mesh.source.string() +
                                     ": out of memory building the mip levels of this model's "
                                     "textures (their size is the cause, not the image's)");
        }
    }
}

NormalMappedShader shader_for(const MappedModel& model, const shading::Placed& placed,
                              const RenderOptions& options) {
    return {placed.uniforms,
            model.maps,
            options.normal_map,
            options.specular,
            placed.surface.view.mirrored ? -1.0f : 1.0f,
            &model.tangents,
            options.filter};
}

// [doc:render-mapped]
pipeline::PipelineCounts render(const std::vector<MappedModel>& models,
                                const pipeline::Camera& camera, const RenderOptions& options,
                                pipeline::ColourTarget& frame) {
    const float aspect = static_cast<float>(frame.width()) / static_cast<float>(frame.height());
    const rl::mat4 view_projection = pipeline::view_projection(camera, aspect);
    textures::SamplerState sampler;  // the diffuse texture: sRGB unless naive
    sampler.filter = options.filter;
    sampler.encoding = options.output == shading::Output::srgb ? &shading::srgb_texels() : nullptr;
    pipeline::PipelineCounts counts;
    for (const MappedModel& m : models) {
        const std::optional<shading::Placed> p =
            shading::place(m.lit, view_projection, camera, options.lighting, sampler,
                           options.cull_objects, counts);
        if (!p) continue;
        counts += shading::draw(p->surface, shader_for(m, *p, options), frame, options.pipeline,
                                options.output);
    }
    return counts;
}
// [/doc:render-mapped]

}  // namespace normal_mapping
