// Lesson 07's full shading with the key light's share scaled by what the
// shadow map lets through: the shadow darkens the direct light only, in
// linear light; the fill light and the ambient term are untouched (they
// stand for light from everywhere else, which one map cannot test).
// For a spot light the key light comes from its position, dimmed smoothly
// over the outer fifth of its cone's angle and dark outside it.
//
//   const shadows::ShadowedShader shader{mapped, map, lookup, key, rest};
//   shading::draw(surface, shader, frame, {});
#pragma once

#include <cmath>

#include "07_normal_mapping/normal_mapped.hpp"
#include "shadow_lookup.hpp"

namespace shadows {

// How much of a spot light's cone a direction from the light is in: 1
// inside 80% of the half angle, 0 outside the cone, smooth between.
inline float cone_factor(const LightView& light, float cone_degrees, rl::vec3 from_light) {
    const float c = rl::dot(rl::normalize(from_light), light.direction);
    const float outer = std::cos(0.5f * rl::radians(cone_degrees));
    const float inner = std::cos(0.4f * rl::radians(cone_degrees));
    const float t = std::clamp((c - outer) / std::max(inner - outer, 1e-6f), 0.0f, 1.0f);
    return t * t * (3 - 2 * t);
}

// [doc:shadowed-shader]
struct ShadowedShader {
    normal_mapping::NormalMappedShader surface;  // lesson 07: normals, albedo, maps
    const ShadowMap& map;
    ShadowLookup lookup;
    shading::Light<float> key;      // the light the map was made from (its direction: directional)
    float cone_degrees = 0;         // spot only
    shading::Lighting<float> rest;  // the other lights and the ambient term
    using Varyings = normal_mapping::NormalMappedShader::Varyings;

    pipeline::ClipVertex<Varyings> vertex(const shading::SurfaceCorner& in) const {
        return surface.vertex(in);
    }

    // The map's answer at a pixel, 0 to 1. The offset goes along the
    // interpolated surface normal: the mapped one follows the relief.
    float light_reaching(const Varyings& v) const {
        return visibility(map, v.position, rl::normalize(v.normal), lookup);
    }

    rl::vec3 fragment(const pipeline::Fragment<Varyings>& f) const {
        const Varyings& v = f.varyings;
        const rl::vec2 dx = f.d_dx(&Varyings::uv), dy = f.d_dy(&Varyings::uv);
        const rl::vec3 n = surface.normal_at(f, dx, dy);
        const rl::vec3 to_eye = rl::normalize(surface.u.eye - v.position);
        shading::Reflection<float> r = shading::reflection(rest, n, to_eye, surface.specular);
        shading::Light<float> light = key;
        if (map.light.type == LightType::spot) {
            light.direction = rl::normalize(map.light.position - v.position);
            light.colour = light.colour * cone_factor(map.light, cone_degrees, -light.direction);
        }
        if (light.colour.x > 0 || light.colour.y > 0 || light.colour.z > 0) {
            const float lit = light_reaching(v);
            if (lit > 0) {
                const shading::Reflection<float> direct =
                    shading::reflection_of(light, surface.u.lighting, n, to_eye, surface.specular);
                r.diffuse += direct.diffuse * lit;
                r.specular += direct.specular * lit;
            }
        }
        return surface.surface_colour(v, dx, dy, r);
    }
};
// [/doc:shadowed-shader]

}  // namespace shadows
