// Stages 1-4 of lesson 05's pipeline: the vertex stage, back-face culling
// in clip space, clipping, the divide and the viewport, for every face of a
// geometry (a MeshView, or any type with face_count() and corner(face, k)),
// each triangle that comes out handed to the caller set up for the rasterizer.
//
//   pipeline::assemble(pipeline::MeshView(mesh), program, 800, 600, options, counts,
//                         [&](const auto& t) { /* stages 5-8 for triangle t */ });
#pragma once

#include <array>

#include "camera.hpp"
#include "clipping.hpp"
#include "pipeline_options.hpp"
#include "program.hpp"
#include "rasterlab/mesh.hpp"
#include "rasterlab/transform.hpp"
#include "triangle_setup.hpp"

namespace pipeline {

// One corner of a mesh face, its attributes read on request.
struct MeshCorner {
    const rl::Mesh* mesh;
    int face, corner;
    const rl::Face& mesh_face() const { return mesh->faces[static_cast<std::size_t>(face)]; }
    rl::vec3 position() const { return mesh->position(mesh_face(), corner); }
    rl::vec2 uv() const {  // (0, 0) where the OBJ gives none
        const int t = mesh_face().corners[static_cast<std::size_t>(corner)].uv;
        return t >= 0 ? mesh->uvs[static_cast<std::size_t>(t)] : rl::vec2{};
    }
};

// A mesh as the pipeline reads it. A model matrix that mirrors (negative
// determinant) turns every face clockwise on screen; the view then hands the
// corners over in the order 0, 2, 1 so that front faces stay
// counter-clockwise. This is the one place mirroring is decided.
struct MeshView {
    const rl::Mesh* mesh;
    bool mirrored = false;
    MeshView(const rl::Mesh& m, const rl::mat4& model = rl::mat4::identity())
        : mesh(&m), mirrored(rl::determinant(rl::linear_part(model)) < 0) {}
    int face_count() const { return static_cast<int>(mesh->faces.size()); }
    // The mesh's corner handed over as corner k of a face: 0, 2, 1 when
    // mirrored. The order is its own inverse: the mesh's corner k is also
    // handed over as corner mesh_corner(k).
    int mesh_corner(int k) const { return mirrored && k != 0 ? 3 - k : k; }
    MeshCorner corner(int face, int k) const { return {mesh, face, mesh_corner(k)}; }
};

// Back-face test in clip space, before the divide: the sign of det[x y w]
// is the sign of the volume of the tetrahedron (eye, v0, v1, v2), so it says
// which side of the face's plane the eye is on even when some w <= 0, where
// the window-space area would flip. Positive: counter-clockwise, facing the eye.
inline double facing(const ClipPosition& a, const ClipPosition& b, const ClipPosition& c) {
    return rl::dot(rl::dvec3{a.x, a.y, a.w},
                   rl::cross(rl::dvec3{b.x, b.y, b.w}, rl::dvec3{c.x, c.y, c.w}));
}

// Whether a box (in model space) lies wholly outside one plane of the
// frustum of `model_view_projection`: then nothing in it can be seen.
bool outside_frustum(const Box& box, const rl::mat4& model_view_projection);

// A face that is not inside every plane, cut against them (assemble_face
// sends a face inside them all on as it is); counts it as cut or as wholly
// outside.
template <Interpolable V, class F>
ClipPolygon<V> clip_face(const std::array<ClipVertex<V, F>, 3>& v, const ClipPlanes& planes,
                         PipelineCounts& counts) {
    const std::array<ClipVertex<V>, 3> corners = {ClipVertex<V>{v[0].position, v[0].varyings},
                                                  ClipVertex<V>{v[1].position, v[1].varyings},
                                                  ClipVertex<V>{v[2].position, v[2].varyings}};
    const ClipPolygon<V> polygon = clip_triangle(corners, planes);
    ++(polygon.size < 3 ? counts.outside : counts.clipped);
    return polygon;
}

// [doc:assemble]
// Stages 2-4 for one face, its corners a, b, c out of the vertex stage, for
// a target of width x height pixels whose clip planes are `planes`: each
// triangle that comes out, set up for the rasterizer, goes to emit(t).
// Counts the face if culled, clipped or wholly outside.
template <Interpolable V, class F, class Emit>
void assemble_face(const ClipVertex<V, F>& a, const ClipVertex<V, F>& b, const ClipVertex<V, F>& c,
                   int face, const ClipPlanes& planes, int width, int height,
                   const PipelineOptions& options, PipelineCounts& counts, Emit&& emit) {
    // 2. Back faces culled by the sign of det[x y w]. Not "culled unless
    // > 0": a face whose sign is NaN goes on, for the rasterizer to refuse.
    if (options.cull != Cull::none) {
        const double area = facing(a.position, b.position, c.position);
        if (options.cull == Cull::back ? area <= 0 : area >= 0) {
            ++counts.culled;
            return;
        }
    }
    // 3. Clipping. Most faces are inside every plane and go on as they are,
    // not copied into a polygon (lesson 12 sets up a million faces a frame);
    // the others become a convex polygon, drawn as a fan.
    const ClipPosition positions[3] = {a.position, b.position, c.position};
    if (inside_all(planes, positions)) {
        // 4. Divide and viewport.
        emit(set_up(a, b, c, a.flat, face, options.interpolation, width, height));
        return;
    }
    const ClipPolygon<V> polygon = clip_face<V, F>({a, b, c}, planes, counts);
    for (int i = 1; i + 1 < polygon.size; ++i)
        // 4. Divide and viewport; the flat values come from the first vertex.
        emit(set_up(polygon.vertices[0], polygon.vertices[static_cast<std::size_t>(i)],
                    polygon.vertices[static_cast<std::size_t>(i + 1)], a.flat, face,
                    options.interpolation, width, height));
}

// Stages 1-4 for every face of the geometry: the vertex stage, then the above.
template <class Geometry, class P, class Emit>
void assemble(const Geometry& geometry, const P& program, int width, int height,
              const PipelineOptions& options, PipelineCounts& counts, Emit&& emit) {
    const ClipPlanes planes = clip_planes(options.clip, width, height);
    for (int face = 0; face < geometry.face_count(); ++face) {
        ++counts.faces;
        // 1. The vertex stage: each corner to clip space, with its varyings.
        const std::array<ClipVertex<typename P::Varyings, FlatOf<P>>, 3> v = {
            program.vertex(geometry.corner(face, 0)), program.vertex(geometry.corner(face, 1)),
            program.vertex(geometry.corner(face, 2))};
        assemble_face(v[0], v[1], v[2], face, planes, width, height, options, counts, emit);
    }
}
// [/doc:assemble]

}  // namespace pipeline
