// Lesson 08's render: lesson 07's scene and shading, in two passes. First
// the shadow map, from the key light, fitted to the scene or to what the
// camera sees; then the scene from the camera, each pixel's key light
// scaled by the map's answer.
//
//   const shadows::ShadowMap map = shadows::shadow_map_for(models, camera, aspect, options);
//   shadows::render(models, camera, options, map, frame);
#pragma once

#include "shadowed_shader.hpp"

namespace shadows {

struct ShadowOptions {
    normal_mapping::RenderOptions render;  // lesson 07's; its first light is the key light
    ShadowLight light;                     // its direction is the key light's
    Fit fit = Fit::view;
    ShadowMapOptions map;
    ShadowLookup lookup;
    bool casters = true;  // false: the same light's map with nothing in it: no shadows
};

// What the program writes: the image, the shadow map's depth as a picture,
// or the image with nothing in the map (no shadows: lesson 07's lighting,
// the "before" of the page's opening picture).
enum class Show { image, shadow_map, unshadowed };
RASTERLAB_NAMED_ENUM(Show, kShows, {Show::image, "image"}, {Show::shadow_map, "shadow-map"},
                     {Show::unshadowed, "unshadowed"});

// The faces the map stores: those facing the light (their back faces
// culled), or those facing away.
enum class MapFaces { front, back };
RASTERLAB_NAMED_ENUM(MapFaces, kMapFaces, {MapFaces::front, "front"}, {MapFaces::back, "back"});
inline pipeline::Cull cull_for(MapFaces faces) {
    return faces == MapFaces::front ? pipeline::Cull::back : pipeline::Cull::front;
}

// The program's --light: from the right, in front, so that the crate and the
// torus shadow the globe, and all three the floor, where the camera sees it.
inline constexpr rl::vec3 kSceneLight{1.0f, 0.6f, 0.6f};

// The default scene: lesson 07's floor, globe and crate, and the torus
// leaning on the crate, so that objects cast on the floor and on each other.
std::vector<normal_mapping::MappedModel> default_scene(std::vector<std::string>& warnings);

using normal_mapping::scene_box;  // the box around every model

// The default scene (or the view's models, as stored, with `tangents`) and
// the camera framing it, as lesson 08's program draws them.
pipeline::ViewedScene<normal_mapping::MappedModel> load_scene(
    const pipeline::ViewOptions& view, normal_mapping::TangentMethod tangents, int width,
    int height, std::vector<std::string>& warnings);

// A spot light's default place: on the --light direction from the scene's
// centre, twice the scene's radius away.
rl::vec3 default_spot_position(const pipeline::Box& box, rl::vec3 towards_light);

// The lights the view asks for: the key light's direction (--light, made
// unit), lesson 07's lighting from it (with its dim fill light unless
// `one_light`). Throws std::invalid_argument naming --light for 0 0 0.
void set_lights(ShadowOptions& options, const pipeline::ViewOptions& view, bool one_light);

// Throws std::invalid_argument naming the option when a spot light's own
// options (--light-position, --cone) come with another kind of light: they
// would be ignored without a word.
void refuse_spot_options(LightType type, bool position_given, bool cone_given);

// A spot light's place: `position` (three numbers) if given, else
// default_spot_position(); nothing for a directional light.
void place_spot(ShadowOptions& options, const pipeline::Box& box,
                const std::vector<float>& position);

// Where the first pass looks from: the light's view fitted to the scene, or
// to what the camera sees of it. `aspect`: the camera's width / height.
LightView light_view_for(const std::vector<normal_mapping::MappedModel>& models,
                         const pipeline::Camera& camera, float aspect,
                         const ShadowOptions& options);

// The first pass, from light_view_for's view.
ShadowMap shadow_map_for(const std::vector<normal_mapping::MappedModel>& models,
                         const pipeline::Camera& camera, float aspect,
                         const ShadowOptions& options);

// The key light, tested against the map (the options' first light, from
// the shadow light's direction), and the others with the ambient term.
struct SplitLighting {
    shading::Light<float> key;
    shading::Lighting<float> rest;
};
SplitLighting split_lighting(const ShadowOptions& options);

// Each model of the second pass, placed and given its shader, handed to
// draw(model, surface, shader), which returns the counts of its draw.
template <class Draw>
pipeline::PipelineCounts draw_shadowed(const std::vector<normal_mapping::MappedModel>& models,
                                       const pipeline::Camera& camera, float aspect,
                                       const ShadowOptions& options, const ShadowMap& map,
                                       Draw&& draw) {
    const normal_mapping::RenderOptions& r = options.render;
    const rl::mat4 view_projection = pipeline::view_projection(camera, aspect);
    textures::SamplerState sampler;
    sampler.filter = r.filter;
    sampler.encoding = r.output == shading::Output::srgb ? &shading::srgb_texels() : nullptr;
    const SplitLighting lights = split_lighting(options);
    pipeline::PipelineCounts counts;
    for (const normal_mapping::MappedModel& m : models) {
        const std::optional<shading::Placed> p = shading::place(
            m.lit, view_projection, camera, r.lighting, sampler, r.cull_objects, counts);
        if (!p) continue;
        counts += draw(m, p->surface,
                       ShadowedShader{normal_mapping::shader_for(m, *p, r), map, options.lookup,
                                      lights.key, options.light.cone_degrees, lights.rest});
    }
    return counts;
}

// The second pass, into the frame.
pipeline::PipelineCounts render(const std::vector<normal_mapping::MappedModel>& models,
                                const pipeline::Camera& camera, const ShadowOptions& options,
                                const ShadowMap& map, pipeline::ColourTarget& frame);

}  // namespace shadows
