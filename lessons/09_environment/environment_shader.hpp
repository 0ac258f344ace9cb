// Lesson 07's normal-mapped surfaces lit by the whole environment instead
// of lights: a mirror reflects what its reflected direction sees; glass
// (Fresnel's share) reflects some and lets the rest through, bent by Snell's
// law at its front face; a diffuse (Lambert) surface reflects its albedo /
// pi times the irradiance; rough metal and plastic reflect through the
// microfacet BRDF, by the split sum or by Monte Carlo. Linear HDR light
// out, for a float render target.
//
//   const environment::EnvironmentShader shader{mapped, {.environment = &env},
//                                               {.material = environment::Material::glass}};
//   pipeline::draw(surface, shader, hdr_target, {});
#pragma once

#include <numbers>

#include "07_normal_mapping/normal_mapped.hpp"
#include "brdf.hpp"
#include "glossy_map.hpp"
#include "irradiance.hpp"
#include "optics.hpp"

namespace environment {

enum class Material { mirror, glass, diffuse, rough_metal, plastic };
RASTERLAB_NAMED_ENUM(Material, kMaterials, {Material::mirror, "mirror"}, {Material::glass, "glass"},
                     {Material::diffuse, "diffuse"}, {Material::rough_metal, "rough-metal"},
                     {Material::plastic, "plastic"});
inline bool is_glossy(Material m) {
    return m == Material::rough_metal || m == Material::plastic;
}

// How a glossy surface gathers its light: the split sum's two look-ups, or
// `samples` GGX rays into the map at each pixel (the reference).
enum class Glossy { split_sum, monte_carlo };
RASTERLAB_NAMED_ENUM(Glossy, kGlossies, {Glossy::split_sum, "split-sum"},
                     {Glossy::monte_carlo, "monte-carlo"});

// Which direction the split sum reads its blurred maps along: the mirror
// direction (as the prefilter assumed), or the lobe's dominant direction,
// leaning towards the normal the rougher the surface.
enum class Lookup { dominant, mirror };
RASTERLAB_NAMED_ENUM(Lookup, kLookups, {Lookup::dominant, "dominant"}, {Lookup::mirror, "mirror"});

inline constexpr float kGlassIor = 1.5f;
// Gold's head-on reflectance in linear RGB (the rough metal's), and a
// plastic's (any dielectric of index 1.5: 4%).
inline constexpr rl::vec3 kGoldF0{1.0f, 0.71f, 0.29f};
inline constexpr float kPlasticF0 = 0.04f;

// What a surface is made of, for one model.
struct SurfaceMaterial {
    Material material = Material::mirror;
    float roughness = 0.35f;   // rough metal and plastic
    rl::vec3 metal = kGoldF0;  // the rough metal's head-on reflectance
    Glossy glossy = Glossy::split_sum;
    Lookup lookup = Lookup::dominant;
    bool multiple_scattering = true;  // put back the energy one bounce loses
    int samples = 64;                 // Monte Carlo's rays per pixel (diffuse and glossy)
};

// The light, prepared once per frame; what a material needs must be there
// (diffuse: `diffuse`; rough metal and plastic: `diffuse` and `glossy`).
struct EnvironmentLight {
    const Environment* environment = nullptr;
    const DiffuseLight* diffuse = nullptr;
    const GlossyMap* glossy = nullptr;
};

struct EnvironmentShader {
    normal_mapping::NormalMappedShader surface;  // lesson 07: positions and normals
    EnvironmentLight light;
    SurfaceMaterial material;
    using Varyings = normal_mapping::NormalMappedShader::Varyings;

    pipeline::ClipVertex<Varyings> vertex(const shading::SurfaceCorner& in) const {
        return surface.vertex(in);
    }

    // [doc:environment-shader]
    rl::vec3 fragment(const pipeline::Fragment<Varyings>& f) const {
        const Varyings& v = f.varyings;
        const rl::vec2 dx = f.d_dx(&Varyings::uv), dy = f.d_dy(&Varyings::uv);
        const rl::vec3 n = surface.normal_at(f, dx, dy);
        const rl::vec3 to_eye = rl::normalize(surface.u.eye - v.position);
        const rl::vec3 r = reflect(-to_eye, n);
        switch (material.material) {
            case Material::mirror:
                return light.environment->sample(r, mirror_level(f));
            case Material::glass:
                return glass(n, to_eye, light.environment->sample(r, mirror_level(f)));
            case Material::diffuse:
                return surface.u.albedo(v.uv, dx, dy) * light.diffuse->at(n, seed(f)) *
                       (1 / std::numbers::pi_v<float>);
            case Material::rough_metal:
                return glossy(f, n, to_eye, r, material.metal, {0, 0, 0});
            case Material::plastic:
                return glossy(f, n, to_eye, r, rl::vec3{1, 1, 1} * kPlasticF0,
                              surface.u.albedo(v.uv, dx, dy));
        }
        return {0, 0, 0};
    }
    // [/doc:environment-shader]

    // Each pixel's Monte Carlo rays are its own (seeded by its place), so
    // the noise stays put when nothing moves.
    static std::uint32_t seed(const pipeline::Fragment<Varyings>& f) {
        return static_cast<std::uint32_t>(f.x) * 73856093u ^
               static_cast<std::uint32_t>(f.y) * 19349663u;
    }

    // [doc:mirror-level]
    // The mip level a mirror reads: how far the reflected direction turns
    // from this pixel to the next (from the screen derivatives of the
    // position and the interpolated normal; the normal map's own bumps
    // within a pixel are not counted), in texels of the map.
    float mirror_level(const pipeline::Fragment<Varyings>& f) const {
        if (light.environment->filter() != MapFilter::trilinear) return 0;  // no level to pick
        const Varyings& v = f.varyings;
        const auto mirrored = [&](rl::vec3 position, rl::vec3 normal) {
            return reflect(-rl::normalize(surface.u.eye - position), rl::normalize(normal));
        };
        const rl::vec3 here = mirrored(v.position, v.normal);
        const rl::vec3 right = mirrored(v.position + f.d_dx(&Varyings::position),
                                        v.normal + f.d_dx(&Varyings::normal));
        const rl::vec3 up = mirrored(v.position + f.d_dy(&Varyings::position),
                                     v.normal + f.d_dy(&Varyings::normal));
        // A chord of the unit sphere: the angle, for the small ones that matter.
        const float turn = std::max(rl::length(right - here), rl::length(up - here));
        return light.environment->level_for(turn);
    }
    // [/doc:mirror-level]

    // [doc:glass]
    // Glass: one interface, the front one (a rasterizer sees no back face
    // behind this pixel): what the refracted ray sees, and Fresnel's share
    // of the mirror image on top. Total internal reflection cannot happen
    // entering a denser medium; a normal map tilted past the eye can still
    // ask for it, and then everything is reflected.
    rl::vec3 glass(rl::vec3 n, rl::vec3 to_eye, rl::vec3 mirrored) const {
        const std::optional<rl::vec3> through = refract(-to_eye, n, 1 / kGlassIor);
        if (!through) return mirrored;
        const float share = schlick(rl::dot(n, to_eye), reflectance_at_normal(kGlassIor));
        return mirrored * share + light.environment->sample(*through) * (1 - share);
    }
    // [/doc:glass]

    // [doc:glossy-shader]
    // Cook-Torrance's reflection of the environment, plus (for a plastic)
    // the albedo's diffuse light under it: what the specular layer lets through.
    rl::vec3 glossy(const pipeline::Fragment<Varyings>& f, rl::vec3 n, rl::vec3 to_eye, rl::vec3 r,
                    rl::vec3 f0, rl::vec3 albedo) const {
        // A broken model's zero or NaN normal: the surface faces the eye.
        if (!(rl::dot(n, n) > 0.5f)) n = to_eye, r = to_eye;
        const float n_dot_v = std::max(rl::dot(n, to_eye), 1e-4f);
        const SpecularShares shares = specular_shares(
            f0, split_sum_table().at(n_dot_v, material.roughness), material.multiple_scattering);
        const rl::vec3 mean_light = light.diffuse->at(n, seed(f)) * (1 / std::numbers::pi_v<float>);
        const rl::vec3 one_bounce =
            material.glossy == Glossy::split_sum
                ? shares.single *
                      light.glossy->sample(along(n, r), material.roughness, mirror_level(f))
                : glossy_monte_carlo(*light.environment, n, to_eye, material.roughness, f0,
                                     material.samples, seed(f));
        const rl::vec3 under = rl::vec3{1, 1, 1} - shares.single - shares.multiple;
        return one_bounce + (shares.multiple + albedo * under) * mean_light;
    }
    // [/doc:glossy-shader]

    rl::vec3 along(rl::vec3 n, rl::vec3 r) const {
        return material.lookup == Lookup::dominant ? dominant_direction(n, r, material.roughness)
                                                   : r;
    }
};

}  // namespace environment
