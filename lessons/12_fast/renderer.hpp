// The fast path: lesson 07's scene and shading, rendered by a pipeline of its
// own built for speed. Per frame:
//
//   vertex stage, once per distinct vertex (lesson 07's own vertex function)
//     -> cull, clip, set-up (lessons 05 and 02) -> bin into square tiles
//     -> per tile, in parallel, each tile owned by one thread:
//          rasterize to depth + triangle ids (8x8 blocks, SIMD)
//          -> shade each visible pixel once (SIMD) -> copy into the frame
//
// The image is lesson 07's (the same coverage, shading in the same order of
// operations) whatever the thread count. Derivations and measurements:
// docs/12_fast.md.
//
//   fast::Renderer renderer(models, 800, 800, {});
//   renderer.render(camera);                 // allocates nothing after the first frame
//   rl::save_image("out.tga", renderer.frame());
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "07_normal_mapping/scene.hpp"
#include "08_shadows/shadow_map.hpp"
#include "fast_triangle.hpp"
#include "material.hpp"
#include "tile_kernels.hpp"

namespace fast {

// The most tile entries (a triangle in one tile's bin) a frame may bin: 2^28,
// 1 GiB of 32-bit triangle indices. A few hundred large triangles at 16384²
// in 8-pixel tiles need billions; render() refuses such a frame, naming the cap.
inline constexpr std::size_t kMaxBinnedEntries = std::size_t{1} << 28;

struct FastOptions {
    int threads = 0;                                     // 0: every core
    int tile_size = 64;                                  // pixels per side, a multiple of 8
    std::size_t max_binned_entries = kMaxBinnedEntries;  // the binning cap (a test lowers it)
    normal_mapping::RenderOptions render;  // lesson 07's shading options and its pipeline's
    // The techniques, for the lab to turn off one at a time:
    bool vertex_cache = true;  // the vertex function once per distinct vertex, not per corner
    // The specular map in the normal maps' alpha bytes where their levels
    // match, read by the normal map's lookups (docs/12_fast.md, "Textures
    // laid out for the gathers").
    bool specular_in_normal_alpha = true;
    // The decoded albedo in one word per texel rather than two (docs/12_fast.md,
    // "The albedo in one word").
    bool albedo_in_one_word = true;
    bool parallel = true;   // the vertex stage and the tiles on the threads (or on one)
    Techniques techniques;  // the tile kernels' (tile_kernels.hpp)
    // A shadow map's pass (lesson 08's first pass) rather than a picture:
    // render_depth() only, no textures packed, no lights. The pipeline's
    // cull and max_overdraw (per model, as lesson 08 counts it) are the
    // map's; the bias is lesson 08's depth bias.
    bool depth_only = false;
    float constant_bias = 0, slope_bias = 0;
};

// Where a frame's time went, in milliseconds of the clock, from timers
// around each stage (the tiles' own split, summed over threads, is in
// FrameCounts::tiles).
struct StageTimes {
    double vertex = 0, setup = 0, binning = 0, tiles = 0;
};

// What a frame did: lesson 05's counts of the faces (objects_culled, faces,
// culled, clipped, outside, refused; `drawn`: the triangles set up and
// binned; its sample counts stay 0, the tiles' own being in `tiles`), the
// vertex stage's runs, and the tiles' counts.
struct FrameCounts {
    pipeline::PipelineCounts pipeline;
    std::size_t vertices = 0;  // vertex-stage runs (distinct vertices of the models drawn)
    TileCounts tiles;          // summed over the tiles
};

// A model as the fast path draws it: distinct vertices (each one corner that
// stands for all the corners sharing its position, uv, normal and tangent),
// each face as three indices into them, and the maps packed for gathers.
struct FastModel {
    const normal_mapping::MappedModel* source;
    std::vector<std::uint32_t> indices;         // 3 per face
    std::vector<std::uint32_t> representative;  // per vertex: face * 3 + corner
    std::unique_ptr<PackedTexture> albedo, tangent_map, object_map, specular_map;
};
FastModel fast_model(const normal_mapping::MappedModel& model, const FastOptions& options);

class Renderer {
  public:
    Renderer(const std::vector<normal_mapping::MappedModel>& models, int width, int height,
             const FastOptions& options);
    ~Renderer();
    FrameCounts render(const pipeline::Camera& camera);
    // Lesson 08's shadow map pass on the same tiles (a renderer built with
    // depth_only): each texel of `depth` (width x height) the nearest biased
    // window depth seen through `view_projection`, 1 where nothing is.
    // Throws pipeline::OverdrawError for a model over the overdraw cap.
    FrameCounts render_depth(const rl::mat4& view_projection, rl::FloatImage& depth);
    // New lights for the frames to come (at most 8), without rebuilding the
    // models: the viewer's light moves with a key or a drag.
    void set_lighting(const shading::Lighting<float>& lighting);
    // Lesson 08's second pass from the next frame on: the first light (the
    // key light) scaled at each pixel by what `map` lets through, by lesson
    // 08's visibility() with `lookup`; nullptr: no shadows. The map must be
    // made from the first light's direction and outlive the frames drawn
    // with it. Throws std::invalid_argument for a spot light's map (its
    // light comes from a point, not from the first light's direction).
    void set_shadow_map(const shadows::ShadowMap* map, const shadows::ShadowLookup& lookup = {});
    const rl::Image& frame() const { return frame_; }
    const StageTimes& times() const { return times_; }
    int threads() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    rl::Image frame_;
    StageTimes times_;
};

// `frames` frames along fast::orbit(camera, ...), each timed: the median time
// (the first frame left out) and the last frame's counts. The last frame,
// renderer.frame(), is the view of `camera` itself.
struct OrbitRun {
    double median_ms = 0;      // per frame, the first excluded (it warms the caches)
    StageTimes median_stages;  // each stage's own median, the first frame excluded
    FrameCounts counts;        // the last frame's
};
// `between_frames`, if given, runs after every frame but the last (the
// Python module looks for Ctrl-C there).
OrbitRun render_orbit(Renderer& renderer, const pipeline::Camera& camera, int frames,
                      const std::function<void()>& between_frames = {});

}  // namespace fast
