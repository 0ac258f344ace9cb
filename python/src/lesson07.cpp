// rasterlab.lesson07: 07_normal_mapping, models with their diffuse, normal
// and specular maps, lit per pixel.
#include <pybind11/stl.h>

#include "07_normal_mapping/scene.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "mapped_keywords.hpp"
#include "pipeline_result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson07(py::module_ m) {
    const normal_mapping::MappedView defaults;
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, const Numbers<"light">& light,
           Int<"width"> width, Int<"height"> height, const std::string& normal_map,
           const std::string& tangents, const std::string& specular, const std::string& filter,
           bool naive, bool one_light) {
            check_size(width, height);
            normal_mapping::MappedView request = mapped_view(
                models, camera, light, normal_map, tangents, specular, filter, naive, one_light);
            Result r;
            py::gil_scoped_release unlocked;
            const auto scene = normal_mapping::load_scene(request, width, height, r.warnings);
            check_signals();
            pipeline::ColourTarget frame = pipeline::colour_target(width, height);
            const pipeline::PipelineCounts counts =
                normal_mapping::render(scene.models, scene.camera, request.options, frame);
            take_frame(r, frame, counts, scene.camera);
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("light") = default_light(), py::arg("width") = 800, py::arg("height") = 800,
        py::arg("normal_map") = normal_mapping::name(defaults.options.normal_map),
        py::arg("tangents") = normal_mapping::name(defaults.tangents),
        py::arg("specular") = shading::name(defaults.options.specular),
        py::arg("filter") = textures::name(defaults.options.filter), py::arg("naive") = false,
        py::arg("one_light") = false,
        "07_normal_mapping: the floor, globe and crate (or the models given, as stored) with "
        "their diffuse, normal and specular maps, lit per pixel in linear light");
}

}  // namespace py_rl
