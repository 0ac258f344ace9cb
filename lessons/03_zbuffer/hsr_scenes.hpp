// Scenes that tell the hidden-surface methods apart, for the lab and tests.
//
//   const double wrong = zbuffer::wrong_share(painter_frame, zbuffer_frame);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hidden_surfaces.hpp"
#include "scene.hpp"

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

// The program's --scene choices, and the triangles of each for a width x
// height image: "models" (the placements' models, culled faces counted in
// `culled`), "sticks" (cyclic_sticks) or "soup" (60 triangles of random_soup).
inline const std::vector<std::string> kProgramScenes = {"models", "sticks", "soup"};
std::vector<SceneTriangle> program_scene(const std::string& name,
                                         const std::vector<Placement>& placements, int width,
                                         int height, std::vector<std::string>& warnings,
                                         std::size_t& culled);

// The share (0..1) of pixels covered in `reference` whose winning face differs in `frame`.
double wrong_share(const Frame& frame, const Frame& reference);

}  // namespace zbuffer
