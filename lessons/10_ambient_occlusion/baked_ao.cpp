#include "baked_ao.hpp"

#include <stdexcept>
#include <string>

#include "rasterlab/checkpoint.hpp"
#include "rasterlab/workers.hpp"

namespace occlusion {

namespace {

// Lesson 08's shader for the clip position only, handing on the corner's
// baked value as its one varying.
struct BakedShader {
    shadows::ShadowedShader lit;
    const std::vector<float>& corners;
    using Varyings = float;

    pipeline::ClipVertex<float> vertex(const shading::SurfaceCorner& c) const {
        return {lit.vertex(c).position,
                corners[3 * static_cast<std::size_t>(c.face) + static_cast<std::size_t>(c.corner)]};
    }
    float fragment(const pipeline::Fragment<float>& f) const { return f.varyings; }
};

}  // namespace

// [doc:bake]
BakedAo bake_vertex_ao(const std::vector<normal_mapping::MappedModel>& models,
                       const RayTracedAo& rays, double radius, int rays_per_vertex) {
    if (rays_per_vertex < 1 || rays_per_vertex > kMaxBakeRays)
        throw std::invalid_argument("rays a vertex must be 1 to " + std::to_string(kMaxBakeRays) +
                                    ", not " + std::to_string(rays_per_vertex));
    double corners = 0;
    for (const normal_mapping::MappedModel& m : models)
        corners += 3.0 * static_cast<double>(m.lit.model.mesh.faces.size());
    if (corners * rays_per_vertex > kMaxBakeWork)
        throw std::invalid_argument("baking " + std::to_string(static_cast<long long>(corners)) +
                                    " corners x " + std::to_string(rays_per_vertex) +
                                    " rays is over the cap of 2^30 rays: fewer rays");
    BakedAo out;
    for (std::size_t i = 0; i < models.size(); ++i) {
        const rl::Mesh& mesh = models[i].lit.model.mesh;
        const rl::mat4& transform = models[i].lit.model.transform;
        const rl::mat3 to_world = shading::normal_matrix(transform).value_or(rl::mat3::identity());
        std::vector<float>& values = out.corners.emplace_back(3 * mesh.faces.size(), 1.0f);
        rl::parallel_for(std::size_t{0}, mesh.faces.size(), [&](std::size_t f) {
            rl::checkpoint();  // a host's Ctrl-C, between faces
            for (int k = 0; k < 3; ++k) {
                const std::size_t c = 3 * f + static_cast<std::size_t>(k);
                const rl::vec3 p =
                    (transform * rl::extend(mesh.position(mesh.faces[f], k), 1.0f)).xyz();
                const rl::vec3 n = to_world * models[i].lit.normals[c];
                if (!(rl::length(n) > 0)) continue;  // a broken normal: left open
                // The vertex's own seed: its neighbours' corners cast the same rays.
                const auto seed = static_cast<std::uint32_t>(
                    mesh.faces[f].corners[static_cast<std::size_t>(k)].position * 7919 + i);
                values[c] = static_cast<float>(rays.at(rl::cast<double>(p),
                                                       rl::normalize(rl::cast<double>(n)), radius,
                                                       rays_per_vertex, seed));
            }
        });
    }
    return out;
}
// [/doc:bake]

rl::FloatImage draw_baked(const std::vector<normal_mapping::MappedModel>& models,
                          const pipeline::Camera& camera, const shadows::ShadowOptions& options,
                          const shadows::ShadowMap& map, const BakedAo& baked, int width,
                          int height) {
    pipeline::RenderTarget<float> target(width, height, {}, 1.0f);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    shadows::draw_shadowed(
        models, camera, aspect, options, map,
        [&](const normal_mapping::MappedModel& m, const shading::Surface& surface,
            const shadows::ShadowedShader& shader) {
            const auto i = static_cast<std::size_t>(&m - models.data());
            return pipeline::draw(surface, BakedShader{shader, baked.corners.at(i)}, target,
                                  options.render.pipeline);
        });
    return std::move(target.colour<0>());
}

}  // namespace occlusion
