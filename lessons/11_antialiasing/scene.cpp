#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "06_shading/colour.hpp"

namespace antialiasing {

namespace {

bool one_sample(Method method) {
    return method == Method::none || method == Method::post;
}

}  // namespace

int samples_of(const AaOptions& options) {
    return one_sample(options.method) ? 1 : options.samples;
}

void check(const AaOptions& options) {
    if (one_sample(options.method)) return;
    if (!has_count(options.pattern, options.samples))
        sample_offsets(options.pattern, options.samples);  // throws, naming the counts it has
}

void refuse_unused_options(const AaOptions& options, const GivenOptions& given) {
    const auto refuse = [](bool unused, const char* option, const std::string& why) {
        if (unused) throw std::invalid_argument(std::string(option) + ": " + why);
    };
    const std::string method = std::string("--aa ") + name(options.method);
    if (!one_sample(options.method))
        refuse(options.samples == 1, "--samples",
               method + " at one sample a pixel draws --aa none's picture");
    const std::string one = method + " takes one sample a pixel";
    const bool single = one_sample(options.method);
    refuse(given.samples && single && options.samples != 1, "--samples", one);
    refuse(given.pattern && single, "--pattern", one);
    refuse(given.resolve && single, "--resolve", one + ": there is nothing to resolve");
    refuse(options.resolve_encoded && single, "--resolve-encoded",
           one + ": there is nothing to resolve");
    refuse(given.shade_at && options.method != Method::msaa, "--shade-at",
           "only --aa msaa shades once a pixel");
    refuse(options.resolve_encoded && options.tone != ToneOrder::none, "--resolve-encoded",
           "the encoded resolve is shown without a tone map");
}

void check_frame_size(int width, int height, int samples) {
    const long long total = static_cast<long long>(width) * height * samples;
    if (total > kMaxFrameSamples)
        throw std::invalid_argument("a frame of " + std::to_string(width) + "x" +
                                    std::to_string(height) + " at " + std::to_string(samples) +
                                    " samples a pixel is past lesson 11's cap of 2^26 samples " +
                                    "(16 bytes each: 1 GiB)");
}

std::vector<rl::vec2> offsets_of(const AaOptions& options) {
    if (one_sample(options.method)) return {{0, 0}};
    return sample_offsets(options.pattern, options.samples);
}

SampleTarget draw_samples(const std::vector<normal_mapping::MappedModel>& models,
                          const pipeline::Camera& camera, const shadows::ShadowOptions& shadow,
                          Method method, const std::vector<rl::vec2>& offsets, ShadeAt shade_at,
                          int width, int height, pipeline::PipelineCounts* counts) {
    const int n = static_cast<int>(offsets.size());
    check_frame_size(width, height, n);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const shadows::ShadowMap map = shadows::shadow_map_for(models, camera, aspect, shadow);
    // The background in linear light, so that edges blend with it as light.
    const auto linear = [](std::uint8_t byte) {
        return shading::srgb_to_linear(static_cast<float>(byte) / 255);
    };
    const rl::vec3 background{linear(rl::kBackground.r), linear(rl::kBackground.g),
                              linear(rl::kBackground.b)};
    pipeline::TargetOptions samples;
    samples.samples = n;
    SampleTarget target(width, height, samples, background);
    const Supersampling ssaa{offsets};
    const Multisampling msaa{offsets, shade_at};
    const pipeline::PipelineOptions& pipeline = shadow.render.pipeline;
    const pipeline::PipelineCounts drawn = shadows::draw_shadowed(
        models, camera, aspect, shadow, map,
        [&](const normal_mapping::MappedModel&, const shading::Surface& surface,
            const shadows::ShadowedShader& shader) {
            switch (method) {
                case Method::ssaa:
                    return pipeline::draw(surface, shader, target, pipeline, ssaa);
                case Method::msaa:
                    return pipeline::draw(surface, shader, target, pipeline, msaa);
                case Method::none:
                case Method::post:
                    break;
            }
            return pipeline::draw(surface, shader, target, pipeline);
        });
    if (counts) *counts = drawn;
    return target;
}

// [doc:tone-order]
rl::Grid<rl::vec3> shown_light(const rl::Grid<rl::vec3>& samples,
                               const std::vector<rl::vec2>& offsets, const AaOptions& options) {
    environment::Exposure exposure;  // ACES
    exposure.stops = options.exposure_stops;
    const auto each = [](rl::Grid<rl::vec3> light, auto&& f) {
        for (rl::vec3& c : light.pixels()) c = f(c);
        return light;
    };
    switch (options.tone) {
        case ToneOrder::before_resolve:
            return resolve(
                each(samples, [&](rl::vec3 c) { return environment::tone_map(c, exposure); }),
                offsets, options.resolve);
        case ToneOrder::after_resolve:
            return each(resolve(samples, offsets, options.resolve),
                        [&](rl::vec3 c) { return environment::tone_map(c, exposure); });
        case ToneOrder::none:
            break;
    }
    const float scale = std::exp2(options.exposure_stops);
    if (options.resolve_encoded) {
        // Encoded, averaged, decoded: the light the averaged bytes stand for.
        const auto encode = [](float v) {
            return shading::linear_to_srgb(std::clamp(v, 0.0f, 1.0f));
        };
        const rl::Grid<rl::vec3> mean = resolve(
            each(samples,
                 [&](rl::vec3 c) {
                     return rl::vec3{encode(c.x * scale), encode(c.y * scale), encode(c.z * scale)};
                 }),
            offsets, options.resolve);
        return each(mean, [](rl::vec3 c) {
            return rl::vec3{shading::srgb_to_linear(c.x), shading::srgb_to_linear(c.y),
                            shading::srgb_to_linear(c.z)};
        });
    }
    return each(resolve(samples, offsets, options.resolve), [&](rl::vec3 c) { return c * scale; });
}
// [/doc:tone-order]

pipeline::Camera orbit(pipeline::Camera c, double degrees) {
    const double a = degrees * 3.14159265358979 / 180;
    const rl::vec3 d = c.eye - c.target;
    const float cs = static_cast<float>(std::cos(a)), sn = static_cast<float>(std::sin(a));
    c.eye = c.target + rl::vec3{cs * d.x + sn * d.z, d.y, -sn * d.x + cs * d.z};
    return c;
}

Frame render(const std::vector<normal_mapping::MappedModel>& models, const pipeline::Camera& camera,
             const shadows::ShadowOptions& shadow, const AaOptions& options, int width,
             int height) {
    check(options);
    const std::vector<rl::vec2> offsets = offsets_of(options);
    Frame f;
    const SampleTarget target = draw_samples(models, camera, shadow, options.method, offsets,
                                             options.shade_at, width, height, &f.counts);
    f.light = shown_light(target.colour(), offsets, options);
    if (options.method == Method::post) f.light = edge_filter(f.light);
    f.picture = encoded(f.light);
    return f;
}

}  // namespace antialiasing
