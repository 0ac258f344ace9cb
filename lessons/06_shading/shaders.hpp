// The lesson's four shading models as shaders, sharing one set of uniforms:
//   flat        one normal per face, lit once per face (at its first vertex);
//   gouraud     lit at each vertex with its own normal, the light interpolated;
//   phong       the normal interpolated and lit at each pixel, Phong's specular;
//   blinn-phong the same with Blinn's half-vector specular.
// The albedo comes from the diffuse texture at each pixel in every model.
//
//   shading::Uniforms u;  // member by member: see scene.cpp
//   u.model_matrix = model;
//   u.normal_matrix = *shading::normal_matrix(model);  // empty for a singular model
//   u.model_view_projection = view_projection * model;
//   u.eye = camera.eye;
//   u.lighting = lighting;
//   u.texture = &chain;
//   shading::draw(surface, shading::PhongShader{u, shading::Specular::blinn_phong}, target, {});
#pragma once

#include "04_textures/sampling.hpp"
#include "lighting.hpp"
#include "shader.hpp"

namespace shading {

enum class ShadingModel { flat, gouraud, phong, blinn_phong };
RASTERLAB_NAMED_ENUM(ShadingModel, kShadingModels, {ShadingModel::flat, "flat"},
                     {ShadingModel::gouraud, "gouraud"}, {ShadingModel::phong, "phong"},
                     {ShadingModel::blinn_phong, "blinn-phong"});

// What every shader of this lesson reads and no vertex changes.
struct Uniforms {
    rl::mat4 model_matrix;   // model to world
    rl::mat3 normal_matrix;  // shading::normal_matrix(model_matrix)
    rl::mat4 model_view_projection;
    rl::vec3 eye;  // world space
    Lighting<float> lighting;
    const textures::MipChain* texture = nullptr;  // none: albedo `colour`
    textures::SamplerState sampler{};
    rl::vec3 colour{0.8f, 0.8f, 0.8f};  // linear albedo without a texture

    rl::vec3 world(rl::vec3 p) const { return (model_matrix * rl::extend(p, 1.0f)).xyz(); }
    rl::vec3 world_normal(rl::vec3 n) const { return rl::normalize(normal_matrix * n); }
    pipeline::ClipPosition clip(rl::vec3 p) const {
        return pipeline::clip_position(model_view_projection, p);
    }
    // The diffuse colour at a pixel: the texture (mip level from the pixel's
    // UV derivatives, lesson 05) or the plain colour.
    rl::vec3 albedo(rl::vec2 uv, rl::vec2 d_dx, rl::vec2 d_dy) const;
};

// The light reflected at a vertex, for flat and Gouraud shading (the
// albedo still multiplies its diffuse part at each pixel).
Reflection<float> light_at(const Uniforms& u, rl::vec3 world_position, rl::vec3 world_normal);

// [doc:unlit-shader]
// The smallest shader: one colour, no light. A model of how to write one.
struct UnlitShader {
    rl::mat4 model_view_projection;
    rl::vec3 colour;         // linear
    using Varyings = float;  // nothing to carry to the pixels
    pipeline::ClipVertex<float> vertex(const SurfaceCorner& in) const {
        return {pipeline::clip_position(model_view_projection, in.position()), 0.0f};
    }
    rl::vec3 fragment(const pipeline::Fragment<float>&) const { return colour; }
};
// [/doc:unlit-shader]

// [doc:flat-shader]
struct FlatShader {
    const Uniforms& u;
    using Varyings = rl::vec2;       // the texture coordinates
    using Flat = Reflection<float>;  // the light, from the face's first vertex
    pipeline::ClipVertex<Varyings, Flat> vertex(const SurfaceCorner& in) const {
        return {u.clip(in.position()), in.uv(),
                light_at(u, u.world(in.position()), u.world_normal(in.face_normal()))};
    }
    rl::vec3 fragment(const pipeline::Fragment<Varyings, Flat>& f) const {
        const Reflection<float>& l = f.flat();
        return u.albedo(f.varyings, f.d_dx(), f.d_dy()) * l.diffuse + l.specular;
    }
};
// [/doc:flat-shader]

struct GouraudShader {
    const Uniforms& u;
    struct Varyings {
        rl::vec3 diffuse, specular;  // light computed at the vertices, interpolated
        rl::vec2 uv;
    };
    pipeline::ClipVertex<Varyings> vertex(const SurfaceCorner& in) const {
        const Reflection<float> l =
            light_at(u, u.world(in.position()), u.world_normal(in.normal()));
        return {u.clip(in.position()), {l.diffuse, l.specular, in.uv()}};
    }
    rl::vec3 fragment(const pipeline::Fragment<Varyings>& f) const {
        return u.albedo(f.varyings.uv, f.d_dx(&Varyings::uv), f.d_dy(&Varyings::uv)) *
                   f.varyings.diffuse +
               f.varyings.specular;
    }
};

// [doc:phong-shader]
struct PhongShader {
    const Uniforms& u;
    Specular specular;  // Phong's or Blinn's highlight
    struct Varyings {
        rl::vec3 position, normal;  // world space, interpolated across the face
        rl::vec2 uv;
    };
    pipeline::ClipVertex<Varyings> vertex(const SurfaceCorner& in) const {
        return {u.clip(in.position()),
                {u.world(in.position()), u.world_normal(in.normal()), in.uv()}};
    }
    rl::vec3 fragment(const pipeline::Fragment<Varyings>& f) const {
        // An interpolated unit normal is shorter than 1 between the vertices:
        // normalise it again, or the light dims and the highlight spreads.
        const rl::vec3 n = rl::normalize(f.varyings.normal);
        const rl::vec3 to_eye = rl::normalize(u.eye - f.varyings.position);
        return reflected(u.lighting, n, to_eye,
                         u.albedo(f.varyings.uv, f.d_dx(&Varyings::uv), f.d_dy(&Varyings::uv)),
                         specular);
    }
};
// [/doc:phong-shader]

// Draws the surface with the chosen shading model.
pipeline::PipelineCounts draw_model(ShadingModel model, const Surface& surface, const Uniforms& u,
                                    pipeline::ColourTarget& target,
                                    const pipeline::PipelineOptions& options, Output output);

}  // namespace shading
