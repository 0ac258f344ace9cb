// Lesson 10's render: lesson 08's scene and direct light into a G-buffer,
// the ambient occlusion from it, then the picture: the direct light plus
// the ambient light, which alone the occlusion darkens (the direct light
// has its shadow map for that). Or, given an environment (lesson 09), its
// diffuse light alone, darkened by the occlusion, with the environment
// behind the models, tone mapped.
//
//   occlusion::SceneOptions options;  // lesson 08's lights, the AO's defaults
//   const occlusion::Frame f = occlusion::render(models, camera, options, 800, 800);
//   rl::save_image("10.tga", occlusion::picture(f, options));
#pragma once

#include "09_environment/environment.hpp"
#include "09_environment/irradiance.hpp"
#include "09_environment/tone_map.hpp"
#include "ambient_occlusion.hpp"
#include "baked_ao.hpp"

namespace occlusion {

// The light from everywhere (a bright overcast sky's share), times the
// albedo and the occlusion: ten times lesson 06's ambient term, so that
// what it lights is worth darkening.
inline constexpr rl::vec3 kAmbient{0.30f, 0.32f, 0.36f};

// What the program writes: the picture, the occlusion alone as grey, the
// picture without occlusion, or one of the G-buffer's images (the direct
// light, the albedo, the normal as colour (n + 1) / 2, the view depth as
// grey from near, white, to far, black).
enum class Show { image, ao, unoccluded, direct, albedo, normal, depth };
RASTERLAB_NAMED_ENUM(Show, kShows, {Show::image, "image"}, {Show::ao, "ao"},
                     {Show::unoccluded, "unoccluded"}, {Show::direct, "direct"},
                     {Show::albedo, "albedo"}, {Show::normal, "normal"}, {Show::depth, "depth"});

// Light from an environment (lesson 09) in place of lesson 08's lights:
// each point's diffuse light, albedo / pi x the irradiance E(n), is what the
// occlusion darkens. The key light is left out, since the environment's
// sun (if it has one) is that light already; no shadow map stops it, so the
// occlusion is the only shadow the sun gets here.
struct EnvironmentLight {
    const environment::Environment* sky = nullptr;       // behind the models
    const environment::DiffuseLight* diffuse = nullptr;  // E(n)
    environment::Exposure exposure;                      // lesson 09's defaults
};

// An environment and its diffuse light, built once from `source` (sky,
// studio, white or a lat-long .hdr path, as lesson 09 takes them): the map
// at lesson 09's default size and its convolved irradiance. Not movable:
// the diffuse light reads the map it holds.
class EnvironmentLighting {
  public:
    // Throws what lesson 09's make_environment throws; texels a broken file
    // had to lose are counted in `warnings`.
    EnvironmentLighting(const std::string& source, std::vector<std::string>& warnings);
    EnvironmentLighting(const EnvironmentLighting&) = delete;
    EnvironmentLighting& operator=(const EnvironmentLighting&) = delete;
    const EnvironmentLight& light() const { return light_; }

  private:
    environment::Environment sky_;
    environment::DiffuseLight diffuse_;
    EnvironmentLight light_;
};

struct SceneOptions {
    shadows::ShadowOptions shadow;  // lesson 08's: lights, shadow map, normal maps
    AoOptions ao;
    rl::vec3 ambient = kAmbient;
    const EnvironmentLight* environment = nullptr;  // none: lesson 08's lights and kAmbient
};

struct Frame {
    GBuffer g;
    rl::FloatImage ao;
    pipeline::PipelineCounts counts;
};

// A frame holds about 80 bytes a pixel (the G-buffer's three float colours
// and depth, the occlusion's points and depths, two occlusion images): its
// pixels are capped at 2^24 (4096 x 4096, about 1.3 GB), not at the 2^28
// every other lesson allows.
inline constexpr long long kMaxFramePixels = 1LL << 24;
// Throws std::invalid_argument naming the cap when width x height is past it.
void check_frame_size(int width, int height);

// The options a user set: on the command line, or (in Python) to a value
// other than its default. Each must change the picture.
struct GivenOptions {
    bool ao = false, samples = false, radius = false, blur = false, no_rotation = false,
         light = false;
};

// Throws std::invalid_argument naming the first given option that the
// picture `show` would not read: the occlusion's options where no occlusion
// is shown (--show unoccluded and the G-buffer's images), or that `ao`'s
// method would ignore (none uses no sample, radius or blur; baked rays are
// neither turned nor blurred); the light's direction where no direct light
// is shown (the occlusion, the albedo, the normals, the depth, and with an
// `environment` everything but --show direct).
void refuse_unused_options(const AoOptions& ao, bool environment, Show show,
                           const GivenOptions& given);

// Both passes and the occlusion, for `camera` at width x height. The baked
// method reads `baked` (bake_vertex_ao with the same radius), or bakes
// here, within the frame, when given none.
Frame render(const std::vector<normal_mapping::MappedModel>& models, const pipeline::Camera& camera,
             const SceneOptions& options, int width, int height, const BakedAo* baked = nullptr);

// [doc:compose]
// The light at pixel (x, y) of a model, linear, with `open` its occlusion:
// direct + ambient x albedo x open, or, with an environment,
// albedo / pi x E(n) x open.
rl::vec3 light_at(const Frame& f, const SceneOptions& options, int x, int y, float open);

// The picture: each pixel's light encoded to sRGB (lesson 06), or with an
// environment exposed and tone mapped (lesson 09) with the environment
// where no model is; without one the background.
rl::Image picture(const Frame& f, const SceneOptions& options, Show show = Show::image,
                  const Screen* screen = nullptr);  // for Show::depth and an environment
// [/doc:compose]

using shadows::load_scene;  // lesson 08's scene and camera

}  // namespace occlusion
