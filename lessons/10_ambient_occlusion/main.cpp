// Lesson 10: ambient occlusion. Lesson 08's scene drawn once into a
// G-buffer (direct light, albedo, normal, depth), then a screen-space pass
// that finds how open each visible point's hemisphere is, which darkens the
// ambient light only. Read docs/10_ambient_occlusion.md beside this.
#include <chrono>
#include <cstdio>
#include <optional>

#include "05_perspective/view_cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "scene.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 10, ambient occlusion: lesson 08's scene into a G-buffer, then screen-space "
        "ambient occlusion darkening the ambient light."};
    rl::ImageOptions image_options{"10_ambient_occlusion.tga"};
    pipeline::ViewOptions view;
    occlusion::SceneOptions options;
    normal_mapping::TangentMethod tangents = normal_mapping::TangentMethod::split;
    occlusion::Show show = occlusion::Show::image;
    view.light = {shadows::kSceneLight.x, shadows::kSceneLight.y, shadows::kSceneLight.z};
    pipeline::add_view_options(app, view, "floor, globe, crate and torus from obj/");
    rl::add_image_options(app, image_options);
    rl::Option* ao_option = rl::add_method_option(
        app, "--ao", options.ao.method, occlusion::kAoMethods, "How the occlusion is found");
    rl::Option* samples = app.add_option("--samples", options.ao.samples,
                                         "Depth-buffer reads a pixel (1 to " +
                                             std::to_string(occlusion::kMaxAoSamples) +
                                             "; horizon: 8 per slice; baked: rays a vertex)")
                              ->capture_default_str()
                              ->check(rl::range(1, occlusion::kMaxAoSamples));
    rl::Option* radius_option =
        app.add_option("--radius", options.ao.radius,
                       "How far an occluder may be, in world units (the floor is 3.4 wide)")
            ->capture_default_str()
            ->check(rl::finite_number(1e-4, 1e4));
    rl::Option* blur = app.add_option("--blur", options.ao.blur,
                                      "The blur's half width in pixels, within one surface (0 to " +
                                          std::to_string(occlusion::kMaxBlurRadius) + "; 0: none)")
                           ->capture_default_str()
                           ->check(rl::range(0, occlusion::kMaxBlurRadius));
    bool no_rotation = false;
    rl::Option* no_rotation_flag =
        app.add_flag("--no-rotation", no_rotation,
                     "The same kernel at every pixel, not turned by the 4x4 noise");
    rl::add_method_option(
        app, "--show", show, occlusion::kShows,
        "Write the picture, the occlusion alone, the picture without it, or one of the "
        "G-buffer's images");
    std::string environment_source;
    app.add_option("--environment", environment_source,
                   "Light by lesson 09's environment instead of lesson 08's lights: sky, studio, "
                   "white, or the path of a lat-long .hdr file (its diffuse light is what the "
                   "occlusion darkens)");
    rl::add_method_option(app, "--normal-map", options.shadow.render.normal_map,
                          normal_mapping::kNormalMaps, "Normal map to use (lesson 07)");
    rl::add_method_option(app, "--tangents", tangents, normal_mapping::kTangentMethods,
                          "Tangent frames of the --model files (lesson 07)");
    return app.run(argc, argv, "10_ambient_occlusion", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::check_image_output(output);
        options.ao.rotate = !no_rotation;
        occlusion::check(options.ao);
        // Options the method (or the environment) would ignore are refused, not ignored.
        occlusion::refuse_unused_options(options.ao, !environment_source.empty(), show,
                                         {.ao = ao_option->count() > 0,
                                          .samples = samples->count() > 0,
                                          .radius = radius_option->count() > 0,
                                          .blur = blur->count() > 0,
                                          .no_rotation = no_rotation_flag->count() > 0,
                                          .light = app.get_option("--light")->count() > 0});
        occlusion::check_frame_size(width, height);
        shadows::set_lights(options.shadow, view, false);
        std::vector<std::string> warnings;
        const auto [models, camera] =
            occlusion::load_scene(view, tangents, width, height, warnings);
        rl::print_warnings("10_ambient_occlusion", warnings);
        if (options.shadow.render.filter == textures::Filter::trilinear)
            normal_mapping::build_mip_levels(models);
        // The environment and the bake belong to loading, not to the
        // frame: timed apart.
        using Clock = std::chrono::steady_clock;
        const auto load = Clock::now();
        std::optional<occlusion::EnvironmentLighting> lighting;
        if (!environment_source.empty()) {
            std::vector<std::string> map_warnings;  // texels a broken .hdr had to lose
            lighting.emplace(environment_source, map_warnings);
            rl::print_warnings("10_ambient_occlusion", map_warnings);
            options.environment = &lighting->light();
        }
        const auto lit = Clock::now();
        // Embree's scene is built first, timed apart from the rays it casts.
        std::optional<occlusion::RayTracedAo> rays;
        std::optional<occlusion::BakedAo> baked;
        if (options.ao.method == occlusion::AoMethod::baked) rays.emplace(models);
        const auto scene_built = Clock::now();
        if (rays)
            baked = occlusion::bake_vertex_ao(models, *rays, options.ao.radius, options.ao.samples);
        const auto start = Clock::now();
        const occlusion::Frame frame =
            occlusion::render(models, camera, options, width, height, baked ? &*baked : nullptr);
        const auto done = Clock::now();
        const occlusion::Screen screen(camera, width, height);
        rl::save_image(output, occlusion::picture(frame, options, show, &screen));
        const std::chrono::duration<double, std::milli> ms = done - start,
                                                        bake = start - scene_built,
                                                        embree = scene_built - lit,
                                                        light = lit - load;
        if (lighting)
            std::printf("%s environment and its diffuse light built in %.1f ms\n",
                        environment_source.c_str(), light.count());
        if (baked)
            std::printf("Embree's scene built in %.1f ms; baked %d rays a vertex in %.1f ms\n",
                        embree.count(), options.ao.samples, bake.count());
        // What the method used: no samples for none, rays a vertex and no blur for baked.
        char settings[96] = "";
        const double radius = options.ao.radius;
        if (options.ao.method == occlusion::AoMethod::baked)
            std::snprintf(settings, sizeof settings, " (%d rays a vertex, radius %g)",
                          options.ao.samples, radius);
        else if (options.ao.method != occlusion::AoMethod::none)
            std::snprintf(settings, sizeof settings, " (%d samples, radius %g, blur %d)",
                          options.ao.samples, radius, options.ao.blur);
        std::printf(
            "%zu models: %zu faces, %zu fragments shaded; %s occlusion%s in a frame of %.1f ms; "
            "%s into %s\n",
            models.size(), frame.counts.faces, frame.counts.shaded,
            occlusion::name(options.ao.method), settings, ms.count(), occlusion::name(show),
            output.c_str());
        return 0;
    });
}
