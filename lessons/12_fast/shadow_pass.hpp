// Lesson 08's first pass, the shadow map, drawn by the fast path: the same
// vertex stage, set-up, binning and tiles as a picture, with the visibility
// pass alone in each tile (depth only: nothing is shaded) and lesson 08's
// depth bias added to each sample before its test. The map is lesson 08's,
// texel for texel, at any thread count. docs/12_fast.md, "Shadows on the
// fast path".
//
//   fast::ShadowPass pass(models, {.size = 2048, .slope_bias = 1});
//   const shadows::LightView light = shadows::light_view_for(models, camera, aspect, options);
//   const shadows::ShadowMap& map = pass.render(light);
//   renderer.set_shadow_map(&map, options.lookup);  // the second pass: a fast::Renderer's
#pragma once

#include "08_shadows/shadow_map.hpp"
#include "renderer.hpp"

namespace fast {

class ShadowPass {
  public:
    // Throws std::invalid_argument for a map size outside lesson 08's range.
    // threads: 0 for every core.
    ShadowPass(const std::vector<normal_mapping::MappedModel>& models,
               const shadows::ShadowMapOptions& options, int threads = 0);
    // The map of shadows::render_shadow_map(models, light, options); throws
    // lesson 08's pipeline::OverdrawError for a model over its cap.
    const shadows::ShadowMap& render(const shadows::LightView& light);
    const StageTimes& times() const { return renderer_.times(); }

  private:
    shadows::ShadowMapOptions options_;
    Renderer renderer_;
    shadows::ShadowMap map_;
};

}  // namespace fast
