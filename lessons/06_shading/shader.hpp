// Shaders, the way GPUs are programmed: a type with a vertex function (one
// corner of a face and the shader's own uniforms in; a clip-space position
// and varyings out) and a fragment function (interpolated varyings in; a
// linear colour out, or std::nullopt to discard the pixel). The pipeline of
// lesson 05 runs them: shaders are types checked by a concept, so the calls
// are inlined, with no virtual call per pixel. Derivation:
// docs/06_shading.md#shaders.
//
//   shading::draw(shading::Surface{mesh, normals},
//                 shading::UnlitShader{mvp, {1, 0, 0}},  // shaders.hpp: a complete shader
//                 perspective::target_of(frame), {});
#pragma once

#include <concepts>
#include <optional>
#include <vector>

#include "05_perspective/pipeline.hpp"
#include "colour.hpp"
#include "normals.hpp"

namespace shading {

// What the vertex function sees of one corner (model space).
struct VertexInput {
    rl::vec3 position;
    rl::vec3 normal;       // the corner's unit normal (corner_normals)
    rl::vec3 face_normal;  // the face's unit normal, for flat shading
    rl::vec2 uv;           // (0, 0) where the OBJ gives none
    int face, corner;
};

template <class S>
concept Shader = requires(const S& shader, const VertexInput& in,
                          const perspective::Fragment<typename S::Varyings>& fragment) {
    requires perspective::Varyings<typename S::Varyings>;
    { shader.vertex(in) } -> std::same_as<perspective::ClipVertex<typename S::Varyings>>;
    requires std::same_as<decltype(shader.fragment(fragment)), rl::vec3> ||
        std::same_as<decltype(shader.fragment(fragment)), std::optional<rl::vec3>>;
};

// A varying that is not interpolated: every pixel of a triangle gets the
// value of its first vertex (the "provoking vertex", as in OpenGL). It obeys
// + and * by keeping its left operand, which is all interpolation and
// clipping ever do to it.
template <class T>
struct Flat {
    T value{};
    friend Flat operator+(const Flat& a, const Flat&) { return a; }
    friend Flat operator*(const Flat& a, float) { return a; }
};

// A mesh with a normal per corner, ready to shade.
struct Surface {
    const rl::Mesh& mesh;
    const std::vector<rl::vec3>& normals;  // 3 per face: corner_normals(mesh, ...)
    bool mirrored = false;  // the model matrix mirrors (det < 0): faces turn clockwise
};

// [doc:draw-shader]
// Every face of the surface through the pipeline with this shader; the
// fragment's linear colour is written encoded by `output`.
template <Shader S>
perspective::PipelineCounts draw(const Surface& surface, const S& shader,
                                 perspective::RenderTarget target,
                                 const perspective::PipelineOptions& options,
                                 Output output = Output::srgb) {
    using V = typename S::Varyings;
    const rl::Mesh& mesh = surface.mesh;
    const auto vertex_stage = [&](const rl::Face& face, int k) {
        // A mirroring model matrix reverses every face's winding: take the
        // corners in reverse so that front faces stay counter-clockwise.
        const int corner = surface.mirrored ? (3 - k) % 3 : k;
        const auto index = static_cast<std::size_t>(&face - mesh.faces.data());
        const rl::Corner& c = face.corners[static_cast<std::size_t>(corner)];
        return shader.vertex(
            VertexInput{mesh.position(face, corner),
                        surface.normals[3 * index + static_cast<std::size_t>(corner)],
                        rl::normalize(area_normal(mesh, face)),
                        c.uv >= 0 ? mesh.uvs[static_cast<std::size_t>(c.uv)] : rl::vec2{},
                        static_cast<int>(index), corner});
    };
    const auto pixel_stage = [&](const perspective::Fragment<V>& f) {
        if constexpr (std::same_as<decltype(shader.fragment(f)), rl::vec3>) {
            return encode(shader.fragment(f), output);
        } else {
            const std::optional<rl::vec3> c = shader.fragment(f);
            return c ? std::optional<rl::Rgba>(encode(*c, output)) : std::nullopt;
        }
    };
    return perspective::draw_mesh<V>(mesh, target, options, vertex_stage, pixel_stage);
}
// [/doc:draw-shader]

}  // namespace shading
