// rasterlab.lesson01: 01_lines, a model's wireframe.
#include <pybind11/stl.h>

#include "01_lines/wireframe.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson01(py::module_ m) {
    m.def(
        "draw",
        [](py::object model, Int<"width"> width, Int<"height"> height, const std::string& method) {
            check_size(width, height);
            const auto line = choice("--method", method, lines::kLineMethods);
            const std::string path =
                model.is_none() ? rl::project_model("rock").string() : model_path(model);
            Result r;
            py::gil_scoped_release unlocked;
            const rl::Mesh mesh = rl::load_obj(path, &r.warnings);
            check_signals();
            r.colour = rl::Image(width, height, rl::kBackground);
            r.count("edges", lines::draw_wireframe(r.colour, mesh, lines::kWireColour, line));
            return r;
        },
        py::arg("model") = py::none(), py::kw_only(), py::arg("width") = 800,
        py::arg("height") = 800, py::arg("method") = "bresenham",
        "01_lines: the wireframe of a model (default obj/rock.obj), orthographic, with the "
        "line method named as --method names it");
}

}  // namespace py_rl
