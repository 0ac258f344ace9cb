// Lesson 09: light from the whole environment. The models (lesson 07's, with
// their normal maps) as mirrors, glass, rough metal or plastic, lit by a sky, a studio or a
// Radiance .hdr file stored as a cube or a lat-long map, the sky behind them;
// linear HDR light, then the exposure, a tone map and sRGB. Read
// docs/09_environment.md beside it.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "05_perspective/view_cli.hpp"
#include "rasterlab/image_io.hpp"
#include "rasterlab/main_guard.hpp"
#include "scene.hpp"
#include "tone_map.hpp"

int main(int argc, char** argv) {
    rl::CommandLine app{
        "Lesson 09, environment: mirrors, glass, rough metal and plastic lit by a sky, a studio or "
        "an .hdr file, as a cube or a lat-long map, with the sky behind them, tone mapped."};
    rl::ImageOptions image_options{"09_environment.tga"};
    pipeline::ViewOptions view;
    environment::EnvironmentOptions env_options;
    environment::RenderOptions options;
    environment::Exposure exposure;
    normal_mapping::TangentMethod tangents = normal_mapping::TangentMethod::split;
    pipeline::add_view_options(app, view, "the globe and the torus from obj/");
    app.remove_option(app.get_option("--light"));  // the environment is the light here
    rl::add_image_options(app, image_options);
    app.add_option(
           "--environment", env_options.source,
           "The light around the scene: sky, studio, white (a furnace: radiance 1 everywhere), "
           "or the path of a lat-long .hdr file")
        ->capture_default_str();
    rl::add_method_option(app, "--map", env_options.layout, environment::kLayouts,
                          "How the environment is stored");
    rl::Option* map_size =
        app.add_option("--map-size", env_options.size,
                       "A cube face's side, or a lat-long map's height, in texels (1 to " +
                           std::to_string(environment::kMaxMapSize) + ")")
            ->capture_default_str();
    rl::add_method_option(app, "--filter", env_options.filter, environment::kMapFilters,
                          "How the map is read between texels");
    std::vector<float> metal;
    environment::Material material = environment::Material::mirror;
    rl::Option* material_option =
        rl::add_method_option(app, "--material", material, environment::kMaterials,
                              "What every model is made of")
            ->default_str("the first model mirror, the others rough-metal");
    rl::Option* roughness =
        app.add_option("--roughness", options.roughness,
                       "How rough rough-metal and plastic are: 0 (a mirror) to 1")
            ->capture_default_str()
            ->check(rl::finite_number(0, 1));
    rl::Option* metal_option =
        app.add_option(
               "--metal", metal,
               "The rough metal's head-on reflectance, R G B from 0 to 1 (gold: 1 0.71 0.29; "
               "white, 1 1 1, for the white furnace)")
            ->expected(3)
            ->check(rl::finite_number(0, 1));
    rl::Option* glossy =
        rl::add_method_option(app, "--glossy", options.glossy, environment::kGlossies,
                              "How rough-metal and plastic gather the light they reflect");
    rl::Option* lookup = rl::add_method_option(
        app, "--lookup", options.lookup, environment::kLookups,
        "Where the split sum reads its blurred maps: along the mirror direction, "
        "or leaning towards the normal as a rough lobe does");
    bool single_scatter = false;
    rl::Option* single =
        app.add_flag("--single-scatter", single_scatter,
                     "Leave out the light that bounces between a rough surface's facets (the "
                     "microfacet BRDF's lost energy)");
    rl::Option* glossy_levels =
        app.add_option("--glossy-levels", options.prefilter.levels,
                       "Roughness steps of the split sum's blurred maps (2 to " +
                           std::to_string(environment::kMaxGlossyLevels) + ")")
            ->capture_default_str()
            ->check(rl::range(2, environment::kMaxGlossyLevels));
    rl::Option* glossy_size = app.add_option("--glossy-size", options.prefilter.size,
                                             "The largest blurred map's face, in texels (8 to " +
                                                 std::to_string(environment::kMaxGlossySize) + ")")
                                  ->capture_default_str()
                                  ->check(rl::range(8, environment::kMaxGlossySize));
    rl::Option* glossy_samples =
        app.add_option("--glossy-samples", options.prefilter.samples,
                       "GGX rays per texel of the blurred maps (1 to " +
                           std::to_string(environment::kMaxGlossySamples) + ")")
            ->capture_default_str()
            ->check(rl::range(1, environment::kMaxGlossySamples));
    rl::Option* irradiance =
        rl::add_method_option(app, "--irradiance", options.irradiance, environment::kIrradiances,
                              "How a diffuse surface finds the light arriving from its hemisphere");
    rl::Option* samples =
        app.add_option("--samples", options.samples,
                       "Monte Carlo's rays per pixel (--irradiance or --glossy monte-carlo; 1 to " +
                           std::to_string(environment::kMaxIrradianceSamples) + ")")
            ->capture_default_str()
            ->check(rl::range(1, environment::kMaxIrradianceSamples));
    rl::add_method_option(app, "--tone-map", exposure.curve, environment::kToneMaps,
                          "How light above 1 is brought into the image");
    app.add_option("--exposure", exposure.stops, "Exposure in stops: the light times 2^stops")
        ->capture_default_str()
        ->check(rl::finite_number(-20, 20));
    rl::add_method_option(app, "--frame-store", exposure.store, environment::kFrameStores,
                          "What the frame keeps before the tone map: float light, or (no HDR) "
                          "the exposed light as linear bytes, 0 to 1 in 256 steps");
    rl::add_method_option(app, "--normal-map", options.normal_map, normal_mapping::kNormalMaps,
                          "Normal map to use (lesson 07)");
    rl::add_method_option(app, "--tangents", tangents, normal_mapping::kTangentMethods,
                          "Tangent frames of the --model files (lesson 07)");
    std::string maps_folder;
    app.add_option("--write-maps", maps_folder,
                   "Also write the maps the render read (the environment with its mip levels, "
                   "the blurred maps) as Radiance .hdr files into this existing folder");
    bool no_skybox = false;
    app.add_flag("--no-skybox", no_skybox, "Leave the background black instead of the sky");
    return app.run(argc, argv, "09_environment", [&] {
        const std::string& output = image_options.output;
        const int width = image_options.width, height = image_options.height;
        rl::ImageOutputs outputs;
        outputs.check(output);
        options.skybox = !no_skybox;
        options.multiple_scattering = !single_scatter;
        if (material_option->count() > 0) options.material = material;
        if (!metal.empty()) options.metal = {metal[0], metal[1], metal[2]};
        std::vector<std::string> warnings;
        // The models first: a model the loader refuses costs no map.
        const auto [models, camera] =
            environment::load_scene(view, tangents, width, height, warnings);
        // Options the materials would ignore are refused, not ignored.
        environment::refuse_unused_options(options, env_options, models.size(),
                                           {.roughness = roughness->count() > 0,
                                            .metal = metal_option->count() > 0,
                                            .glossy = glossy->count() > 0,
                                            .lookup = lookup->count() > 0,
                                            .single_scatter = single->count() > 0,
                                            .glossy_levels = glossy_levels->count() > 0,
                                            .glossy_size = glossy_size->count() > 0,
                                            .glossy_samples = glossy_samples->count() > 0,
                                            .irradiance = irradiance->count() > 0,
                                            .samples = samples->count() > 0,
                                            .map_size = map_size->count() > 0});
        const auto start = std::chrono::steady_clock::now();
        const environment::Environment env = environment::make_environment(env_options, warnings);
        const environment::PreparedLight light(env, options, models.size());
        const auto built = std::chrono::steady_clock::now();
        // The maps' files are checked before the frame is drawn: a bad
        // folder, or a name that is the input's or the image's, costs no frame.
        std::vector<environment::MapFile> map_files;
        if (!maps_folder.empty()) {
            map_files = environment::map_files(env, light.glossy());
            for (const environment::MapFile& f : map_files)
                outputs.check_file(std::filesystem::path(maps_folder) / f.name);
        }
        rl::print_warnings("09_environment", warnings);
        if (options.map_filter == textures::Filter::trilinear)
            normal_mapping::build_mip_levels(models);
        const auto drawing = std::chrono::steady_clock::now();
        environment::LightTarget frame = environment::light_target(width, height);
        const pipeline::PipelineCounts counts =
            environment::render(models, camera, light, options, frame);
        const rl::Image picture = environment::tone_mapped(frame.colour(), exposure);
        const auto done = std::chrono::steady_clock::now();
        outputs.stage(output, picture);
        for (const environment::MapFile& f : map_files) {
            const std::filesystem::path path = std::filesystem::path(maps_folder) / f.name;
            outputs.stage_bytes(path, rl::encode_hdr(path, *f.image));
        }
        outputs.commit();
        const std::chrono::duration<double, std::milli> map_ms = built - start,
                                                        frame_ms = done - drawing;
        std::printf(
            "%zu models: %zu faces, %zu fragments shaded, %s; %s environment as a %s map (%d, %s "
            "filter) and its light built in %.1f ms; frame (with the sky and the %s tone map) in "
            "%.1f ms; into "
            "%s%s\n",
            models.size(), counts.faces, counts.shaded,
            options.material ? environment::name(*options.material) : "mirror and rough-metal",
            env_options.source.c_str(), environment::name(env.layout()),
            env.cube() ? env.cube()->size() : env.latlong()->height(),
            environment::name(env.filter()), map_ms.count(), environment::name(exposure.curve),
            frame_ms.count(), output.c_str(),
            map_files.empty()
                ? ""
                : (", and " + std::to_string(map_files.size()) + " maps into " + maps_folder)
                      .c_str());
        return 0;
    });
}
