#include "gbuffer.hpp"

#include <cmath>

namespace occlusion {

GBuffer render_gbuffer(const std::vector<normal_mapping::MappedModel>& models,
                       const pipeline::Camera& camera, const shadows::ShadowOptions& options,
                       const shadows::ShadowMap& map, int width, int height,
                       pipeline::PipelineCounts* counts) {
    GBuffer g(width, height, {}, rl::vec3{0, 0, 0}, rl::vec3{0, 0, 0}, rl::vec3{0, 0, 0});
    shadows::ShadowOptions direct = options;
    direct.render.lighting.ambient = {0, 0, 0};  // added later, under the occlusion
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const pipeline::PipelineCounts drawn = shadows::draw_shadowed(
        models, camera, aspect, direct, map,
        [&](const normal_mapping::MappedModel&, const shading::Surface& surface,
            const shadows::ShadowedShader& shader) {
            return pipeline::draw(surface, GBufferShader{shader}, g, direct.render.pipeline);
        });
    if (counts) *counts = drawn;
    return g;
}

Screen::Screen(const pipeline::Camera& camera, int width, int height)
    : view_projection_(pipeline::view_projection(
          camera, static_cast<float>(width) / static_cast<float>(height))),
      rays_(camera, width, height),
      eye_(camera.eye),
      forward_(rl::normalize(camera.target - camera.eye)),
      inverse_near_(1 / camera.near),
      inverse_span_(1 / camera.near - 1 / camera.far),
      focal_(static_cast<float>(height) / (2 * std::tan(0.5f * rl::radians(camera.fov_y)))),
      width_(width),
      height_(height) {
    right_ = rl::normalize(rl::cross(forward_, camera.up));
    up_ = rl::cross(right_, forward_);
}

float Screen::view_depth(float window_depth) const {
    return 1 / (inverse_near_ - window_depth * inverse_span_);
}

rl::vec3 Screen::at_depth(float x, float y, float d) const {
    const rl::vec3 ray = rays_.ray(x, y);
    return eye_ + ray * (d / rl::dot(ray, forward_));
}

std::optional<rl::vec3> Screen::position(const GBuffer& g, int x, int y) const {
    const float z = g.depth()->get(x, y);
    if (!(z < g.depth_state.clear)) return std::nullopt;
    return at_depth(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, view_depth(z));
}

rl::vec3 Screen::project(rl::vec3 p) const {
    const rl::vec4 clip = view_projection_ * rl::extend(p, 1.0f);
    return {(clip.x / clip.w + 1) * 0.5f * static_cast<float>(width_),
            (clip.y / clip.w + 1) * 0.5f * static_cast<float>(height_), clip.w};
}

}  // namespace occlusion
