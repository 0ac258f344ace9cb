// The lab's ground truth for texture filtering: the texture averaged over
// each pixel's exact footprint, for scenes whose texture mapping is affine.
//
//   const rl::Image truth = textures::footprint_average(texture, scene, 64);
#pragma once

#include <cstdint>

#include "04_textures/sampling.hpp"
#include "04_textures/textured.hpp"

namespace textures {

// An affine texture mapping of a size x size image: uv at window point p is
// origin + p.x * du + p.y * dv (du, dv: the change per pixel).
struct AffineScene {
    rl::vec2 origin, du, dv;
    int size;
    rl::vec2 uv_at(double x, double y) const {
        return {static_cast<float>(origin.x + x * du.x + y * dv.x),
                static_cast<float>(origin.y + x * du.y + y * dv.y)};
    }
    UvDerivatives derivatives() const { return {du, dv}; }
};

// Magnification: the texture about 8x enlarged and turned by 20 degrees.
AffineScene magnification_scene(const rl::Image& texture, int size);
// Minification: the texture repeated and sheared, 20 to 40 texels per pixel.
AffineScene minification_scene(const rl::Image& texture, int size);

// Per pixel, the mean of the texture (texels as constant squares, repeat
// wrap) over the parallelogram the pixel maps to, from n x n samples in
// double precision.
rl::Image footprint_average(const rl::Image& texture, const AffineScene& scene, int n);

// The same truth for a whole mesh drawn as draw_textured draws it (without
// lighting) into a size x size image: per pixel, the texture averaged over
// the part of the surface the pixel shows, from n x n depth-tested samples.
// Only pixels that one face covers entirely are scored: a pixel on a face's
// edge mixes faces or the background, which is coverage, not filtering.
struct MeshFootprint {
    rl::Image average;
    rl::Grid<std::uint8_t> scored;  // 1 where `average` is the truth
    long covered = 0;               // pixels with any face in them
};
MeshFootprint mesh_footprint_average(const rl::Mesh& mesh, const rl::Image& texture,
                                     const TexturedOptions& options, int size, int n);

// The scene rendered with a sampler: one sample at each pixel centre.
rl::Image render_scene(const MipChain& texture, const AffineScene& scene,
                       const SamplerState& state);

}  // namespace textures
