// Ambient occlusion by ray casting, through every triangle of the scene:
// from a surface point, `rays` cosine-weighted rays as long as the AO
// radius count what is open. Embree casts the rays (in float, each one
// offset off the surface by a millionth of the scene's size): thousands of
// rays a point in microseconds. The baked method calls it at every vertex
// once, at load time; the lab calls it at every pixel for its truth.
// Derivation: docs/10_ambient_occlusion.md#ray-cast-occlusion.
//
//   const occlusion::RayTracedAo rays(models);
//   const double open = rays.at(p, n, 0.5, 1024, seed);  // 0 closed to 1 open
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "09_environment/scene.hpp"

namespace occlusion {

class RayTracedAo {
  public:
    explicit RayTracedAo(const std::vector<normal_mapping::MappedModel>& models);
    ~RayTracedAo();
    RayTracedAo(const RayTracedAo&) = delete;
    RayTracedAo& operator=(const RayTracedAo&) = delete;

    // The occlusion at one surface point with unit normal n, by `rays`
    // stratified cosine-weighted rays (turned by `seed`).
    double at(rl::dvec3 p, rl::dvec3 n, double radius, int rays, std::uint32_t seed) const;

    // The nearest triangle along origin + t d for t in [near, far]: t and the
    // interpolated unit normal turned towards the ray's origin.
    struct Hit {
        double t;
        rl::dvec3 normal;
    };
    std::optional<Hit> first_hit(rl::dvec3 origin, rl::dvec3 d, double near, double far) const;

  private:
    struct Scene;
    std::unique_ptr<Scene> scene_;
};

}  // namespace occlusion
