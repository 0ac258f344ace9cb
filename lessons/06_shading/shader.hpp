// Shaders, the way GPUs are programmed: a type with a vertex function (one
// corner of a surface and the shader's own uniforms in; a clip-space
// position and varyings out) and a fragment function (interpolated varyings
// in; a linear colour out). Lesson 05's pipeline runs them: shaders are types
// checked by a concept, so the calls are inlined, with no virtual call per
// pixel. A shader declares what else it does: `using Flat = ...` for values
// taken from the face's first vertex and not interpolated, and
// `static constexpr bool may_discard = true` when fragment() returns
// std::optional (std::nullopt discards the pixel). Derivation:
// docs/06_shading.md#shaders.
//
//   shading::draw(shading::Surface(mesh, normals),
//                 shading::UnlitShader{mvp, {1, 0, 0}},  // shaders.hpp: a complete shader
//                 frame, {});
#pragma once

#include <concepts>
#include <optional>
#include <vector>

#include "05_perspective/pipeline.hpp"
#include "colour.hpp"
#include "normals.hpp"

namespace shading {

// One corner of a surface as the vertex function reads it: lesson 05's mesh
// corner (position, uv) and its unit normal.
struct SurfaceCorner : pipeline::MeshCorner {
    const std::vector<rl::vec3>* normals;  // 3 per face
    rl::vec3 normal() const {
        return (*normals)[3 * static_cast<std::size_t>(face) + static_cast<std::size_t>(corner)];
    }
    rl::vec3 face_normal() const {
        return rl::cast<float>(rl::normalize(area_normal(*mesh, mesh_face())));
    }
};

// A mesh with a normal per corner, ready to shade; mirroring as lesson 05's
// MeshView decides it from the model matrix.
struct Surface {
    pipeline::MeshView view;
    const std::vector<rl::vec3>* normals;  // 3 per face: corner_normals(mesh, ...)
    Surface(const rl::Mesh& mesh, const std::vector<rl::vec3>& corner_normals,
            const rl::mat4& model = rl::mat4::identity())
        : view(mesh, model), normals(&corner_normals) {}
    int face_count() const { return view.face_count(); }
    SurfaceCorner corner(int face, int k) const { return {view.corner(face, k), normals}; }
};

template <class S>
concept Shader = pipeline::Program<S, SurfaceCorner> &&
    requires(const S& shader,
             const pipeline::Fragment<typename S::Varyings, pipeline::FlatOf<S>>& f) {
    shader.fragment(f);
};

// A shader's colour encoded for an 8-bit target by `output` (sRGB or naive).
template <Shader S>
struct Encoded {
    const S& shader;
    Output output;
    using Varyings = typename S::Varyings;
    using Flat = pipeline::FlatOf<S>;
    static constexpr bool may_discard = pipeline::ProgramTraits<S>::may_discard;
    pipeline::ClipVertex<Varyings, Flat> vertex(const SurfaceCorner& c) const {
        return shader.vertex(c);
    }
    auto fragment(const pipeline::Fragment<Varyings, Flat>& f) const {
        if constexpr (may_discard) {
            const std::optional<rl::vec3> c = shader.fragment(f);
            return c ? std::optional<rl::Rgba>(encode(*c, output)) : std::nullopt;
        } else {
            return encode(shader.fragment(f), output);
        }
    }
};

// [doc:draw-shader]
// Every face of the surface through the pipeline with this shader; the
// fragment's linear colour is written encoded by `output`.
template <Shader S>
pipeline::PipelineCounts draw(const Surface& surface, const S& shader,
                              pipeline::ColourTarget& target,
                              const pipeline::PipelineOptions& options,
                              Output output = Output::srgb) {
    return pipeline::draw(surface, Encoded<S>{shader, output}, target, options);
}
// [/doc:draw-shader]

}  // namespace shading
