// The two scenes of the lab's clipping question, shared with 05_failures
// (which draws the first without clipping, for the page):
//   around_eye_scene  random triangles all around the eye, half of them
//                     within reach of the near plane or behind it;
//   floor_scene       a vast floor seen from just above it, whose near cells
//                     cut at the near plane reach far past the rasterizer's range.
//
//   const pipeline::ClippingScene s = pipeline::around_eye_scene(200);
//   const rl::Grid<int> ids = pipeline::pipeline_ids(s.triangles, s.camera, 512, 512, {});
#pragma once

#include <string>
#include <vector>

#include "05_perspective/truths/ray_truth.hpp"

namespace pipeline {

struct ClippingScene {
    std::string name;
    Camera camera;
    std::vector<WorldTriangle> triangles;
};

// `count` triangles around an eye at the origin looking down -z (near 0.1).
ClippingScene around_eye_scene(int count);

// A floor 1000 x 1000 of 20 x 20 cells (800 triangles), seen from 0.3 above
// with the near plane at 0.02.
ClippingScene floor_scene();

}  // namespace pipeline
