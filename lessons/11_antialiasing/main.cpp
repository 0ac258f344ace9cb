// Lesson 11: antialiasing. Lesson 08's scene with several samples a pixel:
// supersampling (every sample shaded) or multisampling (coverage and depth
// per sample, one shading a pixel), in a pattern of samples, resolved in
// linear light by a box or a tent. Read docs/11_antialiasing.md beside it.
#include <chrono>
#include <cstdio>

#include "05_perspective/view_cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "scene.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 11, antialiasing: lesson 08's scene with several samples a pixel, supersampled or "
        "multisampled, resolved in linear light."};
    rl::ImageOptions image_options{"11_antialiasing.tga"};
    pipeline::ViewOptions view;
    shadows::ShadowOptions shadow;
    antialiasing::AaOptions options;
    normal_mapping::TangentMethod tangents = normal_mapping::TangentMethod::split;
    view.light = {shadows::kSceneLight.x, shadows::kSceneLight.y, shadows::kSceneLight.z};
    pipeline::add_view_options(app, view, "floor, globe, crate and torus from obj/");
    rl::add_image_options(app, image_options);
    rl::add_method_option(app, "--aa", options.method, antialiasing::kMethods,
                          "How a pixel is sampled: once, supersampled, multisampled, or once and "
                          "then the edge filter");
    rl::Option* samples =
        app.add_option("--samples", options.samples,
                       "Samples a pixel for ssaa and msaa: 2, 4, 8 or 16 (as the pattern has them)")
            ->capture_default_str()
            ->check(rl::one_of({1, 2, 4, 8, 16}));
    rl::Option* pattern = rl::add_method_option(
        app, "--pattern", options.pattern, antialiasing::kPatterns,
        "Where a pixel's samples lie: an ordered grid (4, 16), a rotated grid "
        "(4) or Direct3D's standard patterns (2, 4, 8, 16)");
    rl::Option* resolve =
        rl::add_method_option(app, "--resolve", options.resolve, antialiasing::kResolves,
                              "How samples become a pixel: their mean (box), or a tent over the "
                              "pixel and its neighbours");
    rl::Option* shade_at =
        rl::add_method_option(app, "--shade-at", options.shade_at, antialiasing::kShadeAts,
                              "msaa: where the fragment stage runs in a pixel");
    rl::add_method_option(app, "--tone-map", options.tone, antialiasing::kToneOrders,
                          "Lesson 09's tone map (ACES): none (the light clamped at 1), after the "
                          "resolve, or on each sample before it");
    app.add_option("--exposure", options.exposure_stops,
                   "Stops: the light times 2^stops before the tone map or the clamp (-16 to 16)")
        ->capture_default_str()
        ->check(rl::finite_number(-16, 16));
    app.add_flag("--resolve-encoded", options.resolve_encoded,
                 "The pitfall: average the samples' sRGB-encoded values instead of their light "
                 "(with --tone-map none)");
    double orbit_degrees = 0;
    app.add_option("--orbit", orbit_degrees,
                   "Turn the camera about the vertical through its target, degrees (-360 to 360): "
                   "a frame of a slow orbit")
        ->capture_default_str()
        ->check(rl::finite_number(-360, 360));
    rl::add_method_option(app, "--normal-map", shadow.render.normal_map,
                          normal_mapping::kNormalMaps, "Normal map to use (lesson 07)");
    rl::add_method_option(app, "--tangents", tangents, normal_mapping::kTangentMethods,
                          "Tangent frames of the --model files (lesson 07)");
    return app.run(argc, argv, "11_antialiasing", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::check_image_output(output);
        // Options the method would ignore are refused, not ignored.
        antialiasing::refuse_unused_options(options, {.samples = samples->count() > 0,
                                                      .pattern = pattern->count() > 0,
                                                      .resolve = resolve->count() > 0,
                                                      .shade_at = shade_at->count() > 0});
        antialiasing::check(options);
        antialiasing::check_frame_size(width, height, antialiasing::samples_of(options));
        shadows::set_lights(shadow, view, false);
        std::vector<std::string> warnings;
        const auto [models, framed] =
            antialiasing::load_scene(view, tangents, width, height, warnings);
        const pipeline::Camera camera = antialiasing::orbit(framed, orbit_degrees);
        rl::print_warnings("11_antialiasing", warnings);
        if (shadow.render.filter == textures::Filter::trilinear)
            normal_mapping::build_mip_levels(models);
        const auto start = std::chrono::steady_clock::now();
        const antialiasing::Frame frame =
            antialiasing::render(models, camera, shadow, options, width, height);
        const std::chrono::duration<double, std::milli> ms =
            std::chrono::steady_clock::now() - start;
        rl::save_image(output, frame.picture);
        // What the method used: a pattern and a resolve only with several samples.
        const int n = antialiasing::samples_of(options);
        const std::string sampling = n == 1
                                         ? "one sample a pixel"
                                         : std::to_string(n) + " samples a pixel (" +
                                               antialiasing::name(options.pattern) + " pattern, " +
                                               antialiasing::name(options.resolve) + " resolve)";
        std::printf(
            "%zu models: %zu faces, %zu fragments shaded, %zu samples stored; %s, %s in a frame "
            "of %.1f ms; into %s\n",
            models.size(), frame.counts.faces, frame.counts.shaded, frame.counts.stored,
            antialiasing::name(options.method), sampling.c_str(), ms.count(), output.c_str());
        return 0;
    });
}
