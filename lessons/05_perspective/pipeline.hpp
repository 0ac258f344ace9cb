// The pipeline every drawing lesson from here on goes through, in the order a
// GPU runs it:
//
//   vertex stage -> clip space -> back-face cull -> clip -> divide by w
//     -> viewport -> rasterizer (lesson 02) -> early depth test (lesson 03)
//     -> per-pixel stage -> colour
//
// A lesson supplies two functions: the vertex stage turns one corner of a
// face into a clip-space position and the attributes ("varyings") to carry
// to the pixels; the per-pixel stage turns a Fragment (the interpolated
// varyings, their screen derivatives on request) into a colour. Everything
// between is here, once, and every drawing lesson from 05 on goes through
// it (lessons 02-04 drew through lesson 02's shorter loop, draw_faces.hpp).
// Derivations: docs/05_perspective.md.
//
//   const rl::mat4 mvp = perspective::view_projection(camera, aspect) * model;
//   perspective::draw_mesh<rl::vec2>(
//       mesh, {frame.colour, &frame.depth}, options,
//       [&](const rl::Face& face, int corner) {   // vertex stage
//           return perspective::ClipVertex<rl::vec2>{
//               mvp * rl::extend(mesh.position(face, corner), 1.0f), uv_of(face, corner)};
//       },
//       [&](const perspective::Fragment<rl::vec2>& f) {  // per-pixel stage
//           return colour_at(f.varyings, f.d_dx(), f.d_dy());
//       });
#pragma once

#include "rasterlab/named_enum.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <type_traits>

#include "02_triangles/raster.hpp"
#include "03_zbuffer/depth_test.hpp"
#include "03_zbuffer/hidden_surfaces.hpp"
#include "camera.hpp"
#include "clipping.hpp"
#include "rasterlab/mesh.hpp"
#include "rasterlab/transform.hpp"

namespace perspective {

// How varyings are interpolated between a triangle's vertices: linearly in
// the window (what lessons 02-04 did; wrong under perspective) or linearly
// in the surface, by interpolating varyings / w and 1 / w and dividing.
enum class Interpolation { affine, perspective };
inline constexpr std::array<rl::Named<Interpolation>, 2> kInterpolationNames = {
    {{Interpolation::affine, "affine"}, {Interpolation::perspective, "perspective"}}};
inline constexpr std::array<Interpolation, 2> kInterpolations = rl::values_of(kInterpolationNames);
inline const char* name(Interpolation value) {
    return rl::name_in(kInterpolationNames, value);
}

struct PipelineOptions {
    ClipMode clip = ClipMode::guard_band;
    Interpolation interpolation = Interpolation::perspective;
    bool cull_back_faces = true;
    bool cull_objects = true;  // skip a model whose bounding box is outside the frustum
    triangles::RasterMethod raster = triangles::RasterMethod::edge;  // lesson 02's three
};

// Where the pipeline draws: a colour image and a depth image of the same
// size for the depth test, or none (the last triangle drawn wins, as in
// lesson 02).
struct RenderTarget {
    rl::Image& colour;
    rl::FloatImage* depth = nullptr;
};

inline RenderTarget target_of(zbuffer::Frame& frame) {
    return {frame.colour, &frame.depth};
}

// What became of the work: every count the lab reports.
struct PipelineCounts {
    std::size_t objects_culled = 0;  // models skipped whole by their bounding box
    std::size_t faces = 0;           // faces that reached the vertex stage
    std::size_t back_faces = 0;      // culled as facing away
    std::size_t outside = 0;         // nothing left after clipping
    std::size_t clipped = 0;         // cut by at least one plane
    std::size_t drawn = 0;           // triangles rasterized (a clipped face may give several)
    std::size_t refused = 0;         // refused by the rasterizer (beyond 2^22 pixels, NaN)
    std::size_t fragments = 0;       // pixels that passed the depth test and were shaded
    PipelineCounts& operator+=(const PipelineCounts& o);
};

// The per-triangle constants the per-pixel step needs, computed once after
// the viewport transform (the "triangle setup" of a GPU).
template <Varyings V>
struct TriangleSetup {
    rl::vec3 window[3];  // x, y in pixels, z the window depth in [0, 1]
    V vertex[3];         // the varyings at the three vertices
    float inverse_w[3];  // 1 / w (all 1 for affine interpolation)
    bool perspective_correct = true;
    V over_w[3];                 // varyings / w
    V d_over_w_dx, d_over_w_dy;  // screen derivatives of sum(b_i varyings_i / w_i) ...
    float d_inverse_w_dx = 0, d_inverse_w_dy = 0;  // ... and of sum(b_i / w_i)
    int face = 0;                                  // the mesh face it came from
};

// One pixel reaching the per-pixel stage.
template <Varyings V>
struct Fragment {
    int x, y;
    float depth;
    V varyings;
    float inverse_w;  // interpolated 1 / w at this pixel
    const TriangleSetup<V>* triangle;
    int face() const { return triangle->face; }
    // How the varyings change per pixel to the right (d_dx) and up (d_dy):
    // exact for either interpolation, from the quotient rule on
    // varyings = (varyings / w) / (1 / w), both of which are linear on screen.
    V d_dx() const {
        return (triangle->d_over_w_dx + varyings * -triangle->d_inverse_w_dx) * (1 / inverse_w);
    }
    V d_dy() const {
        return (triangle->d_over_w_dy + varyings * -triangle->d_inverse_w_dy) * (1 / inverse_w);
    }
};

// Back-face test in clip space, before the divide: the sign of det[x y w]
// is the sign of the volume of the tetrahedron (eye, v0, v1, v2), so it says
// which side of the face's plane the eye is on even when some w <= 0, where
// the window-space area would flip. Positive: counter-clockwise, facing the eye.
inline float facing(const rl::vec4& a, const rl::vec4& b, const rl::vec4& c) {
    return rl::dot(rl::vec3{a.x, a.y, a.w},
                   rl::cross(rl::vec3{b.x, b.y, b.w}, rl::vec3{c.x, c.y, c.w}));
}

// Whether a box (in model space) lies wholly outside one plane of the
// frustum of `model_view_projection`: then nothing in it can be seen.
bool outside_frustum(const Box& box, const rl::mat4& model_view_projection);

// [doc:triangle-setup]
// Divide, viewport, and the constants of the per-pixel step for one triangle
// of clip-space vertices.
template <Varyings V>
TriangleSetup<V> set_up(const ClipVertex<V>& a, const ClipVertex<V>& b, const ClipVertex<V>& c,
                        Interpolation interpolation, int width, int height, int face) {
    TriangleSetup<V> t;
    const ClipVertex<V>* v[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
        const rl::vec4& p = v[k]->position;
        const float inverse_w = 1 / p.w;
        t.window[k] = rl::ndc_to_window(p.xyz() * inverse_w, width, height);
        t.vertex[k] = v[k]->varyings;
        t.inverse_w[k] = interpolation == Interpolation::perspective ? inverse_w : 1.0f;
        t.over_w[k] = t.vertex[k] * t.inverse_w[k];
    }
    t.perspective_correct = interpolation == Interpolation::perspective;
    // The barycentric weight b_k is linear on screen: b_k = E_k / (2 area),
    // where E_k is the edge function of the edge opposite vertex k, so
    // db_k/dx = -(y_j - y_i) / (2 area) and db_k/dy = (x_j - x_i) / (2 area).
    const float area2 =
        triangles::signed_area2({{t.window[0].xy(), t.window[1].xy(), t.window[2].xy()}});
    const float inverse_area2 = area2 != 0 ? 1 / area2 : 0.0f;
    for (int k = 0; k < 3; ++k) {
        const rl::vec3 &i = t.window[(k + 1) % 3], &j = t.window[(k + 2) % 3];
        const float db_dx = (i.y - j.y) * inverse_area2, db_dy = (j.x - i.x) * inverse_area2;
        t.d_over_w_dx = t.d_over_w_dx + t.over_w[k] * db_dx;
        t.d_over_w_dy = t.d_over_w_dy + t.over_w[k] * db_dy;
        t.d_inverse_w_dx += t.inverse_w[k] * db_dx;
        t.d_inverse_w_dy += t.inverse_w[k] * db_dy;
    }
    t.face = face;
    return t;
}
// [/doc:triangle-setup]

template <class T>
inline constexpr bool kIsOptional = false;
template <class T>
inline constexpr bool kIsOptional<std::optional<T>> = true;

// [doc:draw-setup]
// Rasterizes one set-up triangle: lesson 02's rasterizer, lesson 03's depth
// test (window depth is linear on screen, so it is interpolated with the
// plain weights), then the varyings, then the per-pixel stage. Under
// perspective the varyings are b . (varyings / w) divided by b . (1 / w);
// affine interpolation is b . varyings. The depth test runs before the
// per-pixel stage (early) unless that stage may discard the pixel (it
// returns std::optional): then the stage runs on pixels that would pass, and
// only a pixel it keeps writes its depth (late). Returns false if refused.
template <Varyings V, class PixelStage>
bool rasterize_setup(const TriangleSetup<V>& t, RenderTarget target, triangles::RasterMethod method,
                     PixelStage& pixel_stage, std::size_t& fragments) {
    using Result = std::invoke_result_t<PixelStage&, const Fragment<V>&>;
    constexpr bool late_depth = kIsOptional<Result>;
    const triangles::ScreenTriangle screen{{t.window[0].xy(), t.window[1].xy(), t.window[2].xy()}};
    const int width = target.colour.width(), height = target.colour.height();
    return triangles::rasterize(method, screen, width, height, [&](int x, int y, rl::vec3 b) {
        const float z = zbuffer::interpolate_depth(b, t.window[0].z, t.window[1].z, t.window[2].z);
        if constexpr (late_depth) {
            if (target.depth && !(z < target.depth->at(x, y))) return;
        } else {
            if (target.depth && !zbuffer::passes_depth_test(*target.depth, x, y, z)) return;
        }
        const V over_w = t.over_w[0] * b.x + t.over_w[1] * b.y + t.over_w[2] * b.z;
        float inverse_w = 1;
        V varyings = over_w;
        if (t.perspective_correct) {
            inverse_w = b.x * t.inverse_w[0] + b.y * t.inverse_w[1] + b.z * t.inverse_w[2];
            varyings = over_w * (1 / inverse_w);
        }
        const Fragment<V> fragment{x, y, z, varyings, inverse_w, &t};
        if constexpr (late_depth) {
            const Result kept = pixel_stage(fragment);
            if (!kept) return;  // discarded: neither colour nor depth
            if (target.depth) target.depth->at(x, y) = z;
            target.colour.at(x, y) = *kept;
        } else {
            target.colour.at(x, y) = pixel_stage(fragment);
        }
        ++fragments;
    });
}
// [/doc:draw-setup]

// [doc:assemble-triangle]
// One face from clip space to window space: back-face cull, clip (a face
// may become a fan of up to 7 triangles), divide and viewport. Calls
// emit(TriangleSetup) for each triangle to rasterize.
template <Varyings V, class Emit>
void assemble_triangle(const std::array<ClipVertex<V>, 3>& v, const ClipPlanes& planes,
                       const PipelineOptions& options, int width, int height, int face,
                       PipelineCounts& counts, Emit&& emit) {
    ++counts.faces;
    // Not "culled unless > 0": a face whose sign is NaN goes on, for the
    // rasterizer to refuse and count.
    if (options.cull_back_faces && facing(v[0].position, v[1].position, v[2].position) <= 0) {
        ++counts.back_faces;
        return;
    }
    const rl::vec4 positions[3] = {v[0].position, v[1].position, v[2].position};
    if (inside_all(planes, positions))
        return emit(set_up(v[0], v[1], v[2], options.interpolation, width, height, face));
    const ClipPolygon<V> polygon = clip_triangle(v, planes);
    if (polygon.size < 3) {
        ++counts.outside;
        return;
    }
    ++counts.clipped;
    for (int i = 1; i + 1 < polygon.size; ++i)  // a convex polygon as a fan of triangles
        emit(set_up(polygon.vertices[0], polygon.vertices[static_cast<std::size_t>(i)],
                    polygon.vertices[static_cast<std::size_t>(i + 1)], options.interpolation, width,
                    height, face));
}
// [/doc:assemble-triangle]

// One face through every stage after the vertex stage.
template <Varyings V, class PixelStage>
void draw_triangle(const std::array<ClipVertex<V>, 3>& v, const ClipPlanes& planes,
                   const PipelineOptions& options, RenderTarget target, PixelStage& pixel_stage,
                   int face, PipelineCounts& counts) {
    assemble_triangle(v, planes, options, target.colour.width(), target.colour.height(), face,
                      counts, [&](const TriangleSetup<V>& t) {
                          const bool ok = rasterize_setup(t, target, options.raster, pixel_stage,
                                                          counts.fragments);
                          ++(ok ? counts.drawn : counts.refused);
                      });
}

// [doc:draw-mesh]
// Every face of a mesh: vertex_stage(face, corner) -> ClipVertex<V> for
// each corner, then draw_triangle. The caller does the object-level culling
// (outside_frustum), since only it knows the model's box.
template <Varyings V, class VertexStage, class PixelStage>
PipelineCounts draw_mesh(const rl::Mesh& mesh, RenderTarget target, const PipelineOptions& options,
                         VertexStage&& vertex_stage, PixelStage&& pixel_stage) {
    PipelineCounts counts;
    const ClipPlanes planes =
        clip_planes(options.clip, target.colour.width(), target.colour.height());
    int index = 0;
    for (const rl::Face& face : mesh.faces) {
        const std::array<ClipVertex<V>, 3> v = {vertex_stage(face, 0), vertex_stage(face, 1),
                                                vertex_stage(face, 2)};
        draw_triangle(v, planes, options, target, pixel_stage, index++, counts);
    }
    return counts;
}
// [/doc:draw-mesh]

}  // namespace perspective
