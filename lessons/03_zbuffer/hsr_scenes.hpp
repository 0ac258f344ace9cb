// Scenes that tell the hidden-surface methods apart, for the lab and tests.
//
//   const double wrong = zbuffer::wrong_share(painter_frame, zbuffer_frame);
#pragma once

#include <cstdint>

#include "hidden_surfaces.hpp"

namespace zbuffer {

// Three sticks, each lying over the next at one end and under the previous
// at the other: no order of whole sticks is right. All three have the same
// mean depth, so the painter's sort has nothing to go on.
std::vector<SceneTriangle> cyclic_sticks(int size);

// `count` large triangles with random depths at their corners, so that they
// pierce each other everywhere.
std::vector<SceneTriangle> random_soup(int count, int size, std::uint64_t seed);

// Two coplanar triangles covering the same pixels, drawn in the given order.
std::vector<SceneTriangle> coplanar_pair(int size);

// The share (0..1) of pixels covered in `reference` whose winning face differs in `frame`.
double wrong_share(const Frame& frame, const Frame& reference);

}  // namespace zbuffer
