// Lesson 07's normal-mapped surfaces lit by the whole environment instead
// of lights: a mirror reflects what its reflected direction sees; glass
// (Fresnel's share) reflects some and lets the rest through, bent by Snell's
// law at its front face. Linear HDR light out, for a float render target.
//
//   const environment::EnvironmentShader shader{mapped, env, environment::Material::glass};
//   perspective::draw(surface, shader, hdr_target, {});
#pragma once

#include "07_normal_mapping/normal_mapped.hpp"
#include "environment.hpp"
#include "optics.hpp"

namespace environment {

enum class Material { mirror, glass };
inline constexpr std::array<rl::Named<Material>, 2> kMaterialNames = {
    {{Material::mirror, "mirror"}, {Material::glass, "glass"}}};
inline constexpr std::array<Material, 2> kMaterials = rl::values_of(kMaterialNames);
inline const char* name(Material value) {
    return rl::name_in(kMaterialNames, value);
}

inline constexpr float kGlassIor = 1.5f;

struct EnvironmentShader {
    normal_mapping::NormalMappedShader surface;  // lesson 07: positions and normals
    const Environment& environment;
    Material material;
    using Varyings = normal_mapping::NormalMappedShader::Varyings;

    perspective::ClipVertex<Varyings> vertex(const shading::SurfaceCorner& in) const {
        return surface.vertex(in);
    }

    rl::vec3 fragment(const perspective::Fragment<Varyings>& f) const {
        const Varyings& v = f.varyings;
        const rl::vec3 n = surface.normal_at(f, f.d_dx(&Varyings::uv), f.d_dy(&Varyings::uv));
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

}  // namespace environment
