// rasterlab.lesson06: 06_shading, models lit by flat, Gouraud, Phong or
// Blinn-Phong shading in linear light (or naively).
#include <pybind11/stl.h>

#include "06_shading/scene.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "pipeline_result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson06(py::module_ m) {
    const shading::ShadingOptions defaults;
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, const Numbers<"light">& light,
           Int<"width"> width, Int<"height"> height, const std::string& shading_model,
           const std::string& weighting, Real<"shininess"> shininess, bool naive, bool one_light) {
            check_size(width, height);
            shading::ShadingOptions options;
            options.model = choice("--shading", shading_model, shading::kShadingModels);
            const auto weights = choice("--weighting", weighting, shading::kWeightings);
            const float exponent = finite("--shininess", shininess, 0, 1e6);
            const pipeline::ViewOptions view = view_options(models, camera, light);
            options.output = naive ? shading::Output::naive : shading::Output::srgb;
            options.lighting = shading::default_lighting(pipeline::light_direction(view));
            if (one_light) options.lighting.lights.resize(1);
            options.lighting.shininess = exponent;
            Result r;
            py::gil_scoped_release unlocked;
            const auto scene =
                shading::load_scene(view, options.output, weights, width, height, r.warnings);
            check_signals();
            std::size_t computed = 0;
            for (const shading::LitModel& lit : scene.models) computed += lit.computed_normals;
            pipeline::ColourTarget frame = pipeline::colour_target(width, height);
            const pipeline::PipelineCounts counts =
                shading::render(scene.models, scene.camera, options, frame);
            take_frame(r, frame, counts, scene.camera);
            r.count("computed_normals", computed);
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("light") = default_light(), py::arg("width") = 800, py::arg("height") = 800,
        py::arg("shading") = shading::name(defaults.model), py::arg("weighting") = "angle",
        py::arg("shininess") = defaults.lighting.shininess, py::arg("naive") = false,
        py::arg("one_light") = false,
        "06_shading: the floor, globe and torus (or the models given, as stored) lit by the "
        "shading model in linear light (naive: the bytes lit as if linear)");
}

}  // namespace py_rl
