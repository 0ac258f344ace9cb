// Lesson 09's render: the models with their normal maps (lesson 07) lit by
// the environment alone, into a float target of linear light, then the
// sky behind them.
//
//   auto scene = environment::load_scene(view, TangentMethod::split, 800, 800, warnings);
//   environment::LightTarget frame = environment::light_target(800, 800);
//   environment::render(scene.models, scene.camera, env, {}, frame);
#pragma once

#include "05_perspective/view_options.hpp"
#include "07_normal_mapping/scene.hpp"
#include "environment_shader.hpp"

namespace environment {

// The frame of this lesson: linear light in floats (black where nothing is
// drawn), and depth.
using LightTarget = pipeline::RenderTarget<rl::vec3>;
inline LightTarget light_target(int width, int height) {
    return LightTarget(width, height, {}, rl::vec3{0, 0, 0});
}

// The default scene: the globe and the torus side by side, in the open.
std::vector<normal_mapping::MappedModel> default_scene(std::vector<std::string>& warnings);

// The default scene (or the view's models, as stored) and its camera; for
// the default scene without --eye, a view from just above the horizon, so
// that the sky, the ground and their reflections all show.
pipeline::ViewedScene<normal_mapping::MappedModel> load_scene(
    const pipeline::ViewOptions& view, normal_mapping::TangentMethod tangents, int width,
    int height, std::vector<std::string>& warnings);

struct RenderOptions {
    // Every model's material; nothing: the default scene's look, the first
    // model a mirror and the others rough metal.
    std::optional<Material> material;
    float roughness = 0.35f;   // rough metal and plastic
    rl::vec3 metal = kGoldF0;  // the rough metal's head-on reflectance
    Glossy glossy = Glossy::split_sum;
    // Along the lobe's leaning direction: the lab's 09_glossy finds the
    // split sum's mean error 1.9 to 4.6 times smaller from roughness 0.5 to 1.
    Lookup lookup = Lookup::dominant;
    bool multiple_scattering = true;
    GlossyOptions prefilter;  // the split sum's blurred maps
    // For diffuse light (and the light glossy surfaces bounce between
    // their facets). The convolved map: the lab's 09_irradiance finds it
    // 0.8% from the truth on average where 9 harmonics are 4.7% off, for
    // about 10 ns more a pixel.
    Irradiance irradiance = Irradiance::convolved;
    int samples = 64;  // Monte Carlo's rays per pixel
    normal_mapping::NormalMap normal_map = normal_mapping::NormalMap::tangent;
    textures::Filter map_filter = textures::Filter::trilinear;  // the normal maps'
    bool skybox = true;
    pipeline::PipelineOptions pipeline;
};

// Model `index`'s material under `options`.
SurfaceMaterial material_of(const RenderOptions& options, std::size_t index);

// The options a user set: on the command line, or (in Python) to a value
// other than its default. Each must change the picture.
struct GivenOptions {
    bool roughness = false, metal = false, glossy = false, lookup = false, single_scatter = false,
         glossy_levels = false, glossy_size = false, glossy_samples = false, irradiance = false,
         samples = false, map_size = false;
};

// Throws std::invalid_argument naming the first given option that the
// materials of `model_count` models (and the environment) would ignore, and
// why: a roughness or a metal no model's material has, the split sum's
// options under Monte Carlo, rays for no Monte Carlo, a map size for an .hdr
// file read as the lat-long map it is.
void refuse_unused_options(const RenderOptions& options, const EnvironmentOptions& environment,
                           std::size_t model_count, const GivenOptions& given);

// The rays from the eye through a width x height image: the camera's frame,
// found once per frame. ray(x, y) is the unit world direction through the
// point (x, y) of the image (pixel centres at i + 0.5): the inverse of what
// the camera's projection does to a point.
class PixelRays {
  public:
    PixelRays(const pipeline::Camera& camera, int width, int height);
    rl::vec3 ray(float x, float y) const;

  private:
    rl::vec3 forward_, right_, up_;  // right and up scaled to the screen's half width and height
    float width_, height_;
};

inline rl::vec3 pixel_ray(const pipeline::Camera& camera, int width, int height, float x, float y) {
    return PixelRays(camera, width, height).ray(x, y);
}

// The sky behind the models: every pixel the models left at the far plane
// (its depth still the clear value) gets the environment's radiance along
// the ray through its centre. Drawn after the models, so each pixel is
// looked up once, never for a pixel a model covers.
void draw_skybox(const Environment& environment, const pipeline::Camera& camera,
                 LightTarget& frame);

// The light the materials of `options` need for `model_count` models,
// prepared once per environment (the irradiance, the split sum's blurred
// maps). Throws std::invalid_argument for a roughness outside 0..1, a
// sample count outside 1..kMaxIrradianceSamples, or blurred maps' options
// out of their range.
class PreparedLight {
  public:
    PreparedLight(const Environment& environment, const RenderOptions& options,
                  std::size_t model_count);
    const Environment& environment() const { return *environment_; }
    EnvironmentLight light() const;
    const GlossyMap* glossy() const { return glossy_ ? &*glossy_ : nullptr; }

  private:
    const Environment* environment_;
    std::optional<DiffuseLight> diffuse_;
    std::optional<GlossyMap> glossy_;
};

// The most Monte Carlo rays a frame may take (pixels times --samples, when
// a material uses Monte Carlo): 2^30, about 4.5 minutes of one core here
// at some 250 ns a ray.
inline constexpr long long kMaxMonteCarloRays = 1LL << 30;

// The models, then (if options.skybox) the sky. Throws
// std::invalid_argument, before drawing, when a material uses Monte Carlo
// and the frame's pixels times options.samples exceed kMaxMonteCarloRays.
pipeline::PipelineCounts render(const std::vector<normal_mapping::MappedModel>& models,
                                const pipeline::Camera& camera, const PreparedLight& light,
                                const RenderOptions& options, LightTarget& frame);
// The same, preparing the light first.
pipeline::PipelineCounts render(const std::vector<normal_mapping::MappedModel>& models,
                                const pipeline::Camera& camera, const Environment& environment,
                                const RenderOptions& options, LightTarget& frame);

}  // namespace environment
