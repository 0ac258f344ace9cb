// What a draw of lesson 05's pipeline may change (PipelineOptions: the clip
// mode, the interpolation, the culling, lesson 02's rasterizer, a tile) and
// what became of its work (PipelineCounts); pipeline.hpp draws with them.
//
//   pipeline::PipelineOptions options;
//   options.interpolation = pipeline::Interpolation::affine;  // the lab's wrong one
//   const pipeline::PipelineCounts counts = pipeline::draw(geometry, program, frame,
//   options);
#pragma once

#include "rasterlab/named_enum.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>

#include "02_triangles/raster.hpp"
#include "clipping.hpp"

namespace pipeline {

// How varyings are interpolated between a triangle's vertices: linearly in
// the window (what lessons 02-04 did; wrong under perspective) or linearly
// on the surface, by interpolating varyings / w and 1 / w and dividing.
enum class Interpolation { affine, perspective_correct };
RASTERLAB_NAMED_ENUM(Interpolation, kInterpolations, {Interpolation::affine, "affine"},
                     {Interpolation::perspective_correct, "perspective"});

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

}  // namespace pipeline
