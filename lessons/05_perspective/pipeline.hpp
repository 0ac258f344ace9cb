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
//       pipeline::ClipVertex<rl::vec2> vertex(const pipeline::MeshCorner& c) const {
//           return {pipeline::clip_position(mvp, c.position()), c.uv()};
//       }
//       rl::Rgba fragment(const pipeline::Fragment<rl::vec2>& f) const {
//           const rl::vec4 texel = textures::sample(texture, f.varyings, {f.d_dx(), f.d_dy()}, {});
//           return textures::to_rgba(texel);
//       }
//   };
//   pipeline::ColourTarget frame = pipeline::colour_target(800, 600);
//   pipeline::draw(pipeline::MeshView(mesh, model), TexturedProgram{mvp, chain}, frame);
//
// A stage per file: pipeline_options.hpp (what a draw may change, what it
// counts), program.hpp (what a program declares), assembly.hpp (stages 1-4),
// triangle_setup.hpp (the set-up triangle and its fragments),
// fragment_operations.hpp (stages 7-8); this file, the coverage policy and
// draw() itself.
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "02_triangles/bands.hpp"
#include "02_triangles/raster.hpp"
#include "assembly.hpp"
#include "fragment_operations.hpp"
#include "pipeline_options.hpp"
#include "render_target.hpp"
#include "triangle_setup.hpp"

namespace pipeline {

// Throws OverdrawError for a draw that visited more than `most` samples.
[[noreturn]] void throw_overdraw(double most);

// The pixels of the triangle's bounding box within `rect`: what the
// rasterizer visits (0 for a triangle it would refuse).
inline std::size_t box_samples(const triangles::ScreenTriangle& t, const triangles::PixelRect& r) {
    if (!triangles::within_raster_range(t)) return 0;
    const triangles::PixelBox box = triangles::centres_in_box(t, r);
    if (box.empty()) return 0;
    return static_cast<std::size_t>(box.xs.last - box.xs.first + 1) *
           static_cast<std::size_t>(box.ys.last - box.ys.first + 1);
}

// [doc:rasterize-triangle]
// How draw() turns a set-up triangle into stored samples: its coverage
// policy. Lesson 05's is one sample at each pixel's centre, the fragment
// stage run once for it. A later lesson plugs in its own (several samples a
// pixel, the fragment stage run once per sample or once per pixel) as any
// type with this call, without changing draw(); it counts what it visits
// and stores in `counts`, and returns false for a triangle the rasterizer
// refused.
//
// Stages 5-8 for one set-up triangle: lesson 02's rasterizer finds the
// covered pixels within the options' tile, and each goes through the
// fragment operations.
struct OneSamplePerPixel {
    template <class P, Interpolable V, class F, class... Pixels>
    bool operator()(const TriangleSetup<V, F>& t, const P& program, RenderTarget<Pixels...>& target,
                    const PipelineOptions& options, PipelineCounts& counts) const {
        if (target.samples() != 1)
            throw std::invalid_argument(
                "a target of several samples a pixel needs a coverage policy that fills them");
        const triangles::PixelRect rect = options.tile.value_or(target.bounds());
        const float bias = depth_bias(t, target.depth_state);
        counts.visited += box_samples(t.screen(), rect);
        return triangles::rasterize(
            options.raster, t.screen(), rect, [&](int x, int y, rl::vec3 b) {
                fragment_operations(program, t, x, y, window_depth(t, b, bias), b, target, x,
                                    counts);
            });
    }
};
// [/doc:rasterize-triangle]

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
                 bool ok = true;
                 PipelineOptions in_band = options;
                 for (const triangles::PixelRect band : triangles::Bands(t.screen(), rect, 1)) {
                     rl::checkpoint();
                     in_band.tile = band;
                     ok &= coverage(t, program, target, in_band, counts);
                 }
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

}  // namespace pipeline
