// Drawing a textured mesh: orthographic, z-buffered (lesson 03), with the
// texture coordinates interpolated across each triangle and sampled by a
// chosen filter and wrap mode.
#pragma once

#include "hidden_surfaces.hpp"
#include "rasterlab/mesh.hpp"
#include "sampling.hpp"

namespace textures {

struct TexturedOptions {
    SamplerState sampler;
    float uv_scale = 1.0f;  // texture coordinates are multiplied by this ...
    rl::vec2 uv_offset{};   // ... and then shifted, to show the wrap modes
    bool lighting = true;   // modulate by lesson 02's Lambert term
    rl::mat3 rotation = rl::mat3::identity();
    float scale = 1.0f;
};

// The constant derivatives of an affine texture mapping over a triangle:
// solve uv(p) = uv0 + A (p - p0) for the 2x2 matrix A from two edges.
UvDerivatives affine_derivatives(const rl::vec2 p[3], const rl::vec2 uv[3]);

// Draws the mesh into the frame; returns how many faces were drawn, culled
// as back faces, and refused by the rasterizer.
triangles::DrawCounts draw_textured(zbuffer::Frame& frame, const rl::Mesh& mesh,
                                    const MipChain& texture, const TexturedOptions& options);

}  // namespace textures
