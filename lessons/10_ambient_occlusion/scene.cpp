#include "scene.hpp"

#include <optional>
#include <utility>

#include "06_shading/colour.hpp"

namespace occlusion {

Frame render(const std::vector<normal_mapping::MappedModel>& models,
             const perspective::Camera& camera, const SceneOptions& options, int width, int height,
             const BakedAo* baked) {
    check(options.ao);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const shadows::ShadowMap map = shadows::shadow_map_for(models, camera, aspect, options.shadow);
    perspective::PipelineCounts counts;
    GBuffer g = render_gbuffer(models, camera, options.shadow, map, width, height, &counts);
    if (options.ao.method != AoMethod::baked) {
        rl::FloatImage ao = ambient_occlusion(g, Screen(camera, width, height), options.ao);
        return {std::move(g), std::move(ao), counts};
    }
    std::optional<BakedAo> own;
    if (!baked) {
        own = bake_vertex_ao(models, RayTracedAo(models), options.ao.radius, options.ao.samples);
        baked = &*own;
    }
    rl::FloatImage ao = draw_baked(models, camera, options.shadow, map, *baked, width, height);
    return {std::move(g), std::move(ao), counts};
}

rl::Image picture(const Frame& f, const SceneOptions& options, Show show) {
    rl::Image out(f.g.width(), f.g.height(), rl::kBackground);
    const float clear = f.g.depth_state.clear;
    for (int y = 0; y < f.g.height(); ++y)
        for (int x = 0; x < f.g.width(); ++x) {
            if (!(f.g.depth()->get(x, y) < clear)) continue;
            const float ao = f.ao.get(x, y);
            if (show == Show::ao) {
                out.set(x, y, shading::encode(rl::vec3{ao, ao, ao}, shading::Output::naive));
                continue;
            }
            const float open = show == Show::unoccluded ? 1.0f : ao;
            const rl::vec3 light = f.g.colour<kDirect>().get(x, y) +
                                   options.ambient * f.g.colour<kAlbedo>().get(x, y) * open;
            out.set(x, y, shading::encode(light, shading::Output::srgb));
        }
    return out;
}

}  // namespace occlusion
