// Lesson 11's render: lesson 08's scene and light into a target of linear
// light holding several samples a pixel, filled by a coverage policy
// (coverage.hpp), then resolved (resolve.hpp) and encoded to sRGB.
//
//   antialiasing::AaOptions aa;  // multisampling, 4 standard samples, box resolve
//   const antialiasing::Frame f = antialiasing::render(models, camera, shadow, aa, 800, 800);
//   rl::save_image("11.tga", f.picture);
#pragma once

#include "08_shadows/scene.hpp"
#include "09_environment/tone_map.hpp"
#include "coverage.hpp"
#include "post_filter.hpp"
#include "resolve.hpp"
#include "sample_pattern.hpp"

namespace antialiasing {

// none: one sample a pixel, at its centre (lesson 05's policy). ssaa:
// supersampling, every sample shaded. msaa: multisampling, coverage and
// depth per sample, one shading a pixel per triangle. post: one sample a
// pixel, then the edge filter of post_filter.hpp on the picture.
enum class Method { none, ssaa, msaa, post };
RASTERLAB_NAMED_ENUM(Method, kMethods, {Method::none, "none"}, {Method::ssaa, "ssaa"},
                     {Method::msaa, "msaa"}, {Method::post, "post"});

// Between the samples and the bytes. none: the light is encoded as it
// is, clamped at 1 (lessons 05-10's way). after_resolve: lesson 09's tone
// map (ACES) of the resolved light: the mean of the light, as a sensor
// would take it. before_resolve: the tone map of each sample, then the
// resolve: the mean of what the screen shows. They differ where a bright
// surface meets a dark one: a sample worth 16 times white tone-maps to
// about 1, so after_resolve lets one bright sample in four whiten the pixel.
enum class ToneOrder { none, after_resolve, before_resolve };
RASTERLAB_NAMED_ENUM(ToneOrder, kToneOrders, {ToneOrder::none, "none"},
                     {ToneOrder::after_resolve, "after-resolve"},
                     {ToneOrder::before_resolve, "before-resolve"});

struct AaOptions {
    Method method = Method::msaa;
    int samples = 4;
    Pattern pattern = Pattern::standard;
    Resolve resolve = Resolve::box;
    // msaa only. The centroid: the lab finds msaa 4 at the centroid as near
    // the truth at edges as 8 at the centre, in half the time.
    ShadeAt shade_at = ShadeAt::centroid;
    ToneOrder tone = ToneOrder::none;
    float exposure_stops = 0;  // the light times 2^stops before the tone map (or the clamp)
    // The pitfall, to be seen: average the samples as sRGB-encoded values
    // (what averaging the bytes of an 8-bit target does) instead of light.
    bool resolve_encoded = false;
};

// The samples the options' method takes a pixel: 1 for none and post.
int samples_of(const AaOptions& options);

// Throws std::invalid_argument naming the option: a pattern without that
// many samples (none takes 1 whatever --samples says, and says so only by
// ignoring it: the program refuses the combination itself).
void check(const AaOptions& options);

// The options a user set: on the command line, or (in Python) to a value
// other than its default. Each must change the picture.
struct GivenOptions {
    bool samples = false, pattern = false, resolve = false, shade_at = false;
};

// Throws std::invalid_argument naming the first option the method would
// ignore: with one sample a pixel (none, post, or ssaa and msaa at 1, which
// draw --aa none's picture) a sample count, a pattern, a resolve or the
// encoded resolve; a place to shade but for msaa; the encoded resolve under
// a tone map.
void refuse_unused_options(const AaOptions& options, const GivenOptions& given);

// A frame holds 16 bytes a sample (linear colour in float and depth): its
// samples, pixels times samples a pixel, are capped at 2^26 (1 GiB; 4096 x
// 4096 at 4 samples, 2048 x 2048 at 16).
inline constexpr long long kMaxFrameSamples = 1LL << 26;
// Throws std::invalid_argument naming the cap when width x height x samples is past it.
void check_frame_size(int width, int height, int samples);

struct Frame {
    rl::Grid<rl::vec3>
        light;          // resolved, exposed and tone-mapped if asked: linear, 0 to 1 as shown
    rl::Image picture;  // the light in sRGB bytes
    pipeline::PipelineCounts counts;
};

// Lesson 08's two passes, the second through the options' coverage policy,
// then the resolve.
Frame render(const std::vector<normal_mapping::MappedModel>& models, const pipeline::Camera& camera,
             const shadows::ShadowOptions& shadow, const AaOptions& options, int width, int height);

// What render() draws before its resolve: every sample of the frame, for
// explicit offsets (the lab's truth draws 256 a pixel as 16 frames of 16).
using SampleTarget = pipeline::RenderTarget<rl::vec3>;
SampleTarget draw_samples(const std::vector<normal_mapping::MappedModel>& models,
                          const pipeline::Camera& camera, const shadows::ShadowOptions& shadow,
                          Method method, const std::vector<rl::vec2>& offsets, ShadeAt shade_at,
                          int width, int height, pipeline::PipelineCounts* counts = nullptr);

// The offsets the options ask for: {0, 0} for none and post.
std::vector<rl::vec2> offsets_of(const AaOptions& options);

// The light the picture shows, from a frame's samples: resolved, exposed,
// and tone-mapped before or after the resolve as the options ask.
rl::Grid<rl::vec3> shown_light(const rl::Grid<rl::vec3>& samples,
                               const std::vector<rl::vec2>& offsets, const AaOptions& options);

// The camera turned about the vertical through its target by `degrees`
// (a frame of a slow orbit: the lab's motion, the page's crawling edges).
pipeline::Camera orbit(pipeline::Camera camera, double degrees);

using shadows::load_scene;  // lesson 08's scene and camera

}  // namespace antialiasing
