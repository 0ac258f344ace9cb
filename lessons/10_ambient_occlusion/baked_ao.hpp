// The offline alternative: ambient occlusion cast once per vertex at load
// time (RayTracedAo at each corner's position and normal), then
// interpolated across each triangle like any other varying. No screen,
// so no halos and no noise; but it knows only what its vertices know: a
// floor of two triangles gets no contact shadow at all, and a moving
// object would need the bake again. Pictures: docs/10_ambient_occlusion.md#baked-per-vertex.
//
//   const occlusion::RayTracedAo rays(models);
//   const occlusion::BakedAo baked = occlusion::bake_vertex_ao(models, rays, 0.5, 256);
//   const rl::FloatImage ao = occlusion::draw_baked(models, camera, options, map, baked, 800, 800);
#pragma once

#include <vector>

#include "gbuffer.hpp"
#include "ray_traced_ao.hpp"

namespace occlusion {

// Three values a face, per model, in the models' order.
struct BakedAo {
    std::vector<std::vector<float>> corners;
};

// The bake's caps: rays a vertex, and rays in all (corners x rays: 2^30 is
// about a minute on two cores at the lab's 20 million rays a second).
inline constexpr int kMaxBakeRays = 4096;
inline constexpr double kMaxBakeWork = 1 << 30;

// Every corner's occlusion within `radius`, by `rays` rays. Corners that
// share a position and a normal get the same value (the seed is the
// vertex's). Throws std::invalid_argument past the caps, before any ray.
BakedAo bake_vertex_ao(const std::vector<normal_mapping::MappedModel>& models,
                       const RayTracedAo& rays, double radius, int rays_per_vertex);

// The baked values interpolated to every pixel, drawn with the G-buffer's
// camera and pipeline (so the same pixels are covered); 1 where no model is.
rl::FloatImage draw_baked(const std::vector<normal_mapping::MappedModel>& models,
                          const pipeline::Camera& camera, const shadows::ShadowOptions& options,
                          const shadows::ShadowMap& map, const BakedAo& baked, int width,
                          int height);

}  // namespace occlusion
