// rasterlab.lesson12: 12_fast, lesson 07's image from the tiled, threaded
// SIMD renderer, timed over frames of an orbiting camera. (The llvmpipe peer
// is the program's and the lab's: it is not timed from Python.)
#include <pybind11/stl.h>

#include "12_fast/orbit.hpp"
#include "12_fast/renderer.hpp"
#include "12_fast/tile_kernels.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "mapped_keywords.hpp"
#include "pipeline_result.hpp"

namespace py_rl {

void bind_lesson12(py::module_ m) {
    const normal_mapping::MappedView mapped;
    const fast::FastOptions defaults;
    m.def(
        "render",
        [](py::object models, std::optional<Camera> camera, const Numbers<"light">& light,
           Int<"width"> width, Int<"height"> height, const std::string& normal_map,
           const std::string& tangents, const std::string& specular, const std::string& filter,
           bool naive, bool one_light, Int<"frames"> frames, Int<"threads"> threads,
           Int<"tile_size"> tile_size) {
            check_size(width, height);
            normal_mapping::MappedView request = mapped_view(
                models, camera, light, normal_map, tangents, specular, filter, naive, one_light);
            in_range("--frames", frames, 1, 1000);
            in_range("--threads", threads, 0, 256);
            in_range("--tile-size", tile_size, 8, 1024);
            fast::check_frames(frames, width, height);
            fast::FastOptions options;
            options.threads = threads;
            options.tile_size = tile_size;
            Result r;
            py::gil_scoped_release unlocked;
            const auto scene = normal_mapping::load_scene(request, width, height, r.warnings);
            check_signals();
            options.render = request.options;  // with the lighting and output load_scene set
            fast::Renderer renderer(scene.models, width, height, options);
            check_signals();
            // Ctrl-C between frames (at most every 50 ms), and between tiles.
            const fast::OrbitRun run =
                fast::render_orbit(renderer, scene.camera, frames, [] { check_signals(50); });
            r.colour = renderer.frame();
            r.count("frames", frames);
            r.count("median_ms", run.median_ms);
            r.count("threads", renderer.threads());
            r.count("simd", std::string(fast::simd_target()));
            r.count("triangles", run.counts.pipeline.drawn);
            r.count("pixels_shaded", static_cast<std::size_t>(run.counts.tiles.shaded));
            const fast::StageTimes& t = run.median_stages;
            r.count("vertex_ms", t.vertex);
            r.count("setup_ms", t.setup);
            r.count("binning_ms", t.binning);
            r.count("tiles_ms", t.tiles);
            return r;
        },
        py::arg("models") = py::none(), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("light") = default_light(), py::arg("width") = 800, py::arg("height") = 800,
        py::arg("normal_map") = normal_mapping::name(mapped.options.normal_map),
        py::arg("tangents") = normal_mapping::name(mapped.tangents),
        py::arg("specular") = shading::name(mapped.options.specular),
        py::arg("filter") = textures::name(mapped.options.filter), py::arg("naive") = false,
        py::arg("one_light") = false, py::arg("frames") = 30, py::arg("threads") = defaults.threads,
        py::arg("tile_size") = defaults.tile_size,
        "12_fast: lesson 07's picture from the fast path, the camera orbiting the target over "
        "frames (the last is the view asked for); counts give the median ms per frame, the "
        "first excluded, and each stage's median");
}

}  // namespace py_rl
