#include "shadow_map.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

namespace shadows {
namespace {

// [doc:depth-program]
// The light's pass needs positions only: no varyings, no fragment stage.
struct DepthProgram {
    rl::mat4 model_view_projection;  // the light's view-projection times the model matrix
    using Varyings = float;
    pipeline::ClipVertex<float> vertex(const pipeline::MeshCorner& c) const {
        return {pipeline::clip_position(model_view_projection, c.position()), 0.0f};
    }
};
// [/doc:depth-program]

}  // namespace

pipeline::OverdrawError too_much_work(double cap, int size) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "the shadow map's pass: the triangles' bounding boxes, seen from the light, "
                  "cover more than %.3g texels, the cap (%.3g layers of this %dx%d map; at most a "
                  "thousand layers, and never more than a thousand layers of a 2048x2048 one): "
                  "refusing to spend minutes on them (the same faces repeated, or long thin faces)",
                  cap, cap / (static_cast<double>(size) * size), size, size);
    return pipeline::OverdrawError(text);
}

void check_map_size(int size) {
    if (size < 1 || size > kMaxShadowMapSize)
        throw std::invalid_argument("--shadow-map-size: " + std::to_string(size) +
                                    " is outside 1 to " + std::to_string(kMaxShadowMapSize) +
                                    " texels (the cap: a map of 8192 x 8192 floats takes 256 MiB)");
}

pipeline::PipelineOptions map_pipeline(const ShadowMapOptions& options) {
    pipeline::PipelineOptions pipeline;
    pipeline.cull = options.cull;
    // At most a thousand layers of the map, and never more work than a
    // thousand layers of a 2048² map, whatever the map's size.
    const double texels = static_cast<double>(options.size) * options.size;
    pipeline.max_overdraw = std::min(pipeline.max_overdraw, options.max_samples / texels);
    return pipeline;
}

ShadowMap render_shadow_map(const std::vector<normal_mapping::MappedModel>& models,
                            const LightView& light, const ShadowMapOptions& options) {
    check_map_size(options.size);
    pipeline::TargetOptions target_options;
    target_options.depth.constant_bias = options.constant_bias;
    target_options.depth.slope_bias = options.slope_bias;
    pipeline::RenderTarget<> target(options.size, options.size, target_options);
    const pipeline::PipelineOptions pipeline = map_pipeline(options);
    const double texels = static_cast<double>(options.size) * options.size;
    const auto pass = [&](const normal_mapping::MappedModel& m) {
        const pipeline::TexturedModel& model = m.lit.model;
        return std::pair(pipeline::MeshView(model.mesh, model.transform),
                         DepthProgram{light.view_projection * model.transform});
    };
    // Every model's work counted by the pipeline's set-up alone, before any
    // is drawn: a hostile model is refused in the time its set-up takes, not
    // after drawing up to the cap (17-19 s, when draw() alone checked it).
    for (const normal_mapping::MappedModel& m : models) {
        const auto [mesh, program] = pass(m);
        const double cap = pipeline.max_overdraw * texels;
        if (pipeline::samples_to_visit(mesh, program, options.size, options.size, 1, pipeline) >
            cap)
            throw too_much_work(cap, options.size);
    }
    for (const normal_mapping::MappedModel& m : models) {
        const auto [mesh, program] = pass(m);
        pipeline::draw(mesh, program, target, pipeline);
    }
    return {light, std::move(*target.depth())};
}

}  // namespace shadows
