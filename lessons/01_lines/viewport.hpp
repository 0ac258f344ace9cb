// The simplest camera there is: orthographic, looking down -z, with model
// x and y in [-1, 1] stretched over the image. Lesson 05 replaces it.
//
//   const rl::vec3 w = lines::orthographic_to_window(mesh.positions[i], 800, 800);
#pragma once

#include "rasterlab/transform.hpp"

namespace lines {

// Model (x, y) to window coordinates: (-1, -1) is the image's bottom-left
// corner, (1, 1) its top-right corner; z is carried along unchanged.
inline rl::vec3 orthographic_to_window(rl::vec3 p, int width, int height) {
    const rl::vec3 window = rl::ndc_to_window(p, width, height);  // the viewport, written once
    return {window.x, window.y, p.z};
}

}  // namespace lines
