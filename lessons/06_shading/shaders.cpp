#include "shaders.hpp"

namespace shading {

rl::vec3 Uniforms::albedo(rl::vec2 uv, rl::vec2 d_dx, rl::vec2 d_dy) const {
    if (!texture) return colour;
    return textures::sample(*texture, uv, {d_dx, d_dy}, sampler).xyz();
}

// Flat and Gouraud shading light vertices with Blinn's specular.
Reflection<float> light_at(const Uniforms& u, rl::vec3 world_position, rl::vec3 world_normal) {
    return reflection(u.lighting, world_normal, rl::normalize(u.eye - world_position),
                      Specular::blinn_phong);
}

pipeline::PipelineCounts draw_model(ShadingModel model, const Surface& surface, const Uniforms& u,
                                    pipeline::ColourTarget& target,
                                    const pipeline::PipelineOptions& options, Output output) {
    switch (model) {
        case ShadingModel::flat:
            return draw(surface, FlatShader{u}, target, options, output);
        case ShadingModel::gouraud:
            return draw(surface, GouraudShader{u}, target, options, output);
        case ShadingModel::phong:
            return draw(surface, PhongShader{u, Specular::phong}, target, options, output);
        case ShadingModel::blinn_phong:
            return draw(surface, PhongShader{u, Specular::blinn_phong}, target, options, output);
    }
    return {};
}

}  // namespace shading
