// The full render of this series: lesson 06's Blinn-Phong (or Phong) shading
// in linear light, with the normal at each pixel from a normal map, in
// tangent space (through the corner tangent frames) or in object space, and
// the highlight's strength from a specular map.
//
//   const normal_mapping::Maps maps = normal_mapping::load_maps(mesh, warnings);
//   shading::draw(surface, normal_mapping::NormalMappedShader{u, maps, kind, ...}, target, {});
#pragma once

#include <algorithm>
#include <optional>

#include "06_shading/shaders.hpp"
#include "tangents.hpp"

namespace normal_mapping {

// Where the normal at a pixel comes from.
enum class NormalMap { tangent, object, none };
RASTERLAB_NAMED_ENUM(NormalMap, kNormalMaps, {NormalMap::tangent, "tangent"},
                     {NormalMap::object, "object"}, {NormalMap::none, "none"});

// A model's maps; each empty where the model has none. Normal and specular
// maps hold data, not colours: their bytes are read as they are, not sRGB.
struct Maps {
    std::optional<textures::MipChain> tangent_normals, object_normals, specular;
};

// Finds `<name>_nm_tangent`, `_nm`, `_spec` (or the MTL's maps) beside the
// OBJ. A missing map is silent (most models have few); an unreadable one warns.
// `only`: load just that normal map (none for NormalMap::none), not both.
Maps load_maps(const rl::Mesh& mesh, std::vector<std::string>& warnings,
               std::optional<NormalMap> only = std::nullopt);

// A tangent-space texel (r, g, b) as a direction: 2 * rgb - 1, the OpenGL
// convention (green along +v).
inline rl::vec3 decode_normal(rl::vec4 texel) {
    return {2 * texel.x - 1, 2 * texel.y - 1, 2 * texel.z - 1};
}

// A decoded map normal shorter than one byte step (2/255) has no direction
// the texel's bytes can tell.
inline constexpr float kShortestMapNormal = 2.0f / 255;

// [doc:normal-mapped-shader]
struct NormalMappedShader {
    const shading::Uniforms& u;
    const Maps& maps;
    NormalMap source;
    shading::Specular specular;
    float mirror;  // -1 when the model matrix mirrors: the bitangent flips with it
    struct Varyings {
        rl::vec3 position, normal, tangent;  // world space
        float handedness;
        rl::vec2 uv;
    };
    // The vertex stage reads the corner's tangent from here (3 per face).
    const std::vector<rl::vec4>* tangents = nullptr;
    textures::Filter map_filter = textures::Filter::trilinear;  // for the normal and specular maps

    pipeline::ClipVertex<Varyings> vertex(const shading::SurfaceCorner& in) const {
        const rl::vec4 t = (*tangents)[3 * static_cast<std::size_t>(in.face) +
                                       static_cast<std::size_t>(in.corner)];
        // A tangent is a direction along the surface: it transforms like a
        // position difference (by the model's 3x3), not like a normal.
        const rl::vec3 world_tangent = (u.model_matrix * rl::vec4{t.x, t.y, t.z, 0}).xyz();
        return {u.clip(in.position()),
                {u.world(in.position()), u.world_normal(in.normal()), world_tangent, t.w * mirror,
                 in.uv()}};
    }

    // The unit normal at a pixel, in world space: from the map chosen, or
    // the interpolated one. A map texel too close to the middle grey to hold
    // a direction (filtering a 127/128 checker averages to 0) keeps the
    // interpolated normal, as lesson 06 does for a zero normal in the OBJ.
    // (dx, dy: the texture coordinates' screen derivatives, for the mip level.)
    rl::vec3 normal_at(const pipeline::Fragment<Varyings>& f, rl::vec2 dx, rl::vec2 dy) const {
        const Varyings& v = f.varyings;
        const rl::vec3 n = rl::normalize(v.normal);
        if (source == NormalMap::tangent && maps.tangent_normals) {
            const rl::vec3 m = decode_normal(sample(*maps.tangent_normals, v.uv, dx, dy));
            const float length = rl::length(m);
            if (!(length >= kShortestMapNormal)) return n;
            // Re-orthogonalise the interpolated frame, then B from N, T and w.
            // T, B, N are orthonormal, so T m.x + B m.y + N m.z is as long as m.
            const rl::vec3 t = rl::normalize(v.tangent - n * rl::dot(n, v.tangent));
            const rl::vec3 b = rl::cross(n, t) * (v.handedness < 0 ? -1.0f : 1.0f);
            return (t * m.x + b * m.y + n * m.z) / length;
        }
        if (source == NormalMap::object && maps.object_normals) {
            const rl::vec3 m = decode_normal(sample(*maps.object_normals, v.uv, dx, dy));
            if (!(rl::length(m) >= kShortestMapNormal)) return n;
            return u.world_normal(m);
        }
        return n;
    }

    rl::vec3 fragment(const pipeline::Fragment<Varyings>& f) const {
        const Varyings& v = f.varyings;
        const rl::vec2 dx = f.d_dx(&Varyings::uv), dy = f.d_dy(&Varyings::uv);
        const rl::vec3 n = normal_at(f, dx, dy);
        return surface_colour(
            v, dx, dy,
            shading::reflection(u.lighting, n, rl::normalize(u.eye - v.position), specular));
    }

    // The light reflected at a pixel, coloured by the surface's maps: the
    // albedo times the diffuse part, the specular map times the highlight.
    rl::vec3 surface_colour(const Varyings& v, rl::vec2 dx, rl::vec2 dy,
                            const shading::Reflection<float>& r) const {
        // Where the highlight is too dim to change any byte (under 10^-4 of
        // the light), skip the specular map's lookup.
        const float peak = std::max({r.specular.x, r.specular.y, r.specular.z});
        const float shine = !maps.specular ? 1.0f
                            : peak < 1e-4f ? 0.0f
                                           : sample(*maps.specular, v.uv, dx, dy).x;
        return u.albedo(v.uv, dx, dy) * r.diffuse + r.specular * shine;
    }

    rl::vec4 sample(const textures::MipChain& map, rl::vec2 uv, rl::vec2 dx, rl::vec2 dy) const {
        textures::SamplerState data;  // bytes as they are: these maps hold data
        data.filter = map_filter;
        return textures::sample(map, uv, {dx, dy}, data);
    }
};
// [/doc:normal-mapped-shader]

}  // namespace normal_mapping
