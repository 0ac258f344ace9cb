// rasterlab.lesson05: 05_perspective, textured models through a camera,
// clipped, interpolated perspective-correctly (or not).
#include <pybind11/stl.h>

#include "05_perspective/scene.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "pipeline_result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson05(py::module_ m) {
    const pipeline::RenderOptions defaults;
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, const Numbers<"light">& light,
           Int<"width"> width, Int<"height"> height, const std::string& clip,
           const std::string& interpolation, const std::string& lod, const std::string& filter,
           bool no_light) {
            check_size(width, height);
            pipeline::RenderOptions options;
            options.pipeline.clip = choice("--clip", clip, pipeline::kClipModes);
            options.pipeline.interpolation =
                choice("--interpolation", interpolation, pipeline::kInterpolations);
            options.lod = choice("--lod", lod, pipeline::kLodMethods);
            options.sampler.filter = choice("--filter", filter, textures::kFilters);
            const pipeline::ViewOptions view = view_options(models, camera, light);
            options.light = pipeline::light_direction(view);
            options.lighting = !no_light;
            Result r;
            py::gil_scoped_release unlocked;
            const auto scene = pipeline::load_scene(view, width, height, r.warnings);
            check_signals();
            pipeline::ColourTarget frame = pipeline::colour_target(width, height);
            const pipeline::PipelineCounts counts =
                pipeline::render(scene.models, scene.camera, options, frame);
            take_frame(r, frame, counts, scene.camera);
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("light") = default_light(), py::arg("width") = 800, py::arg("height") = 800,
        py::arg("clip") = pipeline::name(defaults.pipeline.clip),
        py::arg("interpolation") = pipeline::name(defaults.pipeline.interpolation),
        py::arg("lod") = pipeline::name(defaults.lod),
        py::arg("filter") = textures::name(defaults.sampler.filter), py::arg("no_light") = false,
        "05_perspective: the floor, crate and globe (or the models given, as stored) through "
        "the camera (None: framed to fit), clipped by clip, texture coordinates interpolated "
        "by interpolation");
}

}  // namespace py_rl
