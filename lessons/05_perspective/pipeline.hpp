// The pipeline every drawing lesson from 05 on goes through, in the order a
// GPU runs it:
//
//   vertex stage -> back-face cull -> clip -> divide and viewport
//     -> rasterize (lesson 02) -> depth test (lesson 03) -> fragment stage -> store
//
// A lesson hands draw() three things: the geometry (a MeshView, or any type
// with face_count() and corner(face, k)), a program, and a render target. A
// program is a type with a vertex function (one corner in; a clip-space
// position, the varyings to interpolate and, optionally, flat values out) and
// a fragment function (the interpolated varyings at one pixel in; one value
// per colour attachment of the target out). Everything between is here, once
// (lessons 02-04 drew through lesson 02's shorter loop, draw_faces.hpp).
// Derivations: docs/05_perspective.md.
//
//   struct TexturedProgram {
//       rl::mat4 mvp; const textures::MipChain& texture;
//       using Varyings = rl::vec2;                     // texture coordinates
//       perspective::ClipVertex<rl::vec2> vertex(const perspective::MeshCorner& c) const {
//           return {perspective::clip_position(mvp, c.position()), c.uv()};
//       }
//       rl::Rgba fragment(const perspective::Fragment<rl::vec2>& f) const {
//           const rl::vec4 texel = textures::sample(texture, f.varyings, {f.d_dx(), f.d_dy()}, {});
//           return textures::to_rgba(texel);
//       }
//   };
//   perspective::ColourTarget frame = perspective::colour_target(800, 600);
//   perspective::draw(perspective::MeshView(mesh, model), TexturedProgram{mvp, chain}, frame);
#pragma once

#include "rasterlab/named_enum.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "02_triangles/bands.hpp"
#include "02_triangles/raster.hpp"
#include "03_zbuffer/depth_test.hpp"
#include "camera.hpp"
#include "clipping.hpp"
#include "rasterlab/mesh.hpp"
#include "rasterlab/transform.hpp"
#include "render_target.hpp"
#include "varyings.hpp"

namespace perspective {

// How varyings are interpolated between a triangle's vertices: linearly in
// the window (what lessons 02-04 did; wrong under perspective) or linearly
// on the surface, by interpolating varyings / w and 1 / w and dividing.
enum class Interpolation { affine, perspective_correct };
inline constexpr std::array<rl::Named<Interpolation>, 2> kInterpolationNames = {
    {{Interpolation::affine, "affine"}, {Interpolation::perspective_correct, "perspective"}}};
inline constexpr std::array<Interpolation, 2> kInterpolations = rl::values_of(kInterpolationNames);
inline const char* name(Interpolation value) {
    return rl::name_in(kInterpolationNames, value);
}

// What a draw may change; the defaults are what the lessons teach, the rest
// is for the lab to compare.
// Faces dropped by their winding on screen: none, those facing away (the
// default: a closed mesh's far side), or those facing the eye (lesson 08
// renders a shadow map from the back faces).
enum class Cull { none, back, front };

struct PipelineOptions {
    ClipMode clip = ClipMode::guard_band;
    Interpolation interpolation = Interpolation::perspective_correct;
    Cull cull = Cull::back;  // which faces the culling step drops
    triangles::RasterMethod raster = triangles::RasterMethod::edge;  // lesson 02's three
    std::optional<triangles::PixelRect> tile;  // draw only these pixels (default: all)
    // The most samples one draw may visit, in whole targets: 1000 times every
    // sample. The rasterizer visits every sample of a triangle's bounding box
    // within the target, so without a bound one screen-filling triangle
    // repeated 100 000 times (a 1.4 MB OBJ) took 119 s, and a fan of 409 400
    // thin triangles (2 MB) 35 s; a real scene's boxes cover its image a few
    // times over. 0: no bound.
    double max_overdraw = 1000;
};

// What draw() throws when a draw visits more than max_overdraw targets.
struct OverdrawError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What became of the work: every count the lab reports. Counts of separate
// draws (models, tiles) add up with +=.
struct PipelineCounts {
    std::size_t objects_culled = 0;  // models skipped whole by their bounding box
    std::size_t faces = 0;           // faces that reached the vertex stage
    std::size_t culled = 0;   // by their winding: facing away (Cull::back) or towards (Cull::front)
    std::size_t outside = 0;  // nothing left after clipping
    std::size_t clipped = 0;  // cut by at least one plane
    std::size_t drawn = 0;    // triangles rasterized (a clipped face may give several)
    std::size_t refused = 0;  // refused by the rasterizer (beyond 2^22 pixels, NaN)
    std::size_t visited = 0;  // samples of the triangles' boxes the rasterizer tested
    std::size_t shaded = 0;   // runs of the fragment stage (once per stored pixel, but where
                              // the program discards; once per pixel under multisampling)
    std::size_t stored = 0;   // samples that passed the depth test and were not discarded
    PipelineCounts& operator+=(const PipelineCounts& o);
};

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
    MeshCorner corner(int face, int k) const { return {mesh, face, mirrored ? (3 - k) % 3 : k}; }
};

// A program's flat values (not interpolated: every pixel of a triangle gets
// those of the face's first vertex, its "provoking vertex" as Direct3D and
// Vulkan choose it; OpenGL's default is the last), and whether its fragment
// stage may discard a pixel. Both are declared by the program: `using Flat
// = ...;` and `static constexpr bool may_discard = true;` (then fragment()
// returns std::optional); a program that declares neither has neither.
template <class P>
struct ProgramTraits {
    static constexpr auto flat() {
        if constexpr (requires { typename P::Flat; })
            return std::type_identity<typename P::Flat>{};
        else
            return std::type_identity<NoFlat>{};
    }
    using Flat = typename decltype(flat())::type;
    static constexpr bool may_discard = [] {
        if constexpr (requires { P::may_discard; })
            return static_cast<bool>(P::may_discard);
        else
            return false;
    }();
};
template <class P>
using FlatOf = typename ProgramTraits<P>::Flat;

template <class P, class Corner>
concept Program = Interpolable<typename P::Varyings> && requires(const P& p, const Corner& c) {
    { p.vertex(c) } -> std::same_as<ClipVertex<typename P::Varyings, FlatOf<P>>>;
};

// [doc:triangle-setup]
// The per-triangle constants the per-pixel work needs, computed once after
// the divide and the viewport (a GPU's "triangle setup").
template <Interpolable V, class F = NoFlat>
struct TriangleSetup {
    rl::vec3 window[3];  // x, y in pixels, z the window depth in [0, 1]
    V vertex[3];         // the varyings at the three vertices
    float inverse_w[3];  // 1 / w (all 1 for affine interpolation)
    bool perspective_correct = true;
    V over_w[3];                 // varyings / w
    V d_over_w_dx, d_over_w_dy;  // screen derivatives of sum(b_i varyings_i / w_i) ...
    float d_inverse_w_dx = 0, d_inverse_w_dy = 0;  // ... and of sum(b_i / w_i)
    float depth_slope = 0;                         // max(|dz/dx|, |dz/dy|), for the slope bias
    [[no_unique_address]] F flat{};
    int face = 0;  // the face it came from
    triangles::ScreenTriangle screen(rl::vec2 offset = {}) const {
        return {{window[0].xy() - offset, window[1].xy() - offset, window[2].xy() - offset}};
    }
};

// A value of the divide in float. One past float's range (a vertex just in
// front of the eye when only the near plane clips) becomes +-FLT_MAX, which
// the rasterizer then refuses, rather than an undefined conversion.
inline float to_float(double v) {
    constexpr double kLargest = std::numeric_limits<float>::max();
    return static_cast<float>(std::clamp(v, -kLargest, kLargest));  // (NaN stays NaN)
}
inline rl::vec3 to_float(const rl::dvec3& v) {
    return {to_float(v.x), to_float(v.y), to_float(v.z)};
}

// Divide, viewport, and the constants of one triangle of clip-space vertices
// (their own flat values, G, are not read: `flat` is the triangle's).
template <Interpolable V, class F, class G = NoFlat>
TriangleSetup<V, F> set_up(const ClipVertex<V, G>& a, const ClipVertex<V, G>& b,
                           const ClipVertex<V, G>& c, const F& flat, int face,
                           Interpolation interpolation, int width, int height) {
    TriangleSetup<V, F> t;
    const ClipVertex<V, G>* v[3] = {&a, &b, &c};
    t.perspective_correct = interpolation == Interpolation::perspective_correct;
    for (int k = 0; k < 3; ++k) {
        const ClipPosition& p = v[k]->position;
        const float inverse_w = to_float(1 / p.w);
        t.window[k] = rl::ndc_to_window(to_float(p.xyz() / p.w), width, height);
        t.vertex[k] = v[k]->varyings;
        t.inverse_w[k] = t.perspective_correct ? inverse_w : 1.0f;
        t.over_w[k] = scaled(t.vertex[k], t.inverse_w[k]);
    }
    // The barycentric weight b_k is linear on screen: b_k = E_k / (2 area),
    // where E_k is the edge function of the edge opposite vertex k, so
    // db_k/dx = -(y_j - y_i) / (2 area) and db_k/dy = (x_j - x_i) / (2 area).
    const float area2 = triangles::signed_area2(t.screen());
    const float inverse_area2 = area2 != 0 ? 1 / area2 : 0.0f;
    float dz_dx = 0, dz_dy = 0;
    for (int k = 0; k < 3; ++k) {
        const rl::vec3 &i = t.window[(k + 1) % 3], &j = t.window[(k + 2) % 3];
        const float db_dx = (i.y - j.y) * inverse_area2, db_dy = (j.x - i.x) * inverse_area2;
        t.d_over_w_dx = blend(t.d_over_w_dx, 1.0f, t.over_w[k], db_dx);
        t.d_over_w_dy = blend(t.d_over_w_dy, 1.0f, t.over_w[k], db_dy);
        t.d_inverse_w_dx += t.inverse_w[k] * db_dx;
        t.d_inverse_w_dy += t.inverse_w[k] * db_dy;
        dz_dx += t.window[k].z * db_dx, dz_dy += t.window[k].z * db_dy;
    }
    t.depth_slope = std::max(std::abs(dz_dx), std::abs(dz_dy));
    t.flat = flat;
    t.face = face;
    return t;
}
// [/doc:triangle-setup]

// One pixel (one sample of it) reaching the fragment stage.
template <Interpolable V, class F = NoFlat>
struct Fragment {
    int x, y;
    float depth;
    V varyings;
    float inverse_w;  // interpolated 1 / w at this pixel
    const TriangleSetup<V, F>* triangle;
    int face() const { return triangle->face; }
    const F& flat() const { return triangle->flat; }
    // How the varyings change per pixel to the right (d_dx) and up (d_dy):
    // exact for either interpolation, from the quotient rule on
    // varyings = (varyings / w) / (1 / w), both of which are linear on screen.
    V d_dx() const {
        return scaled(blend(triangle->d_over_w_dx, 1.0f, varyings, -triangle->d_inverse_w_dx),
                      1 / inverse_w);
    }
    V d_dy() const {
        return scaled(blend(triangle->d_over_w_dy, 1.0f, varyings, -triangle->d_inverse_w_dy),
                      1 / inverse_w);
    }
    // The same for one member only (f.d_dx(&Varyings::uv)): a fragment stage
    // that needs the derivatives of its texture coordinates alone skips the rest.
    template <class M, class W = V>
    M d_dx(M W::*member) const {
        return (triangle->d_over_w_dx.*member + varyings.*member * -triangle->d_inverse_w_dx) *
               (1 / inverse_w);
    }
    template <class M, class W = V>
    M d_dy(M W::*member) const {
        return (triangle->d_over_w_dy.*member + varyings.*member * -triangle->d_inverse_w_dy) *
               (1 / inverse_w);
    }
};

// The fragment at barycentric weights b: perspective-correct varyings are
// b . (varyings / w) divided by b . (1 / w); affine ones are b . varyings.
template <Interpolable V, class F>
Fragment<V, F> fragment_at(const TriangleSetup<V, F>& t, int x, int y, float z, rl::vec3 b) {
    const V over_w = weighted(t.over_w, b);
    if (!t.perspective_correct) return {x, y, z, over_w, 1.0f, &t};
    const float inverse_w = b.x * t.inverse_w[0] + b.y * t.inverse_w[1] + b.z * t.inverse_w[2];
    return {x, y, z, scaled(over_w, 1 / inverse_w), inverse_w, &t};
}

// Throws OverdrawError for a draw that visited more than `most` samples.
[[noreturn]] void throw_overdraw(double most);

// The pixels of the triangle's bounding box within `rect`: what the
// rasterizer visits (0 for a triangle it would refuse).
inline std::size_t box_samples(const triangles::ScreenTriangle& t, const triangles::PixelRect& r) {
    if (!triangles::within_raster_range(t)) return 0;
    const auto [x0, x1] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
    const auto [y0, y1] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    const triangles::PixelRange xs = triangles::centres_between(x0, x1, r.x0, r.x1),
                                ys = triangles::centres_between(y0, y1, r.y0, r.y1);
    if (xs.first > xs.last || ys.first > ys.last) return 0;
    return static_cast<std::size_t>(xs.last - xs.first + 1) *
           static_cast<std::size_t>(ys.last - ys.first + 1);
}

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

// Writes a fragment's outputs into the target's colour attachments: one
// value for a target of one attachment, a tuple in attachment order for several.
template <class Outputs, class... Pixels>
void store(RenderTarget<Pixels...>& target, int column, int y, const Outputs& out) {
    if constexpr (sizeof...(Pixels) == 1) {
        target.template colour<0>().at(column, y) = out;
    } else {
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((target.template colour<I>().at(column, y) = std::get<I>(out)), ...);
        }
        (std::index_sequence_for<Pixels...>{});
    }
}

// The target's depth bias (lesson 08's) for triangle t: constant, plus
// slope-scaled by the triangle's depth slope. Once per triangle.
template <Interpolable V, class F>
float depth_bias(const TriangleSetup<V, F>& t, const zbuffer::DepthState& state) {
    return state.constant_bias + state.slope_bias * t.depth_slope;
}

// The window depth at weights b: interpolated with the plain weights (window
// depth is linear on screen), plus the bias, kept in [0, 1].
template <Interpolable V, class F>
float window_depth(const TriangleSetup<V, F>& t, rl::vec3 b, float bias) {
    const float z = zbuffer::interpolate_depth(b, t.window[0].z, t.window[1].z, t.window[2].z);
    return bias != 0 ? std::clamp(z + bias, 0.0f, 1.0f) : z;
}

// [doc:fragment-operations]
// The fragment operations of one covered sample, in the halves every
// coverage policy calls: the sample's test, before the fragment stage (as a
// GPU's early depth test), and its write. In between, the fragment stage,
// whose outputs are nothing where the program discards: such a fragment
// writes neither colour nor depth.
template <class... Pixels>
bool sample_passes(const RenderTarget<Pixels...>& target, int column, int y, float z) {
    const rl::FloatImage* const depth = target.depth();
    return !depth || zbuffer::depth_passes(target.depth_state.compare, z, depth->at(column, y));
}

template <class Outputs, class... Pixels>
void write_sample(RenderTarget<Pixels...>& target, int column, int y, float z, const Outputs& out) {
    if constexpr (sizeof...(Pixels) > 0) store(target, column, y, out);
    rl::FloatImage* const depth = target.depth();
    if (depth && target.depth_state.write) depth->at(column, y) = z;
}

template <class P, Interpolable V, class F, class... Pixels>
auto shade(const P& program, const Fragment<V, F>& fragment, const RenderTarget<Pixels...>&,
           PipelineCounts& counts) {
    if constexpr (!ProgramTraits<P>::may_discard && sizeof...(Pixels) == 0) {
        return std::optional<std::monostate>(std::in_place);  // depth only: nothing to run
    } else {
        ++counts.shaded;
        if constexpr (ProgramTraits<P>::may_discard)
            return program.fragment(fragment);  // an optional
        else
            return std::optional(program.fragment(fragment));
    }
}

// One sample of triangle t at window depth z, stored at (column, y) of the
// target: its test, the fragment stage (its varyings at weights b, pixel
// (x, y)), its write; counted in `counts`.
template <class P, Interpolable V, class F, class... Pixels>
void fragment_operations(const P& program, const TriangleSetup<V, F>& t, int x, int y, float z,
                         rl::vec3 b, RenderTarget<Pixels...>& target, int column,
                         PipelineCounts& counts) {
    if (!sample_passes(target, column, y, z)) return;
    const auto out = shade(program, fragment_at(t, x, y, z, b), target, counts);
    if (!out) return;
    write_sample(target, column, y, z, *out);
    ++counts.stored;
}
// [/doc:fragment-operations]

// [doc:rasterize-triangle]
// Stages 5-8 for one set-up triangle, one sample per pixel at its centre:
// lesson 02's rasterizer finds the covered pixels within the options' tile,
// and each goes through the fragment operations. Returns false if refused.
template <class P, Interpolable V, class F, class... Pixels>
bool rasterize_triangle(const TriangleSetup<V, F>& t, const P& program,
                        RenderTarget<Pixels...>& target, const PipelineOptions& options,
                        PipelineCounts& counts) {
    const triangles::PixelRect rect = options.tile.value_or(target.bounds());
    const float bias = depth_bias(t, target.depth_state);
    counts.visited += box_samples(t.screen(), rect);
    return triangles::rasterize(options.raster, t.screen(), rect, [&](int x, int y, rl::vec3 b) {
        const float z = window_depth(t, b, bias);
        fragment_operations(program, t, x, y, z, b, target, x, counts);
    });
}
// [/doc:rasterize-triangle]

// [doc:coverage]
// How draw() turns a set-up triangle into stored samples: its coverage
// policy. Lesson 05's is one sample at each pixel's centre, the fragment
// stage run once for it. A later lesson plugs in its own (several samples a
// pixel, the fragment stage run once per sample or once per pixel) as any
// type with this call, without changing draw(); it counts what it visits and
// stores in `counts`, as rasterize_triangle does, and returns false for a
// triangle the rasterizer refused.
struct OneSamplePerPixel {
    template <class P, class T, class... Pixels>
    bool operator()(const T& t, const P& program, RenderTarget<Pixels...>& target,
                    const PipelineOptions& options, PipelineCounts& counts) const {
        if (target.samples() != 1)
            throw std::invalid_argument(
                "a target of several samples a pixel needs a coverage policy that fills them");
        return rasterize_triangle(t, program, target, options, counts);
    }
};
// [/doc:coverage]

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

// [doc:draw]
// Every face of the geometry through every stage, into the target.
template <class Geometry, class P, class... Pixels, class Coverage = OneSamplePerPixel>
PipelineCounts draw(const Geometry& geometry, const P& program, RenderTarget<Pixels...>& target,
                    const PipelineOptions& options = {}, const Coverage& coverage = {}) {
    const triangles::PixelRect rect = options.tile.value_or(target.bounds());
    const double most_visited = options.max_overdraw > 0 ? options.max_overdraw * target.width() *
                                                               target.height() * target.samples()
                                                         : HUGE_VAL;
    PipelineCounts counts;
    // 1.-4. Vertex stage, culling, clipping, divide and viewport.
    assemble(geometry, program, target.width(), target.height(), options, counts,
             [&](const auto& t) {
                 // 5.-8. Rasterize, depth test, fragment stage, store; in bands
                 // of rows (one row of margin for samples off the centre), so
                 // that a host (the Python module) can stop between them.
                 const bool ok = triangles::for_each_band(
                     t.screen(), rect, 1, [&](const triangles::PixelRect& band) {
                         PipelineOptions in_band = options;
                         in_band.tile = band;
                         return coverage(t, program, target, in_band, counts);
                     });
                 ++(ok ? counts.drawn : counts.refused);
                 if (static_cast<double>(counts.visited) > most_visited)
                     throw_overdraw(most_visited);
             });
    return counts;
}
// [/doc:draw]

// The samples draw() would visit (its triangles' bounding boxes within the
// target, times the samples per pixel), found by stages 1-4 alone: a caller
// can refuse a pass before drawing any of it, as lesson 08 does.
template <class Geometry, class P>
double samples_to_visit(const Geometry& geometry, const P& program, int width, int height,
                        int samples, const PipelineOptions& options = {}) {
    const triangles::PixelRect whole =
        options.tile.value_or(triangles::PixelRect{0, 0, width, height});
    double visits = 0;
    PipelineCounts counts;
    assemble(geometry, program, width, height, options, counts, [&](const auto& t) {
        visits += static_cast<double>(box_samples(t.screen(), whole)) * samples;
    });
    return visits;
}

}  // namespace perspective
