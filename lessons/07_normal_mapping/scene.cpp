#include "scene.hpp"

#include "rasterlab/transform.hpp"

namespace normal_mapping {

MappedModel load_mapped_model(const std::filesystem::path& path, const rl::mat4& transform,
                              TangentMethod method, std::vector<std::string>& warnings) {
    MappedModel m{shading::load_lit_model(path, transform, shading::Output::srgb,
                                          shading::Weighting::angle, warnings),
                  {},
                  {}};
    m.tangents = corner_tangents(m.lit.model.mesh, m.lit.normals, method);
    m.maps = load_maps(m.lit.model.mesh, warnings);
    return m;
}

std::vector<MappedModel> default_scene(TangentMethod method, std::vector<std::string>& warnings) {
    std::vector<MappedModel> models;
    const auto add = [&](const char* name, const rl::Trs& trs) {
        models.push_back(
            load_mapped_model(rl::project_model(name), rl::compose(trs), method, warnings));
    };
    add("floor", {.scale = {1.7f, 1.7f, 1.7f}});
    add("globe", {.translation = {-0.75f, 0.9f, -0.2f}, .rotation = rl::axis_angle({0, 1, 0}, 20)});
    add("crate", {.translation = {0.85f, 0.55f, 0.35f}, .rotation = rl::axis_angle({0, 1, 0}, 35)});
    return models;
}

// [doc:render-mapped]
perspective::PipelineCounts render(const std::vector<MappedModel>& models,
                                   const perspective::Camera& camera, const RenderOptions& options,
                                   zbuffer::Frame& frame) {
    const float aspect =
        static_cast<float>(frame.colour.width()) / static_cast<float>(frame.colour.height());
    const rl::mat4 view_projection = perspective::view_projection(camera, aspect);
    perspective::PipelineCounts counts;
    for (const MappedModel& m : models) {
        const perspective::Model& model = m.lit.model;
        const rl::mat4 mvp = view_projection * model.transform;
        if (options.pipeline.cull_objects && perspective::outside_frustum(model.box, mvp)) {
            ++counts.objects_culled;
            continue;
        }
        const std::optional<rl::mat3> normals = shading::normal_matrix(model.transform);
        if (!normals) continue;  // a flattened model has no surface to light
        shading::Uniforms u{model.transform,  *normals,       mvp, camera.eye,
                            options.lighting, &model.texture, {},  {}};
        u.sampler.filter = textures::Filter::trilinear;
        u.sampler.encoding = &shading::srgb_texels();
        const bool mirrored = rl::determinant(shading::linear_part(model.transform)) < 0;
        NormalMappedShader shader{
            u, m.maps, options.normal_map, options.specular, mirrored ? -1.0f : 1.0f, &m.tangents};
        counts += shading::draw(shading::Surface{model.mesh, m.lit.normals, mirrored}, shader,
                                frame.target(), options.pipeline, shading::Output::srgb);
    }
    return counts;
}
// [/doc:render-mapped]

}  // namespace normal_mapping
