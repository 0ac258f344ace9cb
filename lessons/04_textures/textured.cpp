#include "textured.hpp"

#include "02_triangles/flat_shading.hpp"
#include "05_perspective/pipeline.hpp"

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

UvDerivatives affine_derivatives(const perspective::TriangleSetup<rl::vec2>& t) {
    const rl::vec2 window[3] = {t.window[0].xy(), t.window[1].xy(), t.window[2].xy()};
    return affine_derivatives(window, t.vertex);
}

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
        out.window[k] =
            rl::ndc_to_window(perspective::orthographic_clip(out.world[k]).xyz(), width, height);
        out.uv[k] = texture_coordinates(mesh, face, k, options);
    }
    out.front = !(perspective::facing(perspective::orthographic_clip(out.world[0]),
                                      perspective::orthographic_clip(out.world[1]),
                                      perspective::orthographic_clip(out.world[2])) <= 0);
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
    perspective::PipelineOptions pipeline;
    pipeline.clip = perspective::ClipMode::none;  // orthographic: w = 1, nothing to cut
    pipeline.interpolation = perspective::Interpolation::affine;  // exact when w = 1
    // [doc:textured-pixel]
    const auto vertex_stage = [&](const rl::Face& face, int corner) {
        return perspective::ClipVertex<rl::vec2>{
            perspective::orthographic_clip(placed(mesh, face, corner, options)),
            texture_coordinates(mesh, face, corner, options)};
    };
    const auto pixel_stage = [&](const perspective::Fragment<rl::vec2>& f) {
        // The derivatives are constant over the triangle (affine mapping).
        rl::vec4 colour =
            sample(texture, f.varyings, affine_derivatives(*f.triangle), options.sampler);
        const float s = shade[static_cast<std::size_t>(f.face())];
        return to_rgba({colour.x * s, colour.y * s, colour.z * s, 1.0f});
    };
    // [/doc:textured-pixel]
    const perspective::PipelineCounts counts =
        perspective::draw_mesh<rl::vec2>(mesh, frame.target(), pipeline, vertex_stage, pixel_stage);
    return {counts.drawn, counts.back_faces, counts.refused};
}

}  // namespace textures
