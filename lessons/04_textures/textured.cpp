#include "textured.hpp"

#include "02_triangles/draw_faces.hpp"
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

namespace {

rl::vec3 placed(const rl::Mesh& mesh, const rl::Face& face, int corner,
                const TexturedOptions& options) {
    return options.rotation * mesh.position(face, corner) * options.scale;
}

rl::vec2 texture_coordinates(const rl::Mesh& mesh, const rl::Face& face, int corner,
                             const TexturedOptions& options) {
    const int t = face.corners[static_cast<std::size_t>(corner)].uv;
    return (t >= 0 ? mesh.uvs[static_cast<std::size_t>(t)] : rl::vec2{}) * options.uv_scale +
           options.uv_offset;
}

}  // namespace

TexturedFace textured_face(const rl::Mesh& mesh, const rl::Face& face,
                           const TexturedOptions& options, int width, int height) {
    TexturedFace out;
    for (int k = 0; k < 3; ++k) {
        out.world[k] = placed(mesh, face, k, options);
        out.window[k] = zbuffer::orthographic_to_window(out.world[k], width, height);
        out.uv[k] = texture_coordinates(mesh, face, k, options);
    }
    out.front = !triangles::is_back_face(out.screen());
    return out;
}

triangles::DrawCounts draw_textured(zbuffer::Frame& frame, const rl::Mesh& mesh,
                                    const MipChain& texture, const TexturedOptions& options) {
    std::vector<float> shade(mesh.faces.size(), 1.0f);  // lesson 02's Lambert, per face
    for (std::size_t i = 0; options.lighting && i < shade.size(); ++i) {
        const rl::Face& face = mesh.faces[i];
        const rl::vec3 p0 = placed(mesh, face, 0, options), p1 = placed(mesh, face, 1, options),
                       p2 = placed(mesh, face, 2, options);
        shade[i] = triangles::lambert(rl::cross(p1 - p0, p2 - p0), triangles::kDefaultLight);
    }
    const int width = frame.colour.width(), height = frame.colour.height();
    // [doc:textured-pixel]
    const auto vertex_stage = [&](const rl::Face& face, int corner) {
        return zbuffer::orthographic_to_window(placed(mesh, face, corner, options), width, height);
    };
    const auto fragment_stage = [&](const triangles::WindowTriangle& t, int x, int y, rl::vec3 b) {
        // Lesson 03's depth test first: a hidden pixel costs no texture lookup.
        const float z = zbuffer::interpolate_depth(b, t.window[0].z, t.window[1].z, t.window[2].z);
        if (!zbuffer::test_and_store_depth(frame.depth, x, y, z)) return;
        const rl::Face& face = mesh.faces[static_cast<std::size_t>(t.face)];
        const rl::vec2 uv[3] = {texture_coordinates(mesh, face, 0, options),
                                texture_coordinates(mesh, face, 1, options),
                                texture_coordinates(mesh, face, 2, options)};
        // The texture coordinates are linear across the window (w = 1: no
        // perspective yet), so their derivatives are constant over the triangle.
        const rl::vec2 window[3] = {t.window[0].xy(), t.window[1].xy(), t.window[2].xy()};
        const rl::vec4 colour = sample(texture, triangles::interpolate(b, uv[0], uv[1], uv[2]),
                                       affine_derivatives(window, uv), options.sampler);
        const float s = shade[static_cast<std::size_t>(t.face)];
        frame.colour.at(x, y) = to_rgba({colour.x * s, colour.y * s, colour.z * s, 1.0f});
    };
    // [/doc:textured-pixel]
    return triangles::draw_faces(mesh, width, height, {}, vertex_stage, fragment_stage);
}

}  // namespace textures
