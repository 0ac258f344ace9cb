// The light's view of the scene, for a shadow map: the matrix taking world
// space to the map's clip space, fitted around the volume the map must
// cover. Two kinds of light:
//   directional  parallel rays along one direction (the sun): an
//                orthographic projection along it;
//   spot         rays from a point inside a cone: a perspective projection
//                from the point, its field of view the cone's.
// The covered volume is either the whole scene's box, or the part of it the
// camera can see (the box around the view frustum, clipped to the scene's):
// then the map's texels go where the picture needs them.
// Derivations: docs/08_shadows.md#light-space.
//
//   const shadows::LightView light = shadows::light_view(
//       {shadows::LightType::directional, {0.3f, 0.5f, 1.0f}}, scene_box);
#pragma once

#include "05_perspective/camera.hpp"
#include "rasterlab/named_enum.hpp"

namespace shadows {

enum class LightType { directional, spot };
RASTERLAB_NAMED_ENUM(LightType, kLightTypes, {LightType::directional, "directional"},
                     {LightType::spot, "spot"});

enum class Fit { scene, view };
RASTERLAB_NAMED_ENUM(Fit, kFits, {Fit::scene, "scene"}, {Fit::view, "view"});

struct ShadowLight {
    LightType type = LightType::directional;
    rl::vec3 direction{0.3f, 0.5f, 1.0f};  // towards the light, unit length
    rl::vec3 position{0, 0, 0};            // spot: where the light is
    float cone_degrees = 60;               // spot: the cone's full opening angle
};

// Where the map sits: the light's view and projection, and the size of one
// map texel in world units at a point, which normal offsets scale by.
struct LightView {
    LightType type = LightType::directional;
    rl::vec3 position, direction;  // the light's eye (spot) and its axis, pointing away from it
    rl::mat4 view_projection;
    float width = 0;           // directional: the map's side in world units
    float tan_half_angle = 0;  // spot: half the map's side at unit distance
    float texel_size(rl::vec3 world_point, int map_size) const;
};

// OpenGL's orthographic projection: the box [left, right] x [bottom, top] x
// [-near, -far] of eye space to the cube [-1, 1]^3, w = 1.
rl::mat4 orthographic(float left, float right, float bottom, float top, float near, float far);

// The part of `scene` the camera can see: the box around the view
// frustum's eight corners, clipped to the scene's box.
pipeline::Box visible_box(const pipeline::Camera& camera, float aspect, const pipeline::Box& scene);

// The light's view fitted around `covered`, the receivers: a directional
// light's orthographic box holds all its corners; a spot light's frustum
// keeps its cone and puts its near and far planes around them (near at
// least far / 1000, so that a light inside the box keeps a usable depth
// range). The near plane then moves towards the light over `casters` (the
// whole scene's box): a caster outside the camera's view can still stand
// between the light and a point the camera sees, and the map must hold it.
// Throws std::invalid_argument for an empty box or a zero direction.
LightView light_view(const ShadowLight& light, const pipeline::Box& covered,
                     const pipeline::Box& casters);
inline LightView light_view(const ShadowLight& light, const pipeline::Box& covered) {
    return light_view(light, covered, covered);
}

}  // namespace shadows
