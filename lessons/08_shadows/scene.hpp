// Lesson 08's render: lesson 07's scene and shading, in two passes. First
// the shadow map, from the key light, fitted to the scene or to what the
// camera sees; then the scene from the camera, each pixel's key light
// scaled by the map's answer.
//
//   const shadows::ShadowMap map = shadows::shadow_map_for(models, camera, aspect, options);
//   shadows::render(models, camera, options, map, frame);
#pragma once

#include "shadow_lookup.hpp"

namespace shadows {

struct ShadowOptions {
    normal_mapping::RenderOptions render;  // lesson 07's; its first light is the key light
    ShadowLight light;                     // its direction is the key light's
    Fit fit = Fit::view;
    ShadowMapOptions map;
    ShadowLookup lookup;
};

// The default scene: lesson 07's floor, globe and crate, and the torus
// leaning on the crate, so that objects cast on the floor and on each other.
std::vector<normal_mapping::MappedModel> default_scene(std::vector<std::string>& warnings);

// The box around every model.
perspective::Box scene_box(const std::vector<normal_mapping::MappedModel>& models);

// A spot light's default place: on the --light direction from the scene's
// centre, twice the scene's radius away.
rl::vec3 default_spot_position(const perspective::Box& box, rl::vec3 towards_light);

// The first pass. `aspect`: the camera's width / height, for Fit::view.
ShadowMap shadow_map_for(const std::vector<normal_mapping::MappedModel>& models,
                         const perspective::Camera& camera, float aspect,
                         const ShadowOptions& options);

// The second pass, into the frame.
perspective::PipelineCounts render(const std::vector<normal_mapping::MappedModel>& models,
                                   const perspective::Camera& camera, const ShadowOptions& options,
                                   const ShadowMap& map, perspective::ColourTarget& frame);

}  // namespace shadows
