#pragma once

#include "draw_line.hpp"
#include "rasterlab/mesh.hpp"

namespace lines {

// Draws every edge of the mesh once (an edge shared by two triangles is not
// drawn twice, which matters for the blended Wu lines). Returns the number of
// edges drawn.
std::size_t draw_wireframe(rl::Image& image, const rl::Mesh& mesh, rl::Rgba colour,
                           LineMethod method);

}  // namespace lines
