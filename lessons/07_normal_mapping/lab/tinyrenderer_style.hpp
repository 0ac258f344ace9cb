// A renderer written the way tinyrenderer's lessons write theirs, for the
// lab's speed comparison only: a shader interface with virtual functions,
// a bounding-box rasterizer testing float barycentric coordinates at every
// pixel, perspective-correct weights recomputed per pixel, and a Phong
// shader with a tangent-space normal map whose frame is solved per pixel
// (tinyrenderer's "Darboux frame"), nearest-texel lookups, no sRGB.
//
//   const rl::Image image = tinyrenderer_style::render(mesh, maps, camera, light, 800, 800);
#pragma once

#include "05_perspective/camera.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/mesh.hpp"

namespace tinyrenderer_style {

// The diffuse colour and the tangent-space normal map, as images.
struct Textures {
    const rl::Image* diffuse;
    const rl::Image* normals;
};

// Renders the mesh; if `normals` is given (width x height), it receives the
// normal the shader used at each pixel it drew.
rl::Image render(const rl::Mesh& mesh, const Textures& textures, const perspective::Camera& camera,
                 rl::vec3 light, int width, int height, rl::Grid<rl::vec3>* normals = nullptr);

}  // namespace tinyrenderer_style
