// A mesh drawn as lines: every edge once, with any of lesson 01's methods.
//
//   lines::draw_wireframe(image, rl::load_obj("obj/rock.obj"), {255, 255, 255, 255},
//                         lines::LineMethod::wu);
#pragma once

#include "draw_line.hpp"
#include "rasterlab/mesh.hpp"

namespace lines {

// The colour lesson 01's program draws wireframes in: a warm white.
inline constexpr rl::Rgba kWireColour{235, 235, 220, 255};

// Draws every edge of the mesh once (an edge shared by two triangles is not
// drawn twice, which matters for the blended Wu lines). Returns the number of
// edges drawn.
std::size_t draw_wireframe(rl::Image& image, const rl::Mesh& mesh, rl::Rgba colour,
                           LineMethod method);

}  // namespace lines
