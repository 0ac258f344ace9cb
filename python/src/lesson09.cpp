// rasterlab.lesson09: 09_environment, mirrors and glass lit by a sky, a
// studio or an .hdr file, stored as a cube or a lat-long map, with the sky
// behind them, tone mapped.
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
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, Int<"width"> width,
           Int<"height"> height, py::object source, const std::string& map,
           Int<"map_size"> map_size, const std::string& filter, const std::string& material,
           const std::string& irradiance, Int<"samples"> samples, const std::string& tone_map,
           Real<"exposure"> exposure, const std::string& normal_map, const std::string& tangents,
           bool skybox) {
            check_size(width, height);
            environment::EnvironmentOptions env_options;
            env_options.source = model_path(source, "environment");
            env_options.layout = choice("--map", map, environment::kLayouts);
            env_options.size = map_size;
            env_options.filter = choice("--filter", filter, environment::kMapFilters);
            environment::RenderOptions options;
            options.material = choice("--material", material, environment::kMaterials);
            options.irradiance = choice("--irradiance", irradiance, environment::kIrradiances);
            options.samples = samples;
            options.normal_map = choice("--normal-map", normal_map, normal_mapping::kNormalMaps);
            options.skybox = skybox;
            environment::Exposure exposure_options;
            exposure_options.curve = choice("--tone-map", tone_map, environment::kToneMaps);
            exposure_options.stops = finite("--exposure", exposure, -20, 20);
            const auto frames = choice("--tangents", tangents, normal_mapping::kTangentMethods);
            const perspective::ViewOptions view = view_options(models, camera, default_light());
            Result r;
            py::gil_scoped_release unlocked;
            const auto scene = environment::load_scene(view, frames, width, height, r.warnings);
            check_signals();
            const environment::Environment env =
                environment::make_environment(env_options, r.warnings);
            check_signals();
            environment::LightTarget frame = environment::light_target(width, height);
            const perspective::PipelineCounts counts =
                environment::render(scene.models, scene.camera, env, options, frame);
            r.colour = environment::tone_mapped(frame.colour(), exposure_options);
            r.depth = std::move(*frame.depth());
            r.count("faces", counts.faces);
            r.count("fragments", counts.fragments);
            r.count("map_size", env_options.size);
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("width") = 800, py::arg("height") = 800, py::arg("environment") = defaults.source,
        py::arg("map") = environment::name(defaults.layout), py::arg("map_size") = defaults.size,
        py::arg("filter") = environment::name(defaults.filter),
        py::arg("material") = environment::name(environment::RenderOptions{}.material),
        py::arg("irradiance") = environment::name(environment::RenderOptions{}.irradiance),
        py::arg("samples") = environment::RenderOptions{}.samples,
        py::arg("tone_map") = environment::name(environment::Exposure{}.curve),
        py::arg("exposure") = 0.0, py::arg("normal_map") = "tangent", py::arg("tangents") = "split",
        py::arg("skybox") = true,
        "09_environment: the globe and the torus (or the models given, as stored) as mirrors, "
        "glass or diffuse surfaces lit by the environment (sky, studio or the path of a lat-long "
        ".hdr), the sky "
        "behind them, linear light tone mapped to sRGB");
}

}  // namespace py_rl
