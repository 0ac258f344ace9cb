#include "scene.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "rasterlab/transform.hpp"

namespace environment {

std::vector<normal_mapping::MappedModel> default_scene(std::vector<std::string>& warnings) {
    using normal_mapping::TangentMethod;
    std::vector<normal_mapping::MappedModel> models;
    // The globe (radius 1) on the left; the torus (ring 0.62, tube 0.3,
    // about z) on the right, turned a little towards the sky above it.
    models.push_back(normal_mapping::load_mapped_model(
        rl::project_model("globe"),
        rl::compose({.translation = {-0.75f, 0, 0}, .scale = {0.8f, 0.8f, 0.8f}}),
        TangentMethod::split, warnings));
    models.push_back(normal_mapping::load_mapped_model(
        rl::project_model("torus"),
        rl::compose({.translation = {0.85f, 0, 0}, .rotation = rl::axis_angle({1, 0, 0}, -25)}),
        TangentMethod::split, warnings));
    return models;
}

pipeline::ViewedScene<normal_mapping::MappedModel> load_scene(
    const pipeline::ViewOptions& view, normal_mapping::TangentMethod tangents, int width,
    int height, std::vector<std::string>& warnings) {
    pipeline::ViewOptions framed = view;
    if (view.models.empty()) {  // the default scene's view, unless the options give one
        if (view.eye.empty()) framed.eye = {0.3f, 0.35f, 3.8f};
        if (view.target.empty()) framed.target = {0, 0, 0};
    }
    return normal_mapping::load_view(framed, tangents, width, height, warnings, default_scene);
}

PixelRays::PixelRays(const pipeline::Camera& camera, int width, int height)
    : width_(static_cast<float>(width)), height_(static_cast<float>(height)) {
    // The screen one unit in front of the eye spans tan(fov / 2) up and
    // down, times the aspect ratio across.
    forward_ = rl::normalize(camera.target - camera.eye);
    const rl::vec3 right = rl::normalize(rl::cross(forward_, camera.up));
    const float half_height = std::tan(0.5f * rl::radians(camera.fov_y));
    right_ = right * (half_height * width_ / height_);
    up_ = rl::cross(right, forward_) * half_height;
}

rl::vec3 PixelRays::ray(float x, float y) const {
    return rl::normalize(forward_ + right_ * (2 * x / width_ - 1) + up_ * (2 * y / height_ - 1));
}

// [doc:skybox]
void draw_skybox(const Environment& environment, const pipeline::Camera& camera,
                 LightTarget& frame) {
    const rl::FloatImage* depth = frame.depth();
    const float clear = frame.depth_state.clear;
    // The mip level (trilinear only) for a pixel's angular size at the
    // image's centre: the screen spans 2 tan(fov / 2) over its height.
    const float level =
        environment.level_for(2 * std::tan(0.5 * rl::radians(camera.fov_y)) / frame.height());
    const PixelRays rays(camera, frame.width(), frame.height());
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x) {
            if (depth && depth->get(x, y) != clear) continue;  // a model is there
            frame.colour().set(x, y, environment.sample(rays.ray(x + 0.5f, y + 0.5f), level));
        }
}
// [/doc:skybox]

SurfaceMaterial material_of(const RenderOptions& options, std::size_t index) {
    const Material default_look = index == 0 ? Material::mirror : Material::rough_metal;
    return {.material = options.material.value_or(default_look),
            .roughness = options.roughness,
            .metal = options.metal,
            .glossy = options.glossy,
            .lookup = options.lookup,
            .multiple_scattering = options.multiple_scattering,
            .samples = options.samples};
}

void refuse_unused_options(const RenderOptions& options, const EnvironmentOptions& environment,
                           std::size_t model_count, const GivenOptions& given) {
    // Diffuse light reaches a diffuse surface, a plastic's base, and a rough
    // metal only as the light its facets bounce (none with --single-scatter).
    bool glossy = false, metal = false, diffuse = false;
    for (std::size_t i = 0; i < model_count; ++i) {
        const Material m = material_of(options, i).material;
        glossy |= is_glossy(m);
        metal |= m == Material::rough_metal;
        diffuse |= m == Material::diffuse || m == Material::plastic ||
                   (m == Material::rough_metal && options.multiple_scattering);
    }
    const bool split_sum = glossy && options.glossy == Glossy::split_sum;
    const bool monte_carlo = (glossy && options.glossy == Glossy::monte_carlo) ||
                             (diffuse && options.irradiance == Irradiance::monte_carlo);
    const auto refuse = [](bool unused, const char* option, const std::string& why) {
        if (unused) throw std::invalid_argument(std::string(option) + ": " + why);
    };
    const std::string materials = options.material
                                      ? std::string("--material ") + name(*options.material)
                                  : model_count > 1 ? std::string("a mirror and rough metal")
                                                    : std::string("a mirror as the only model");
    const std::string no_glossy = "no model is rough-metal or plastic (" + materials + ")";
    refuse(given.roughness && !glossy, "--roughness", no_glossy);
    refuse(given.glossy && !glossy, "--glossy", no_glossy);
    refuse(given.single_scatter && !glossy, "--single-scatter", no_glossy);
    refuse(given.metal && !metal, "--metal", "no model is rough-metal (" + materials + ")");
    refuse(given.irradiance && !diffuse, "--irradiance",
           "no model reads diffuse light (" + materials +
               (options.multiple_scattering ? "" : ", and --single-scatter") + ")");
    const std::string no_split_sum =
        glossy ? "only the split sum reads blurred maps (--glossy monte-carlo gathers its own rays)"
               : no_glossy;
    refuse(given.lookup && !split_sum, "--lookup", no_split_sum);
    refuse(given.glossy_levels && !split_sum, "--glossy-levels", no_split_sum);
    refuse(given.glossy_size && !split_sum, "--glossy-size", no_split_sum);
    refuse(given.glossy_samples && !split_sum, "--glossy-samples", no_split_sum);
    refuse(given.samples && !monte_carlo, "--samples",
           "no Monte Carlo rays are cast (only by --irradiance monte-carlo, or --glossy "
           "monte-carlo on rough-metal or plastic)");
    refuse(given.map_size && !rl::from_name(environment.source, kAnalytics) &&
               environment.layout == Layout::latlong,
           "--map-size", "an .hdr file as a lat-long map is used at its own size");
}

PreparedLight::PreparedLight(const Environment& environment, const RenderOptions& options,
                             std::size_t model_count)
    : environment_(&environment) {
    if (!(options.roughness >= 0 && options.roughness <= 1))
        throw std::invalid_argument("--roughness: " + std::to_string(options.roughness) +
                                    " is outside 0 to 1");
    if (options.samples < 1 || options.samples > kMaxIrradianceSamples)
        throw std::invalid_argument("--samples: " + std::to_string(options.samples) +
                                    " is outside 1 to " + std::to_string(kMaxIrradianceSamples));
    bool needs_diffuse = false, needs_glossy = false;
    for (std::size_t i = 0; i < model_count; ++i) {
        const Material m = material_of(options, i).material;
        needs_glossy |= is_glossy(m);
        needs_diffuse |= is_glossy(m) || m == Material::diffuse;
    }
    if (needs_diffuse)
        diffuse_.emplace([env = &environment](rl::vec3 d) { return env->sample(d); },
                         options.irradiance, options.samples);
    if (needs_glossy) split_sum_table();  // built here, not in the first pixel that asks
    if (needs_glossy && options.glossy == Glossy::split_sum)
        glossy_.emplace(environment, options.prefilter);
}

EnvironmentLight PreparedLight::light() const {
    return {environment_, diffuse_ ? &*diffuse_ : nullptr, glossy_ ? &*glossy_ : nullptr};
}

pipeline::PipelineCounts render(const std::vector<normal_mapping::MappedModel>& models,
                                const pipeline::Camera& camera, const PreparedLight& light,
                                const RenderOptions& options, LightTarget& frame) {
    bool monte_carlo = false;
    for (std::size_t i = 0; i < models.size(); ++i) {
        const SurfaceMaterial m = material_of(options, i);
        monte_carlo |= (is_glossy(m.material) && m.glossy == Glossy::monte_carlo) ||
                       ((is_glossy(m.material) || m.material == Material::diffuse) &&
                        options.irradiance == Irradiance::monte_carlo);
    }
    const long long rays = static_cast<long long>(frame.width()) * frame.height() * options.samples;
    if (monte_carlo && rays > kMaxMonteCarloRays)
        throw std::invalid_argument("--samples " + std::to_string(options.samples) + " at " +
                                    std::to_string(frame.width()) + "x" +
                                    std::to_string(frame.height()) + " asks for " +
                                    std::to_string(rays) + " Monte Carlo rays, over the " +
                                    std::to_string(kMaxMonteCarloRays) +
                                    " a frame may take: fewer samples or a smaller image");
    const float aspect = static_cast<float>(frame.width()) / static_cast<float>(frame.height());
    const rl::mat4 view_projection = pipeline::view_projection(camera, aspect);
    normal_mapping::RenderOptions surfaces;
    surfaces.normal_map = options.normal_map;
    surfaces.filter = options.map_filter;
    textures::SamplerState sampler;  // the albedo's: sRGB bytes decoded to linear light
    sampler.filter = options.map_filter;
    sampler.encoding = &shading::srgb_texels();
    pipeline::PipelineCounts counts;
    for (std::size_t i = 0; i < models.size(); ++i) {
        const normal_mapping::MappedModel& m = models[i];
        const std::optional<shading::Placed> p = shading::place(
            m.lit, view_projection, camera, surfaces.lighting, sampler, true, counts);
        if (!p) continue;
        counts += pipeline::draw(p->surface,
                                 EnvironmentShader{normal_mapping::shader_for(m, *p, surfaces),
                                                   light.light(), material_of(options, i)},
                                 frame, options.pipeline);
    }
    if (options.skybox) draw_skybox(light.environment(), camera, frame);
    return counts;
}

pipeline::PipelineCounts render(const std::vector<normal_mapping::MappedModel>& models,
                                const pipeline::Camera& camera, const Environment& environment,
                                const RenderOptions& options, LightTarget& frame) {
    return render(models, camera, PreparedLight(environment, options, models.size()), options,
                  frame);
}

}  // namespace environment
