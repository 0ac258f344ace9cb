// What the fast shader reads for one model in one frame: lesson 07's
// NormalMappedShader's uniforms (eye, lights, normal matrix, maps, options)
// flattened into plain arrays that SIMD code broadcasts, with the textures
// packed for gathers. Filled in place each frame (no allocation).
//
//   fast::Material material;  // one per model, refilled in place every frame
//   material.filter = textures::Filter::trilinear;
//   material.albedo = &diffuse;  // a fast::PackedTexture, or nullptr for material.colour
//   material.normal_source = fast::NormalSource::tangent_map;
//   material.normal_map = &tangent_map;
//   material.shadow_map = &map;  // a shadows::ShadowMap from the key light, or nullptr
#pragma once

#include <cstdint>

#include "06_shading/lighting.hpp"
#include "08_shadows/shadow_lookup.hpp"
#include "packed_texture.hpp"

namespace fast {

inline constexpr int kMaxLights = 8;

// Where the normal comes from, after the maps the model has are known.
enum class NormalSource : std::uint8_t { interpolated, tangent_map, object_map };

struct Material {
    float eye[3];
    int lights = 0;
    float light_direction[kMaxLights][3], light_colour[kMaxLights][3];
    float ambient[3], specular_colour[3], shininess;
    bool blinn = true;       // Blinn's half-vector highlight, or Phong's mirror
    float normal_matrix[9];  // row-major: object-space map normals to world
    NormalSource normal_source = NormalSource::interpolated;
    textures::Filter filter = textures::Filter::trilinear;
    bool srgb = true;             // diffuse texels decoded from sRGB and output encoded to sRGB
    bool srgb_one_gather = true;  // Techniques::srgb_one_gather
    const PackedTexture* albedo = nullptr;  // none: the plain colour
    float colour[3];
    const PackedTexture* normal_map = nullptr;  // the one normal_source names
    const PackedTexture* specular_map = nullptr;
    bool specular_in_normal_alpha = false;  // the normal map's alpha bytes hold the specular map
    // Lesson 08's second pass: the first light (the key light the map was
    // made from, directional) scaled at each pixel by what the map lets
    // through, by lesson 08's lookup; none: no shadows.
    const shadows::ShadowMap* shadow_map = nullptr;
    shadows::ShadowLookup shadow_lookup;
};

}  // namespace fast
