// The first pass: the scene's depth as the light sees it, into a
// depth-only render target (lesson 05's pipeline with no colour attachment,
// so no fragment stage runs). Each texel holds the window depth of the
// nearest surface along its ray from the light. The depth bias moves the
// stored depths away from the light while they are written, as
// glPolygonOffset does: a constant, and a multiple of the triangle's depth
// slope. Derivations: docs/08_shadows.md#the-shadow-map.
//
//   const shadows::ShadowMap map =
//       shadows::render_shadow_map(models, light_view, {.size = 1024, .slope_bias = 1});
#pragma once

#include "07_normal_mapping/scene.hpp"
#include "light_space.hpp"

namespace shadows {

// The largest map a program draws: 8192 x 8192 floats, 256 MiB.
inline constexpr int kMaxShadowMapSize = 8192;
// The most texels the shadow map's pass may visit (its triangles' bounding
// boxes, per model): a thousand layers of a 2048² map, whatever the map's
// size, and at most a thousand layers of a smaller one. Sized by the map
// alone, an 8192² map allowed 16 times that: 100 000 copies of one triangle
// (800 KB of OBJ) at 64x64 with an 8192² map are now refused in 0.4 s,
// counted before drawing (render_shadow_map).
inline constexpr double kMaxShadowPassSamples = 1000.0 * 2048 * 2048;

struct ShadowMapOptions {
    // Texels per side. 2048 is where more stop paying at 800 x 800 (the lab's
    // 08_resolution: each doubling halves the wrong pixels, but past 2048 the
    // map's pass outgrows the rest of the frame).
    int size = 2048;
    float constant_bias = 0;                     // added to every stored depth (window depth, 0..1)
    float slope_bias = 1;                        // times the triangle's depth change per texel
    pipeline::Cull cull = pipeline::Cull::back;  // front: store the faces turned away
    double max_samples = kMaxShadowPassSamples;  // the pass's cap (a test lowers it)
};

struct ShadowMap {
    LightView light;
    rl::FloatImage depth;  // window depth from the light; 1 where nothing is
    int size() const { return depth.width(); }
};

// Throws std::invalid_argument for a size outside 1..kMaxShadowMapSize.
void check_map_size(int size);
// The pipeline options of the map's pass: its cull, and its overdraw cap
// (options.max_samples texel visits, per model).
pipeline::PipelineOptions map_pipeline(const ShadowMapOptions& options);
// The refusal of a model whose faces' boxes cover more than `cap` texels of a size² map.
pipeline::OverdrawError too_much_work(double cap, int size);

// Throws std::invalid_argument for a size outside 1..kMaxShadowMapSize.
ShadowMap render_shadow_map(const std::vector<normal_mapping::MappedModel>& models,
                            const LightView& light, const ShadowMapOptions& options);

}  // namespace shadows
