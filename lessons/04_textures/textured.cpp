#include "textured.hpp"

#include "02_triangles/flat_shading.hpp"

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

TexturedFace textured_face(const rl::Mesh& mesh, const rl::Triangle& face,
                           const TexturedOptions& options, int width, int height) {
    TexturedFace out;
    for (int k = 0; k < 3; ++k) {
        out.world[k] = options.rotation * mesh.position(face, k) * options.scale;
        out.window[k] = zbuffer::to_window(out.world[k], width, height);
        const int t = face.corners[static_cast<std::size_t>(k)].uv;
        out.uv[k] =
            (t >= 0 ? mesh.uvs[static_cast<std::size_t>(t)] : rl::vec2{}) * options.uv_scale +
            options.uv_offset;
    }
    // Not "area > 0": a face whose area is NaN (vertices too far out for a
    // float) is not culled but passed on, for the rasterizer to refuse and count.
    out.front = !(triangles::signed_area2(out.screen()) <= 0);
    return out;
}

triangles::DrawCounts draw_textured(zbuffer::Frame& frame, const rl::Mesh& mesh,
                                    const MipChain& texture, const TexturedOptions& options) {
    const int width = frame.colour.width(), height = frame.colour.height();
    triangles::DrawCounts counts;
    for (const rl::Triangle& triangle : mesh.triangles) {
        const TexturedFace face = textured_face(mesh, triangle, options, width, height);
        if (!face.front) {
            ++counts.culled;
            continue;
        }
        const rl::vec3* world = face.world;
        const triangles::Triangle2 tri = face.screen();
        const float shade =
            options.lighting
                ? triangles::lambert(rl::cross(world[1] - world[0], world[2] - world[0]),
                                     triangles::kDefaultLight)
                : 1.0f;
        const UvDerivatives derivatives = affine_derivatives(tri.v, face.uv);
        // [doc:textured-pixel]
        const bool drawn =
            triangles::rasterize_edge(tri, width, height, [&](int x, int y, rl::vec3 b) {
                const float z = zbuffer::interpolate_depth(b, face.window[0].z, face.window[1].z,
                                                           face.window[2].z);
                if (!zbuffer::passes_depth_test(frame.depth, x, y, z)) return;
                const rl::vec2 at = triangles::interpolate(b, face.uv[0], face.uv[1],
                                                           face.uv[2]);  // affine: exact here
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
