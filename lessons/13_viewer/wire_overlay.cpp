#include "wire_overlay.hpp"

#include "01_lines/draw_line.hpp"
#include "05_perspective/pipeline.hpp"
#include "rasterlab/transform.hpp"

namespace viewer {

bool cut_to_front(pipeline::ClipPosition& a, pipeline::ClipPosition& b, double near) {
    if (a.w < near && b.w < near) return false;
    if (a.w < near) std::swap(a, b);  // now a is in front
    if (b.w < near) {
        const double t = (a.w - near) / (a.w - b.w);
        b = a + (b - a) * t;
    }
    return true;
}

std::size_t draw_wire_overlay(rl::Image& image,
                              const std::vector<normal_mapping::MappedModel>& models,
                              const pipeline::Camera& camera, rl::Rgba colour) {
    const float aspect = static_cast<float>(image.width()) / static_cast<float>(image.height());
    const rl::mat4 view_projection = pipeline::view_projection(camera, aspect);
    const double near = camera.near;
    std::size_t drawn = 0;
    for (const normal_mapping::MappedModel& m : models) {
        const pipeline::TexturedModel& model = m.lit.model;
        const rl::mat4 mvp = view_projection * model.transform;
        for (const rl::Face& face : model.mesh.faces)
            for (int k = 0; k < 3; ++k) {
                auto a = pipeline::clip_position(mvp, model.mesh.position(face, k));
                auto b = pipeline::clip_position(mvp, model.mesh.position(face, (k + 1) % 3));
                if (!cut_to_front(a, b, near)) continue;
                const auto window = [&](const pipeline::ClipPosition& p) {
                    const rl::vec3 ndc = pipeline::to_float(p.xyz() / p.w);
                    const rl::vec3 w = rl::ndc_to_window(ndc, image.width(), image.height());
                    return rl::vec2{w.x, w.y};
                };
                const lines::ClipResult r = lines::draw_line(image, window(a), window(b), colour,
                                                             lines::LineMethod::bresenham);
                if (r == lines::ClipResult::inside || r == lines::ClipResult::clipped) ++drawn;
            }
    }
    return drawn;
}

}  // namespace viewer
