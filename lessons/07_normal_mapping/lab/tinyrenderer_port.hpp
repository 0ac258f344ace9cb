// tinyrenderer's renderer, ported for the lab's speed comparison only: its
// algorithm as its final lessons write it, not this series' pipeline. All
// arithmetic in double; a virtual shader interface; back faces and
// triangles under a pixel dropped by the sign and size of det[x y 1];
// no clipping (a face with a vertex behind the eye is skipped, which
// tinyrenderer leaves undefined); for every pixel of the bounding box the
// barycentric weights from the inverse transpose of that 3x3, computed
// again at every pixel; perspective-correct weights; a z-buffer; and a
// Phong shader in eye space with one light, a tangent-space normal map
// whose frame (tinyrenderer's "Darboux frame") is solved at every pixel
// from the triangle's edges and UVs, nearest texels, bytes as they are.
// Unlike tinyrenderer it samples pixel centres (x + 0.5, y + 0.5), so that
// both renderers see the same pixels.
//
//   const rl::Image image = tinyrenderer_port::render(mesh, textures, camera, light, 800, 800);
#pragma once

#include <cstddef>

#include "05_perspective/camera.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/mesh.hpp"

namespace tinyrenderer_port {

// The diffuse colour and the tangent-space normal map, as images.
struct Textures {
    const rl::Image* diffuse;
    const rl::Image* normals;
};

struct Result {
    rl::Image image;
    std::size_t fragments = 0;  // pixels shaded
};

// Renders the mesh; if `normals` is given (width x height), it receives the
// world-space normal the shader used at each pixel it drew.
Result render(const rl::Mesh& mesh, const Textures& textures, const pipeline::Camera& camera,
              rl::vec3 light, int width, int height, rl::Grid<rl::vec3>* normals = nullptr);

}  // namespace tinyrenderer_port
