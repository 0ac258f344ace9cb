// Drawing a textured mesh: orthographic, z-buffered (lesson 03), with the
// texture coordinates interpolated across each triangle and sampled by a
// chosen filter and wrap mode.
//
//   zbuffer::Frame frame(800, 800);
//   textures::draw_textured(frame, mesh, textures::MipChain(diffuse.image), {});
#pragma once

#include "03_zbuffer/hidden_surfaces.hpp"
#include "rasterlab/mesh.hpp"
#include "sampling.hpp"

namespace textures {

// The program's default view: turned 25 degrees about x, then -35 about y.
inline constexpr float kDefaultTurnX = 25.0f, kDefaultTurnY = -35.0f;
// The border colour the program samples outside [0, 1] with: loud, so that
// border texels show.
inline constexpr rl::vec4 kLoudBorder{0.9f, 0.1f, 0.6f, 1.0f};

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

// One face as draw_textured sees it: window coordinates (x, y in pixels, z
// the window depth), texture coordinates after uv_scale and uv_offset, and
// whether it faces the viewer (counter-clockwise on screen).
struct TexturedFace {
    rl::vec3 world[3], window[3];
    rl::vec2 uv[3];
    bool front;
    triangles::ScreenTriangle screen() const {
        return {{window[0].xy(), window[1].xy(), window[2].xy()}};
    }
};
TexturedFace textured_face(const rl::Mesh& mesh, const rl::Face& face,
                           const TexturedOptions& options, int width, int height);

// Draws the mesh into the frame through lesson 02's draw loop (orthographic,
// lesson 03's depth test); returns how many faces were drawn, culled as back
// faces, and refused by the rasterizer.
triangles::DrawCounts draw_textured(zbuffer::Frame& frame, const rl::Mesh& mesh,
                                    const MipChain& texture, const TexturedOptions& options);

}  // namespace textures
