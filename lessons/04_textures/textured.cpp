#include "textured.hpp"

#include "flat_shading.hpp"

namespace textures {

// [doc:affine-derivatives]
UvDerivatives affine_derivatives(const rl::vec2 p[3], const rl::vec2 uv[3]) {
    const rl::vec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
    const rl::vec2 t1 = uv[1] - uv[0], t2 = uv[2] - uv[0];
    const float det = rl::cross(e1, e2);
    if (det == 0) return {};
    return {(t1 * e2.y - t2 * e1.y) / det, (t2 * e1.x - t1 * e2.x) / det};
}
// [/doc:affine-derivatives]

triangles::DrawCounts draw_textured(zbuffer::Frame& frame, const rl::Mesh& mesh,
                                    const MipChain& texture, const TexturedOptions& options) {
    const int width = frame.colour.width(), height = frame.colour.height();
    const rl::vec3 light{0.3f, 0.5f, 1.0f};
    triangles::DrawCounts counts;
    for (const rl::Triangle& face : mesh.triangles) {
        rl::vec3 world[3], window[3];
        rl::vec2 screen[3], uv[3];
        for (int k = 0; k < 3; ++k) {
            world[k] = options.rotation * mesh.position(face, k) * options.scale;
            window[k] = zbuffer::to_window(world[k], width, height);
            screen[k] = window[k].xy();
            const int t = face.corners[static_cast<std::size_t>(k)].uv;
            uv[k] =
                (t >= 0 ? mesh.uvs[static_cast<std::size_t>(t)] : rl::vec2{}) * options.uv_scale +
                options.uv_offset;
        }
        const triangles::Triangle2 tri{{screen[0], screen[1], screen[2]}};
        if (triangles::signed_area2(tri) <= 0) {
            ++counts.culled;
            continue;
        }
        const float shade =
            options.lighting
                ? triangles::lambert(rl::cross(world[1] - world[0], world[2] - world[0]), light)
                : 1.0f;
        const UvDerivatives derivatives = affine_derivatives(screen, uv);
        // [doc:textured-pixel]
        const bool drawn =
            triangles::rasterize_edge(tri, width, height, [&](int x, int y, rl::vec3 b) {
                const float z =
                    zbuffer::interpolate_depth(b, window[0].z, window[1].z, window[2].z);
                if (!zbuffer::passes_depth_test(frame.depth, x, y, z)) return;
                const rl::vec2 at =
                    triangles::interpolate(b, uv[0], uv[1], uv[2]);  // affine: exact here
                rl::vec4 colour = sample(texture, at, derivatives, options.sampler);
                colour = {colour.x * shade, colour.y * shade, colour.z * shade, 1.0f};
                frame.colour.at(x, y) = to_rgba(colour);
            });
        // [/doc:textured-pixel]
        ++(drawn ? counts.drawn : counts.refused);
    }
    return counts;
}

}  // namespace textures
