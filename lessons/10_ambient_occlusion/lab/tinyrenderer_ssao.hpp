// tinyrenderer's SSAO lesson, ported for the lab only, so that the anchor
// the page compares with is scored against the same ray-traced truth. Its
// algorithm as that lesson writes it (ssloy/tinyrenderer, branch "ssao"):
// at every pixel, 128 points drawn at random in a box around the visible
// point (a tenth of the half screen wide in its normalised device
// coordinates, in x, y and depth alike); a point is hidden where the depth
// buffer is nearer than it; a point whose buffer depth is more than five
// box half-widths nearer than the pixel is not counted (its range check);
// the picture is then darkened by smoothstep(0, 1, 1 - 0.4 x hidden share).
// No normal, no rotation tile, no blur: fresh random points at every pixel.
//
// Where it differs, and why: its device coordinates have no field of view,
// so a box of equal sides there is a cube in the world at the pixel's
// depth; here it is that cube, its half side the world length that spans
// a tenth of the half screen at the pixel's depth. Its random generator is
// shared by every thread (a data race) and seeded from the machine; here
// each row has its own, seeded from the row, so runs repeat. A pixel whose
// points were all refused would divide 0 by 0 there; here it is open.
//
//   const rl::FloatImage ao = occlusion::tinyrenderer_ssao(surfaces);
#pragma once

#include <cstdint>

#include "10_ambient_occlusion/ambient_occlusion.hpp"

namespace occlusion {

inline constexpr int kTinyrendererSamples = 128;

// Per pixel, the factor tinyrenderer multiplies the colour by (1: open); 1
// where no model is.
rl::FloatImage tinyrenderer_ssao(const Surfaces& surfaces, int samples = kTinyrendererSamples,
                                 std::uint32_t seed = 1);

}  // namespace occlusion
