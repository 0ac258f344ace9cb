// The lab's ground truth for shadows, computed without the shadow map: at
// every pixel centre a ray from the eye, in double, finds the visible
// surface point (lesson 05's ray caster, through the BVH beside this file); a second
// ray from that point towards the light says whether anything is in the
// way. The renderer's answers at the same pixels come from a probe: the
// second pass with a shader that writes the map's answer and the triangle
// it shades, so that only pixels where both see the same triangle are
// scored.
//
//   const shadows::SceneRays rays(models);
//   const shadows::TruthFrame truth = rays.truth(camera, 512, 512, map.light);
//   const shadows::ProbeFrame answers = shadows::probe(models, camera, 512, 512, options, map);
//   const shadows::ShadowError e = shadows::compare(truth, answers);
#pragma once

#include "08_shadows/scene.hpp"
#include "bvh.hpp"

namespace shadows {

// The scene's triangles in world space, in double, in the order the probe
// numbers them: model after model, face after face.
std::vector<pipeline::WorldTriangle> world_triangles(
    const std::vector<normal_mapping::MappedModel>& models);

// Per pixel, the triangle seen (-1: none) and whether the light reaches
// the point (1) or not (0); NaN where the truth does not judge: nothing
// seen, a point facing away from the light (no direct light to shadow), or
// outside a spot light's cone.
struct TruthFrame {
    rl::Grid<int> triangle;
    rl::FloatImage lit;
};

class SceneRays {
  public:
    explicit SceneRays(const std::vector<normal_mapping::MappedModel>& models);
    // `light`: the map's light view (its kind, position and axis); a spot's
    // cone as the renderer's cone_factor() sees it.
    TruthFrame truth(const pipeline::Camera& camera, int width, int height, const LightView& light,
                     float cone_degrees = 180) const;
    // The same points lit by a round light of the given angular radius
    // (directional lights only): per pixel, the share of 16 rays towards
    // points of its disc that pass, NaN where truth() is NaN. The sun is
    // 0.27 degrees in radius; percentage-closer filters are scored against
    // this, since their soft edges stand for such a light.
    rl::FloatImage soft(const TruthFrame& hard, const pipeline::Camera& camera,
                        const LightView& light, double radius_degrees) const;
    const Bvh& bvh() const { return bvh_; }

  private:
    Bvh bvh_;
    double scale_;  // the scene's size, for the shadow ray's offset off its surface
};

// The renderer's answers: the map's light at each pixel (0..1) and the
// triangle shaded there, numbered as world_triangles() numbers them.
struct ProbeFrame {
    rl::FloatImage lit;
    rl::Grid<int> triangle;
};
ProbeFrame probe(const std::vector<normal_mapping::MappedModel>& models,
                 const pipeline::Camera& camera, int width, int height,
                 const ShadowOptions& options, const ShadowMap& map);

// Over the scored pixels (both see the same triangle, the truth judges
// it): the share wrongly lit (the truth is in shadow, the map says lit:
// peter-panning, leaks) and wrongly shadowed (acne), a map's answer below
// 0.5 counting as shadow; and the mean |answer - truth|, which also counts
// partial answers at edges.
struct ShadowError {
    double wrongly_lit = 0, wrongly_shadowed = 0, mean_error = 0;
    long scored = 0;
    double wrong() const { return wrongly_lit + wrongly_shadowed; }
};
ShadowError compare(const TruthFrame& truth, const ProbeFrame& probe);

// The mean |answer - soft truth| over the pixels compare() scores.
double soft_error(const TruthFrame& truth, const rl::FloatImage& soft, const ProbeFrame& probe);

}  // namespace shadows
