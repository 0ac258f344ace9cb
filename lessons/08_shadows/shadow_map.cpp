#include "shadow_map.hpp"

#include <stdexcept>
#include <string>

namespace shadows {
namespace {

// [doc:depth-program]
// The light's pass needs positions only: no varyings, no fragment stage.
struct DepthProgram {
    rl::mat4 model_view_projection;  // the light's view-projection times the model matrix
    using Varyings = float;
    perspective::ClipVertex<float> vertex(const perspective::MeshCorner& c) const {
        return {perspective::clip_position(model_view_projection, c.position()), 0.0f};
    }
};
// [/doc:depth-program]

}  // namespace

ShadowMap render_shadow_map(const std::vector<normal_mapping::MappedModel>& models,
                            const LightView& light, const ShadowMapOptions& options) {
    if (options.size < 1 || options.size > kMaxShadowMapSize)
        throw std::invalid_argument("--shadow-map-size: " + std::to_string(options.size) +
                                    " is outside 1 to " + std::to_string(kMaxShadowMapSize) +
                                    " texels (the cap: a map of 8192 x 8192 floats takes 256 MiB)");
    perspective::TargetOptions target_options;
    target_options.depth.constant_bias = options.constant_bias;
    target_options.depth.slope_bias = options.slope_bias;
    perspective::RenderTarget<> target(options.size, options.size, target_options);
    perspective::PipelineOptions pipeline;
    pipeline.cull = options.cull;
    for (const normal_mapping::MappedModel& m : models) {
        const perspective::TexturedModel& model = m.lit.model;
        perspective::draw(perspective::MeshView(model.mesh, model.transform),
                          DepthProgram{light.view_projection * model.transform}, target, pipeline);
    }
    return {light, std::move(*target.depth())};
}

}  // namespace shadows
