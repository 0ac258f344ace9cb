// The lab's ground truth for ambient occlusion, computed without the
// G-buffer: at every pixel centre a ray from the eye finds the visible
// point and its interpolated normal; from there, `rays` cosine-weighted
// rays as long as the AO radius, through every triangle of the scene,
// count what is open. Embree casts the rays (in float, each one offset
// off the surface by a millionth of the scene's size): thousands of rays a
// pixel in seconds, on every core.
//
//   const occlusion::RayTracedAo truth(models);
//   const occlusion::TruthFrame t = truth.frame(camera, 800, 800, 0.5, 1024);
#pragma once

#include <memory>

#include "10_ambient_occlusion/scene.hpp"

namespace occlusion {

// Per pixel: the occlusion (0 closed to 1 open) and the view depth of the
// point seen, both NaN where no model is.
struct TruthFrame {
    rl::FloatImage ao, depth;
};

class RayTracedAo {
  public:
    explicit RayTracedAo(const std::vector<normal_mapping::MappedModel>& models);
    ~RayTracedAo();
    RayTracedAo(const RayTracedAo&) = delete;
    RayTracedAo& operator=(const RayTracedAo&) = delete;

    TruthFrame frame(const perspective::Camera& camera, int width, int height, double radius,
                     int rays) const;
    // The occlusion at one surface point with unit normal n, by `rays`
    // stratified cosine-weighted rays (turned by `seed`).
    double at(rl::dvec3 p, rl::dvec3 n, double radius, int rays, std::uint32_t seed) const;

  private:
    struct Scene;
    std::unique_ptr<Scene> scene_;
};

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
