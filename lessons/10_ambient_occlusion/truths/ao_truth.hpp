// The lab's ground truth for ambient occlusion, computed without the
// G-buffer: at every pixel centre a ray from the eye finds the visible
// point, then the lesson's RayTracedAo counts what is open around it, with
// as many rays as asked (1024 in the full lab: 8 s at 800x800 on two cores).
//
//   const occlusion::RayTracedAo rays(models);
//   const occlusion::TruthFrame t = occlusion::truth_frame(rays, camera, 800, 800, 0.5, 1024);
#pragma once

#include "10_ambient_occlusion/ray_traced_ao.hpp"
#include "10_ambient_occlusion/scene.hpp"

namespace occlusion {

// Per pixel: the occlusion (0 closed to 1 open) and the view depth of the
// point seen, both NaN where no model is.
struct TruthFrame {
    rl::FloatImage ao, depth;
};

// The truth at every pixel centre: a ray from the eye finds the visible
// point and its interpolated normal, then `count` rays find its occlusion.
TruthFrame truth_frame(const RayTracedAo& rays, const pipeline::Camera& camera, int width,
                       int height, double radius, int count);

// How far a method's occlusion is from the truth, over the pixels where
// both see the same surface (view depths within 1%): the mean and the 95th
// percentile of |method - truth| away from depth edges, and the mean within
// 3 pixels of one (a neighbour nearer or farther by more than half the
// radius, or no model): where halos are.
struct AoError {
    double mean = 0, p95 = 0, edge_mean = 0;
    long pixels = 0, edge_pixels = 0;
};
AoError compare(const TruthFrame& truth, const rl::FloatImage& ao, const GBuffer& g,
                const Screen& screen, double radius);

}  // namespace occlusion
