#include "shadow_pass.hpp"

namespace fast {

namespace {

FastOptions depth_options(const shadows::ShadowMapOptions& map, int threads) {
    shadows::check_map_size(map.size);  // before the renderer sizes anything by it
    FastOptions o;
    o.threads = threads;
    o.depth_only = true;
    o.constant_bias = map.constant_bias, o.slope_bias = map.slope_bias;
    o.render.pipeline = shadows::map_pipeline(map);
    // The tiles of a small map: no larger than the map (a multiple of 8).
    o.tile_size = std::min(o.tile_size, (map.size + 7) / 8 * 8);
    return o;
}

}  // namespace

ShadowPass::ShadowPass(const std::vector<normal_mapping::MappedModel>& models,
                       const shadows::ShadowMapOptions& options, int threads)
    : options_(options),
      renderer_(models, options.size, options.size, depth_options(options, threads)),
      map_{{}, rl::FloatImage(options.size, options.size, 1.0f)} {}

const shadows::ShadowMap& ShadowPass::render(const shadows::LightView& light) {
    map_.light = light;
    try {
        renderer_.render_depth(light.view_projection, map_.depth);
    } catch (const pipeline::OverdrawError&) {
        // Lesson 08's words for it: the renderer's name a picture's cap.
        const double texels = static_cast<double>(options_.size) * options_.size;
        throw shadows::too_much_work(shadows::map_pipeline(options_).max_overdraw * texels,
                                     options_.size);
    }
    return map_;
}

}  // namespace fast
