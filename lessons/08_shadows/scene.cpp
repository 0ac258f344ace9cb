#include "scene.hpp"

#include <stdexcept>

#include "rasterlab/transform.hpp"

namespace shadows {

std::vector<normal_mapping::MappedModel> default_scene(std::vector<std::string>& warnings) {
    using normal_mapping::TangentMethod;
    std::vector<normal_mapping::MappedModel> models =
        normal_mapping::default_scene(TangentMethod::split, warnings);
    // The torus (ring radius 0.62, tube 0.3, about z) turned to lie flat,
    // scaled by 0.7, on the crate's top (y = 1.1): it overhangs the crate
    // and shadows its top, its sides and the floor.
    models.push_back(normal_mapping::load_mapped_model(
        rl::project_model("torus"),
        rl::compose({.translation = {0.85f, 1.1f + 0.7f * 0.3f, 0.35f},
                     .rotation = rl::axis_angle({1, 0, 0}, 90),
                     .scale = {0.7f, 0.7f, 0.7f}}),
        TangentMethod::split, warnings));
    return models;
}

pipeline::ViewedScene<normal_mapping::MappedModel> load_scene(
    const pipeline::ViewOptions& view, normal_mapping::TangentMethod tangents, int width,
    int height, std::vector<std::string>& warnings) {
    return normal_mapping::load_view(view, tangents, width, height, warnings, default_scene);
}

void set_lights(ShadowOptions& options, const pipeline::ViewOptions& view, bool one_light) {
    options.light.direction = rl::normalize(pipeline::light_direction(view));
    options.render.lighting = shading::default_lighting(options.light.direction);
    if (one_light) options.render.lighting.lights.resize(1);
}

void refuse_spot_options(LightType type, bool position_given, bool cone_given) {
    if (type == LightType::spot) return;
    if (position_given)
        throw std::invalid_argument(
            "--light-position: only a spot light has a position (add --light-type spot)");
    if (cone_given)
        throw std::invalid_argument("--cone: only a spot light has a cone (add --light-type spot)");
}

void place_spot(ShadowOptions& options, const pipeline::Box& box,
                const std::vector<float>& position) {
    if (options.light.type != LightType::spot) return;
    options.light.position = position.empty() ? default_spot_position(box, options.light.direction)
                                              : rl::vec3{position[0], position[1], position[2]};
}

rl::vec3 default_spot_position(const pipeline::Box& box, rl::vec3 towards_light) {
    return box.centre() + rl::normalize(towards_light) * rl::length(box.max - box.min);
}

LightView light_view_for(const std::vector<normal_mapping::MappedModel>& models,
                         const pipeline::Camera& camera, float aspect,
                         const ShadowOptions& options) {
    const pipeline::Box scene = scene_box(models);
    pipeline::Box covered = options.fit == Fit::view ? visible_box(camera, aspect, scene) : scene;
    if (covered.empty()) covered = scene;  // the camera sees none of it: any map will do
    if (scene.empty()) {                   // no geometry at all: a map with nothing in it
        covered.add(rl::vec3{-1, -1, -1});
        covered.add(rl::vec3{1, 1, 1});
    }
    return light_view(options.light, covered, scene);
}

ShadowMap shadow_map_for(const std::vector<normal_mapping::MappedModel>& models,
                         const pipeline::Camera& camera, float aspect,
                         const ShadowOptions& options) {
    // (Chosen by reference: the ternary of a reference and a temporary would
    // copy every model, meshes and textures, into a temporary.)
    static const std::vector<normal_mapping::MappedModel> nothing;
    const std::vector<normal_mapping::MappedModel>& casters = options.casters ? models : nothing;
    return render_shadow_map(casters, light_view_for(models, camera, aspect, options), options.map);
}

SplitLighting split_lighting(const ShadowOptions& options) {
    SplitLighting out{{rl::normalize(options.light.direction), {0, 0, 0}}, options.render.lighting};
    if (!out.rest.lights.empty()) {
        out.key.colour = out.rest.lights.front().colour;
        out.rest.lights.erase(out.rest.lights.begin());
    }
    return out;
}

// [doc:render-shadowed]
pipeline::PipelineCounts render(const std::vector<normal_mapping::MappedModel>& models,
                                const pipeline::Camera& camera, const ShadowOptions& options,
                                const ShadowMap& map, pipeline::ColourTarget& frame) {
    const float aspect = static_cast<float>(frame.width()) / static_cast<float>(frame.height());
    return draw_shadowed(models, camera, aspect, options, map,
                         [&](const normal_mapping::MappedModel&, const shading::Surface& surface,
                             const ShadowedShader& shader) {
                             return shading::draw(surface, shader, frame, options.render.pipeline,
                                                  options.render.output);
                         });
}
// [/doc:render-shadowed]

}  // namespace shadows
