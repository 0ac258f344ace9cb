// The lab's truth for antialiasing: every pixel the mean of side x side
// samples on an ordered grid over its square, each shaded on its own (the
// box filter of the same picture that every method approximates), drawn
// through supersampling as frames of 16 samples, the target's most. And the
// scores of a method's picture against it: at depth edges (where coverage
// aliases) and away from them (where shading and textures alias), apart.
//
//   const rl::Grid<rl::vec3> t = antialiasing::truth_light(models, camera, shadow, 800, 800);
//   const antialiasing::AaError e = antialiasing::compare(t, frame.light, edges);
#pragma once

#include "11_antialiasing/scene.hpp"

namespace antialiasing {

// side x side samples a pixel; side a multiple of 4 (16 samples a frame).
// The light as shown: exposed and tone-mapped as `tone` asks (its method,
// pattern and samples are not used), each sample before the mean or the
// mean after, so that a method is scored against the truth of its own order.
rl::Grid<rl::vec3> truth_light(const std::vector<normal_mapping::MappedModel>& models,
                               const pipeline::Camera& camera, const shadows::ShadowOptions& shadow,
                               int width, int height, int side = 16, const AaOptions& tone = {});

// The pixels within one pixel of a depth edge: a neighbour (of 8) whose
// view depth differs from the pixel's by more than 2%, or where no model
// is beside a pixel where one is. From a frame of one sample a pixel.
rl::Grid<std::uint8_t> depth_edges(const std::vector<normal_mapping::MappedModel>& models,
                                   const pipeline::Camera& camera,
                                   const shadows::ShadowOptions& shadow, int width, int height);

// The mean difference from the truth, per channel of the sRGB picture (what
// the eye compares), in [0, 1]: over edge pixels, over the others, and the
// 95th percentile of all.
struct AaError {
    double edges = 0, shading = 0, p95 = 0;
    long edge_pixels = 0, other_pixels = 0;
};
AaError compare(const rl::Grid<rl::vec3>& truth, const rl::Grid<rl::vec3>& light,
                const rl::Grid<std::uint8_t>& edges);

// How much a method's edges flicker in motion: over two successive frames
// of an orbit, at the pixels that are edges in either, the mean of
// |(method now - method before) - (truth now - truth before)| in sRGB:
// change the truth does not have.
double flicker(const rl::Grid<rl::vec3>& truth_before, const rl::Grid<rl::vec3>& truth_now,
               const rl::Grid<rl::vec3>& before, const rl::Grid<rl::vec3>& now,
               const rl::Grid<std::uint8_t>& edges_before, const rl::Grid<std::uint8_t>& edges_now);

}  // namespace antialiasing
