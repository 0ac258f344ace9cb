#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "06_shading/colour.hpp"

namespace occlusion {

void check_frame_size(int width, int height) {
    const long long pixels = static_cast<long long>(width) * height;
    if (pixels > kMaxFramePixels)
        throw std::invalid_argument(
            "a frame of " + std::to_string(width) + "x" + std::to_string(height) +
            " is past lesson 10's cap of 2^24 pixels (4096x4096): its G-buffer and occlusion "
            "hold about 80 bytes a pixel");
}

void refuse_unused_options(const AoOptions& ao, bool environment, Show show,
                           const GivenOptions& given) {
    const auto refuse = [](bool unused, const char* option, const std::string& why) {
        if (unused) throw std::invalid_argument(std::string(option) + ": " + why);
    };
    const std::string shown = std::string("--show ") + name(show);
    if (show != Show::image && show != Show::ao) {
        const std::string no_occlusion = shown + " shows no occlusion";
        refuse(given.ao, "--ao", no_occlusion);
        refuse(given.samples, "--samples", no_occlusion);
        refuse(given.radius, "--radius", no_occlusion);
        refuse(given.blur, "--blur", no_occlusion);
        refuse(given.no_rotation, "--no-rotation", no_occlusion);
    }
    const bool none = ao.method == AoMethod::none, baked = ao.method == AoMethod::baked;
    const std::string no_occlusion = "--ao none finds no occlusion";
    refuse(given.samples && none, "--samples", no_occlusion);
    refuse(given.radius && none, "--radius", no_occlusion);
    refuse(given.blur && (none || baked), "--blur",
           none ? no_occlusion : "--ao baked is smooth per vertex, and not blurred");
    refuse(given.no_rotation && (none || baked), "--no-rotation",
           none ? no_occlusion : "--ao baked casts its rays per vertex, not by the screen's noise");
    // Lesson 08's lights reach the picture only as the direct light.
    const bool lights_shown =
        show == Show::direct || (!environment && (show == Show::image || show == Show::unoccluded));
    refuse(given.light && !lights_shown, "--light",
           environment ? "the environment lights the picture, not lesson 08's lights (--show "
                         "direct shows their light alone)"
                       : shown + " shows no light");
}

Frame render(const std::vector<normal_mapping::MappedModel>& models, const pipeline::Camera& camera,
             const SceneOptions& options, int width, int height, const BakedAo* baked) {
    check(options.ao);
    check_frame_size(width, height);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const shadows::ShadowMap map = shadows::shadow_map_for(models, camera, aspect, options.shadow);
    pipeline::PipelineCounts counts;
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

EnvironmentLighting::EnvironmentLighting(const std::string& source,
                                         std::vector<std::string>& warnings)
    : sky_(environment::make_environment({.source = source}, warnings)),
      diffuse_([this](rl::vec3 d) { return sky_.sample(d); }, environment::Irradiance::convolved),
      light_{&sky_, &diffuse_, {}} {}

// [doc:environment-light]
rl::vec3 light_at(const Frame& f, const SceneOptions& options, int x, int y, float open) {
    const rl::vec3 albedo = f.g.colour<kAlbedo>().get(x, y);
    if (const EnvironmentLight* e = options.environment)
        return albedo * e->diffuse->at(f.g.colour<kNormal>().get(x, y)) *
               (open / std::numbers::pi_v<float>);
    return f.g.colour<kDirect>().get(x, y) + options.ambient * albedo * open;
}
// [/doc:environment-light]

rl::Image picture(const Frame& f, const SceneOptions& options, Show show, const Screen* screen) {
    const EnvironmentLight* environment = options.environment;
    const bool lit = show == Show::image || show == Show::unoccluded;
    if (environment && lit && !screen)
        throw std::invalid_argument("the environment behind the models needs the frame's screen");
    rl::Image out(f.g.width(), f.g.height(), rl::kBackground);
    const float clear = f.g.depth_state.clear;
    // The depth image's range: the nearest and farthest view depths seen.
    float nearest = INFINITY, farthest = 0;
    if (show == Show::depth) {
        if (!screen) throw std::invalid_argument("the depth image needs the frame's screen");
        for (float z : f.g.depth()->pixels())
            if (z < clear) {
                nearest = std::min(nearest, screen->view_depth(z));
                farthest = std::max(farthest, screen->view_depth(z));
            }
    }
    for (int y = 0; y < f.g.height(); ++y)
        for (int x = 0; x < f.g.width(); ++x) {
            const float z = f.g.depth()->get(x, y);
            if (!(z < clear)) {
                if (environment && lit)
                    out.set(x, y,
                            shading::encode(
                                environment::tone_map(
                                    environment->sky->sample(screen->ray(x + 0.5f, y + 0.5f)),
                                    environment->exposure),
                                shading::Output::srgb));
                continue;
            }
            const float ao = f.ao.get(x, y);
            rl::vec3 grey{ao, ao, ao};
            switch (show) {
                case Show::ao:
                    break;
                case Show::direct:
                    out.set(
                        x, y,
                        shading::encode(f.g.colour<kDirect>().get(x, y), shading::Output::srgb));
                    continue;
                case Show::albedo:
                    out.set(
                        x, y,
                        shading::encode(f.g.colour<kAlbedo>().get(x, y), shading::Output::srgb));
                    continue;
                case Show::normal:
                    grey = (f.g.colour<kNormal>().get(x, y) + rl::vec3{1, 1, 1}) * 0.5f;
                    break;
                case Show::depth: {
                    const float t = farthest > nearest
                                        ? (screen->view_depth(z) - nearest) / (farthest - nearest)
                                        : 0.0f;
                    grey = rl::vec3{1, 1, 1} * (1 - t);
                    break;
                }
                case Show::image:
                case Show::unoccluded: {
                    const rl::vec3 light =
                        light_at(f, options, x, y, show == Show::unoccluded ? 1.0f : ao);
                    out.set(x, y,
                            shading::encode(
                                environment ? environment::tone_map(light, environment->exposure)
                                            : light,
                                shading::Output::srgb));
                    continue;
                }
            }
            out.set(x, y, shading::encode(grey, shading::Output::naive));
        }
    return out;
}

}  // namespace occlusion
