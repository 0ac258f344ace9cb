// Lesson 01's lines over a rendered picture: every triangle's edges, seen
// through the camera. An edge that reaches behind the eye is cut where it
// crosses a plane just in front of it (lesson 05's near-plane clip, for one
// segment), so that no endpoint is divided by w <= 0.
//
//   viewer::draw_wire_overlay(frame, models, camera, {255, 255, 255, 255});
#pragma once

#include <vector>

#include "05_perspective/varyings.hpp"
#include "07_normal_mapping/scene.hpp"
#include "rasterlab/image.hpp"

namespace viewer {

// The segment ab of clip space cut to w >= near (the part in front of the
// eye); false when nothing of it is left.
bool cut_to_front(pipeline::ClipPosition& a, pipeline::ClipPosition& b, double near);

// Returns the number of edges drawn (each triangle's three, shared ones twice).
std::size_t draw_wire_overlay(rl::Image& image,
                              const std::vector<normal_mapping::MappedModel>& models,
                              const pipeline::Camera& camera, rl::Rgba colour);

}  // namespace viewer
