// rasterlab.lesson02: 02_triangles, a model filled with flat Lambert shading,
// and the program's three small pictures (--test-image, --overdraw, --owners).
#include <pybind11/stl.h>

#include "02_triangles/flat_shading.hpp"
#include "02_triangles/overdraw.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "rasterlab/direction.hpp"
#include "result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson02(py::module_ m) {
    const triangles::FlatOptions defaults;
    m.def(
        "draw",
        [](py::object model, Int<"width"> width, Int<"height"> height, const std::string& raster,
           const Numbers<"light">& light, bool no_cull, bool test_image, bool overdraw,
           bool owners) {
            check_size(width, height);
            triangles::FlatOptions options;
            options.method = choice("--raster", raster, triangles::kRasterMethods);
            const std::vector<float> towards = three("--light", light);
            rl::check_direction("--light", towards);
            options.light_direction = {towards[0], towards[1], towards[2]};
            options.cull_back_faces = !no_cull;
            const std::string path =
                model.is_none() ? rl::project_model("torus").string() : model_path(model);
            Result r;
            py::gil_scoped_release unlocked;
            if (overdraw) {  // the program's precedence: --overdraw, --owners, --test-image
                r.colour = triangles::overdraw_fan(options.method, 48, 12);
            } else if (owners) {
                r.colour = triangles::edge_owners(options.method, 16);
            } else if (test_image) {
                r.colour = triangles::three_triangles(options.method);
            } else {
                const rl::Mesh mesh = rl::load_obj(path, &r.warnings);
                check_signals();
                r.colour = rl::Image(width, height, rl::kBackground);
                const triangles::DrawCounts counts =
                    triangles::draw_flat_shaded(r.colour, mesh, options);
                r.count("drawn", counts.drawn);
                r.count("culled", counts.culled);
                r.count("refused", counts.refused);
            }
            return r;
        },
        py::arg("model") = py::none(), py::kw_only(), py::arg("width") = 800,
        py::arg("height") = 800, py::arg("raster") = triangles::name(defaults.method),
        py::arg("light") =
            std::vector<double>{defaults.light_direction.x, defaults.light_direction.y,
                                defaults.light_direction.z},
        py::arg("no_cull") = false, py::arg("test_image") = false, py::arg("overdraw") = false,
        py::arg("owners") = false,
        "02_triangles: a model (default obj/torus.obj) filled with flat Lambert shading, "
        "orthographic, back faces culled; or the classic three triangles (test_image), the "
        "overdraw fan (overdraw) or the edge owners (owners)");
}

}  // namespace py_rl
