// rasterlab.lesson03: 03_zbuffer, hidden surfaces removed by the method of
// your choice, with the depth buffer; and its zfight experiment.
#include <pybind11/stl.h>

#include <algorithm>
#include <limits>

#include "03_zbuffer/hidden_surfaces.hpp"
#include "03_zbuffer/hsr_scenes.hpp"
#include "03_zbuffer/zfight.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson03(py::module_ m) {
    m.def(
        "render",
        [](py::object model, Int<"width"> width, Int<"height"> height, const std::string& hsr,
           const std::string& scene_name) {
            check_size(width, height);
            const auto method = choice("--hsr", hsr, zbuffer::kHsrMethods);
            const std::string which = choice("--scene", scene_name, zbuffer::kProgramScenes);
            std::vector<zbuffer::Placement> placements = zbuffer::default_placements();
            if (!model.is_none()) placements = {{model_path(model)}};
            Result r;
            py::gil_scoped_release unlocked;
            std::size_t culled = 0;
            const std::vector<zbuffer::SceneTriangle> scene =
                zbuffer::program_scene(which, placements, width, height, r.warnings, culled);
            check_signals();
            zbuffer::Frame frame(width, height);
            zbuffer::render(method, scene, frame);
            r.count("drawn", scene.size() - frame.refused);
            r.count("culled", culled);
            r.count("refused", frame.refused);
            r.colour = std::move(frame.colour);
            r.depth = std::move(frame.depth);
            return r;
        },
        py::arg("model") = py::none(), py::kw_only(), py::arg("width") = 800,
        py::arg("height") = 800, py::arg("hsr") = "zbuffer", py::arg("scene") = "models",
        "03_zbuffer: the rock pierced by the torus (or a model alone, or the scenes sticks "
        "and soup) with hidden surfaces removed by hsr; depth is the z-buffer");
    m.def(
        "zfight",
        [](Int<"width"> width, Int<"height"> height, const std::string& format_name,
           Real<"distance"> distance, Real<"near"> near, Real<"far"> far, bool fitted) {
            check_size(width, height);
            const auto format = choice("--format", format_name, zbuffer::kDepthFormats);
            zbuffer::TwoPlanes planes;
            planes.distance = finite("--distance", distance, 1e-3, 1e6);
            const double positive = std::numeric_limits<double>::denorm_min();
            zbuffer::DepthRange range{finite("--near", near, positive),
                                      finite("--far", far, positive)};
            planes.size = std::min<int>(width, height);
            if (fitted) range = zbuffer::fitted_range(planes);
            if (!(range.near_plane > 0 && range.near_plane < range.far_plane))
                throw py::value_error("need 0 < near < far");
            Result r;
            py::gil_scoped_release unlocked;
            r.colour = zbuffer::zfight_map(format, range, planes);
            r.count("share", zbuffer::zfight_share(format, range, planes));
            r.count("near", static_cast<double>(range.near_plane));
            r.count("far", static_cast<double>(range.far_plane));
            return r;
        },
        py::kw_only(), py::arg("width") = 800, py::arg("height") = 800,
        py::arg("format") = "float-z", py::arg("distance") = zbuffer::TwoPlanes{}.distance,
        py::arg("near") = 0.1, py::arg("far") = 1000.0, py::arg("fitted") = false,
        "03_zbuffer zfight: two planes 0.01 apart seen in perspective, red where the far one "
        "wrongly wins in the depth format; counts['share'] is that share of pixels");
}

}  // namespace py_rl
