// rasterlab.lesson09: 09_environment, mirrors, glass, rough metal and
// plastic lit by a sky, a studio or an .hdr file, stored as a cube or a
// lat-long map, with the sky behind them, tone mapped.
#include <pybind11/stl.h>

#include "09_environment/scene.hpp"
#include "09_environment/tone_map.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson09(py::module_ m) {
    const environment::EnvironmentOptions defaults;
    const environment::RenderOptions rendering;
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, Int<"width"> width,
           Int<"height"> height, py::object source, const std::string& map,
           Int<"map_size"> map_size, const std::string& filter,
           const std::optional<std::string>& material, Real<"roughness"> roughness,
           const Numbers<"metal">& metal, const std::string& glossy, const std::string& lookup,
           bool multiple_scattering, Int<"glossy_levels"> glossy_levels,
           Int<"glossy_size"> glossy_size, Int<"glossy_samples"> glossy_samples,
           const std::string& irradiance, Int<"samples"> samples, const std::string& tone_map,
           Real<"exposure"> exposure, const std::string& frame_store, const std::string& normal_map,
           const std::string& tangents, bool skybox) {
            check_size(width, height);
            environment::EnvironmentOptions env_options;
            env_options.source = environment_source(source);
            env_options.layout = choice("--map", map, environment::kLayouts);
            env_options.size = map_size;
            env_options.filter = choice("--filter", filter, environment::kMapFilters);
            environment::RenderOptions options;
            if (material)
                options.material = choice("--material", *material, environment::kMaterials);
            options.roughness = finite("--roughness", roughness, 0, 1);
            const std::vector<float> f0 = three("--metal", metal);
            for (float c : f0) finite("--metal", c, 0, 1);
            options.metal = {f0[0], f0[1], f0[2]};
            options.glossy = choice("--glossy", glossy, environment::kGlossies);
            options.lookup = choice("--lookup", lookup, environment::kLookups);
            options.multiple_scattering = multiple_scattering;
            in_range("--glossy-levels", glossy_levels, 2, environment::kMaxGlossyLevels);
            in_range("--glossy-size", glossy_size, 8, environment::kMaxGlossySize);
            in_range("--glossy-samples", glossy_samples, 1, environment::kMaxGlossySamples);
            options.prefilter = {glossy_levels, glossy_size, glossy_samples};
            options.irradiance = choice("--irradiance", irradiance, environment::kIrradiances);
            options.samples = samples;
            options.normal_map = choice("--normal-map", normal_map, normal_mapping::kNormalMaps);
            options.skybox = skybox;
            environment::Exposure exposure_options;
            exposure_options.curve = choice("--tone-map", tone_map, environment::kToneMaps);
            exposure_options.stops = finite("--exposure", exposure, -20, 20);
            exposure_options.store =
                choice("--frame-store", frame_store, environment::kFrameStores);
            const auto frames = choice("--tangents", tangents, normal_mapping::kTangentMethods);
            const pipeline::ViewOptions view = view_options(models, camera, default_light());
            Result r;
            py::gil_scoped_release unlocked;
            const auto scene = environment::load_scene(view, frames, width, height, r.warnings);
            // As the program: an option the materials would ignore is
            // refused; here one counts as given when it is not its default.
            const environment::RenderOptions d;
            environment::refuse_unused_options(
                options, env_options, scene.models.size(),
                {.roughness = options.roughness != d.roughness,
                 .metal = options.metal != d.metal,
                 .glossy = options.glossy != d.glossy,
                 .lookup = options.lookup != d.lookup,
                 .single_scatter = !multiple_scattering,
                 .glossy_levels = glossy_levels != d.prefilter.levels,
                 .glossy_size = glossy_size != d.prefilter.size,
                 .glossy_samples = glossy_samples != d.prefilter.samples,
                 .irradiance = options.irradiance != d.irradiance,
                 .samples = samples != d.samples,
                 .map_size = map_size != environment::EnvironmentOptions{}.size});
            check_signals();
            const environment::Environment env =
                environment::make_environment(env_options, r.warnings);
            check_signals();
            environment::LightTarget frame = environment::light_target(width, height);
            const pipeline::PipelineCounts counts =
                environment::render(scene.models, scene.camera, env, options, frame);
            r.colour = environment::tone_mapped(frame.colour(), exposure_options);
            r.depth = std::move(*frame.depth());
            r.count("faces", counts.faces);
            r.count("fragments", counts.shaded);
            r.count("map_size", env_options.size);
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("width") = 800, py::arg("height") = 800, py::arg("environment") = defaults.source,
        py::arg("map") = environment::name(defaults.layout), py::arg("map_size") = defaults.size,
        py::arg("filter") = environment::name(defaults.filter), py::arg("material") = py::none(),
        py::arg("roughness") = rendering.roughness,
        py::arg("metal") =
            std::vector<double>{rendering.metal.x, rendering.metal.y, rendering.metal.z},
        py::arg("glossy") = environment::name(rendering.glossy),
        py::arg("lookup") = environment::name(rendering.lookup),
        py::arg("multiple_scattering") = true,
        py::arg("glossy_levels") = rendering.prefilter.levels,
        py::arg("glossy_size") = rendering.prefilter.size,
        py::arg("glossy_samples") = rendering.prefilter.samples,
        py::arg("irradiance") = environment::name(environment::RenderOptions{}.irradiance),
        py::arg("samples") = environment::RenderOptions{}.samples,
        py::arg("tone_map") = environment::name(environment::Exposure{}.curve),
        py::arg("exposure") = 0.0,
        py::arg("frame_store") = environment::name(environment::Exposure{}.store),
        py::arg("normal_map") = "tangent", py::arg("tangents") = "split", py::arg("skybox") = true,
        "09_environment: the globe and the torus (or the models given, as stored) as mirrors, "
        "glass, diffuse surfaces, rough metal or plastic (material=None: a mirror globe and a "
        "rough-metal torus) lit by the environment (sky, studio, white or the path of a lat-long "
        ".hdr), the sky behind them, linear light tone mapped to sRGB");
}

}  // namespace py_rl
