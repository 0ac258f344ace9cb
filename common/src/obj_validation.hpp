// A first pass over an OBJ file's text, before tinyobjloader parses it, for
// what tinyobjloader reads silently wrong: "nan", "inf" and garbage numbers
// (it reads them as 0), values beyond float's range (read as infinity), face
// indices beyond int's range (they wrap around) or beyond the file's vertices,
// and faces too large for its ear-clipping triangulation, whose time grows
// with the square of the face's vertex count. See docs/robustness.md.
#pragma once

#include <string>
#include <string_view>

#include "rasterlab/mesh.hpp"

namespace rl {

// Throws MeshError naming `name`, the line and the problem.
void validate_obj_text(std::string_view text, const std::string& name);

}  // namespace rl
