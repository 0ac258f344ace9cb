// The lighting of this lesson, in linear light: ambient + diffuse (Lambert)
// + specular, summed over directional lights. Two specular models: Phong's
// (the mirror direction r against the view direction) and Blinn's (the
// half-vector h against the normal). Written once for float (the shaders)
// and double (the lab's analytic sphere). Derivations: docs/06_shading.md#lighting.
//
//   const shading::Lighting<float> lighting = shading::default_lighting(light_direction);
//   const rl::vec3 c = shading::reflected(lighting, normal, to_eye, albedo,
//                                         shading::Specular::blinn_phong);
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "rasterlab/named_enum.hpp"
#include "rasterlab/vec.hpp"

namespace shading {

template <class T>
using Colour = rl::Vec<3, T>;

// A directional light: the unit direction towards it, and its colour (linear).
template <class T>
struct Light {
    rl::Vec<3, T> direction;
    Colour<T> colour;
};

template <class T>
struct Lighting {
    std::vector<Light<T>> lights;
    Colour<T> ambient{T(0.03), T(0.03), T(0.035)};  // light from everywhere, times the albedo
    Colour<T> specular{T(0.35), T(0.35), T(0.35)};  // the specular colour (not tinted by albedo)
    T shininess = 32;                               // the specular exponent
};

enum class Specular { phong, blinn_phong };
RASTERLAB_NAMED_ENUM(Specular, kSpeculars, {Specular::phong, "phong"},
                     {Specular::blinn_phong, "blinn-phong"});

// [doc:reflected]
// The light a surface point sends towards the eye, per unit of light
// arriving, in two parts: what the albedo multiplies (ambient and diffuse),
// and the specular highlight (the light's own colour). n and to_eye are
// unit vectors.
template <class T>
struct Reflection {
    Colour<T> diffuse, specular;
};

// How well the light's reflection lines up with the eye, in [-1, 1]: Phong's
// r . v (r: the light's direction mirrored about n) or Blinn's n . h (h:
// halfway between the light and the eye). n_dot_l is n . l, already known.
template <class T>
T alignment(rl::Vec<3, T> n, rl::Vec<3, T> to_light, rl::Vec<3, T> to_eye, T n_dot_l,
            Specular specular) {
    if (specular == Specular::phong) return rl::dot(n * (2 * n_dot_l) - to_light, to_eye);
    return rl::dot(n, rl::normalize(to_light + to_eye));
}

// The highlight's strength: the alignment to the power `shininess`, with the
// alignment clamped at 0 first. Unclamped, pow of a negative base is NaN for
// a fractional exponent and a false highlight for an even one (docs/06_shading.md#lighting).
template <class T>
T highlight(T alignment, T shininess) {
    // pow(0, 0) is 1: an exponent of 0 makes the highlight cover the lit side.
    // (A base of 0 with any other exponent is 0: no pow needed.)
    const T base = std::max(alignment, T(0));
    return base > 0 || shininess == 0 ? std::pow(base, shininess) : T(0);
}

// What one light adds to a point (no ambient); nothing when it is behind
// the surface. Lighting's colours and exponent are the material's.
template <class T>
Reflection<T> reflection_of(const Light<T>& light, const Lighting<T>& material, rl::Vec<3, T> n,
                            rl::Vec<3, T> to_eye, Specular specular) {
    const T n_dot_l = rl::dot(n, light.direction);
    if (!(n_dot_l > 0)) return {};  // the light is behind the surface (or n is NaN)
    const T s = alignment(n, light.direction, to_eye, n_dot_l, specular);
    return {light.colour * n_dot_l,
            light.colour * material.specular * highlight(s, material.shininess)};
}

template <class T>
Reflection<T> reflection(const Lighting<T>& lighting, rl::Vec<3, T> n, rl::Vec<3, T> to_eye,
                         Specular specular) {
    Reflection<T> out{lighting.ambient, {}};
    for (const Light<T>& light : lighting.lights) {
        const Reflection<T> one = reflection_of(light, lighting, n, to_eye, specular);
        out.diffuse += one.diffuse;
        out.specular += one.specular;
    }
    return out;
}

template <class T>
Colour<T> reflected(const Lighting<T>& lighting, rl::Vec<3, T> n, rl::Vec<3, T> to_eye,
                    Colour<T> albedo, Specular specular) {
    const Reflection<T> r = reflection(lighting, n, to_eye, specular);
    return albedo * r.diffuse + r.specular;
}
// [/doc:reflected]

// The lesson's two lights: a key light from `direction` and a dim fill light
// from the opposite side, below, so that no face is left pure black.
// (The fill's direction is built from the key's unit direction: from the raw
// one, --light 1 1 1 and --light 3 3 3 would light the scene differently.)
template <class T>
Lighting<T> default_lighting(rl::Vec<3, T> direction) {
    const rl::Vec<3, T> key = rl::normalize(direction);
    Lighting<T> lighting;
    lighting.lights.push_back({key, {T(1), T(0.97), T(0.92)}});
    lighting.lights.push_back(
        {rl::normalize(rl::Vec<3, T>{-key.x, -T(0.3) * std::abs(key.y) - T(0.2), -key.z * T(0.5)}),
         {T(0.12), T(0.14), T(0.18)}});
    return lighting;
}

}  // namespace shading
