// Lesson 07's normal-mapped surfaces lit by the whole environment instead
// of lights: a mirror reflects what its reflected direction sees; glass
// (Fresnel's share) reflects some and lets the rest through, bent by Snell's
// law at its front face; a diffuse (Lambert) surface reflects its albedo /
// pi times the irradiance. Linear HDR light out, for a float render target.
//
//   const environment::EnvironmentShader shader{mapped, env, environment::Material::glass};
//   perspective::draw(surface, shader, hdr_target, {});
#pragma once

#include <numbers>

#include "07_normal_mapping/normal_mapped.hpp"
#include "environment.hpp"
#include "irradiance.hpp"
#include "optics.hpp"

namespace environment {

enum class Material { mirror, glass, diffuse };
inline constexpr std::array<rl::Named<Material>, 3> kMaterialNames = {
    {{Material::mirror, "mirror"}, {Material::glass, "glass"}, {Material::diffuse, "diffuse"}}};
inline constexpr std::array<Material, 3> kMaterials = rl::values_of(kMaterialNames);
inline const char* name(Material value) {
    return rl::name_in(kMaterialNames, value);
}

inline constexpr float kGlassIor = 1.5f;

// [doc:environment-shader]
struct EnvironmentShader {
    normal_mapping::NormalMappedShader surface;  // lesson 07: positions and normals
    const Environment& environment;
    Material material;
    const DiffuseLight* diffuse = nullptr;  // for Material::diffuse
    using Varyings = normal_mapping::NormalMappedShader::Varyings;

    perspective::ClipVertex<Varyings> vertex(const shading::SurfaceCorner& in) const {
        return surface.vertex(in);
    }

    rl::vec3 fragment(const perspective::Fragment<Varyings>& f) const {
        const Varyings& v = f.varyings;
        const rl::vec2 dx = f.d_dx(&Varyings::uv), dy = f.d_dy(&Varyings::uv);
        const rl::vec3 n = surface.normal_at(f, dx, dy);
        if (material == Material::diffuse) {
            // Lambert: albedo / pi of the irradiance. Each pixel's Monte
            // Carlo rays are its own (seeded by its place).
            const std::uint32_t seed = static_cast<std::uint32_t>(f.x) * 73856093u ^
                                       static_cast<std::uint32_t>(f.y) * 19349663u;
            return surface.u.albedo(v.uv, dx, dy) * diffuse->at(n, seed) *
                   (1 / std::numbers::pi_v<float>);
        }
        const rl::vec3 to_eye = rl::normalize(surface.u.eye - v.position);
        const rl::vec3 mirrored = environment.sample(reflect(-to_eye, n));
        if (material == Material::mirror) return mirrored;
        // Glass: one interface, the front one (a rasterizer sees no back face
        // behind this pixel): what the refracted ray sees, and Fresnel's
        // share of the mirror image on top. Total internal reflection cannot
        // happen entering a denser medium; a normal map tilted past the eye
        // can still ask for it, and then everything is reflected.
        const std::optional<rl::vec3> through = refract(-to_eye, n, 1 / kGlassIor);
        if (!through) return mirrored;
        const float share = schlick(rl::dot(n, to_eye), reflectance_at_normal(kGlassIor));
        return mirrored * share + environment.sample(*through) * (1 - share);
    }
};
// [/doc:environment-shader]

}  // namespace environment
