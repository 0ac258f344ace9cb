// Drawing a mesh with one colour per face: Lambert's law with the face's own
// normal, orthographic projection, back faces culled.
//
//   rl::Image image(800, 800, rl::kBackground);
//   const triangles::DrawCounts counts = triangles::draw_flat_shaded(image, mesh, {});
#pragma once

#include "raster.hpp"
#include "rasterlab/image.hpp"
#include "rasterlab/mesh.hpp"

namespace triangles {

// The light every lesson uses by default: the direction towards it (above,
// right, in front of the viewer), normalised on use; and the surface colour
// of an untextured model.
inline constexpr rl::vec3 kDefaultLight{0.3f, 0.5f, 1.0f};
inline constexpr rl::Rgba kSurfaceColour{235, 225, 205, 255};

struct FlatOptions {
    RasterMethod method = RasterMethod::edge;
    bool cull_back_faces = true;
    rl::vec3 light_direction = kDefaultLight;  // towards the light
    rl::Rgba colour = kSurfaceColour;
};

// Lambert's cosine law: a face lit at an angle receives light in proportion
// to the cosine, n . l (clamped at 0: faces turned away get none).
float lambert(rl::vec3 normal, rl::vec3 to_light);

// A colour scaled by an amount of light in [0, 1] (alpha stays opaque).
rl::Rgba lit(rl::Rgba colour, float light);

// A face's colour: the surface colour lit by Lambert's law with the face's
// own normal.
rl::Rgba face_colour(const rl::Mesh& mesh, const rl::Face& face, const FlatOptions& options);

// Draws every face through lesson 02's draw loop (draw_faces.hpp):
// orthographic, back faces culled, no depth test (the last face drawn wins),
// each face in its own flat colour.
DrawCounts draw_flat_shaded(rl::Image& image, const rl::Mesh& mesh, const FlatOptions& options);

// The classic first picture: three triangles (red, white, green) in a
// 200 x 200 image, as tinyrenderer's second lesson draws them.
rl::Image three_triangles(RasterMethod method);

}  // namespace triangles
