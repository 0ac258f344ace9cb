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
    const perspective::RenderOptions defaults;
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, const Numbers<"light">& light,
           Int<"width"> width, Int<"height"> height, const std::string& clip,
           const std::string& interpolation, const std::string& lod, const std::string& filter,
           bool no_light) {
            check_size(width, height);
            perspective::RenderOptions options;
            options.pipeline.clip = choice("--clip", clip, perspective::kClipModes);
            options.pipeline.interpolation =
                choice("--interpolation", interpolation, perspective::kInterpolations);
            options.lod = choice("--lod", lod, perspective::kLodMethods);
            options.sampler.filter = choice("--filter", filter, textures::kFilters);
            const perspective::ViewOptions view = view_options(models, camera, light);
            options.light = perspective::light_direction(view);
            options.lighting = !no_light;
            Result r;
            py::gil_scoped_release unlocked;
            const auto scene = perspective::load_scene(view, width, height, r.warnings);
            check_signals();
            perspective::ColourTarget frame = perspective::colour_target(width, height);
            const perspective::PipelineCounts counts =
                perspective::render(scene.models, scene.camera, options, frame);
            take_frame(r, frame, counts, scene.camera);
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("light") = default_light(), py::arg("width") = 800, py::arg("height") = 800,
        py::arg("clip") = perspective::name(defaults.pipeline.clip),
        py::arg("interpolation") = perspective::name(defaults.pipeline.interpolation),
        py::arg("lod") = perspective::name(defaults.lod),
        py::arg("filter") = textures::name(defaults.sampler.filter), py::arg("no_light") = false,
        "05_perspective: the floor, crate and globe (or the models given, as stored) through "
        "the camera (None: framed to fit), clipped by clip, texture coordinates interpolated "
        "by interpolation");
}

}  // namespace py_rl
