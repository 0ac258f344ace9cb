// rasterlab.lesson12: 12_fast, lesson 07's image from the tiled, threaded
// SIMD renderer, timed over frames of an orbiting camera. (The llvmpipe peer
// is the program's and the lab's: it is not timed from Python.)
#include <pybind11/stl.h>

#include <chrono>
#include <vector>

#include "12_fast/orbit.hpp"
#include "12_fast/renderer.hpp"
#include "12_fast/tile_kernels.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "mapped_keywords.hpp"
#include "pipeline_result.hpp"

namespace py_rl {

namespace {

// fast::render_orbit() with a look for Ctrl-C between frames (every 50 ms at
// most): the same frames, the same timers around each.
fast::OrbitRun orbit_run(fast::Renderer& renderer, const perspective::Camera& camera, int frames) {
    std::vector<double> times;
    fast::OrbitRun run;
    for (int i = 0; i < frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        run.counts = renderer.render(fast::orbit(camera, i, frames));
        times.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        if (i + 1 < frames) check_signals(50);
    }
    run.median_ms = fast::median_after_first(std::move(times));
    return run;
}

}  // namespace

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
            const fast::OrbitRun run = orbit_run(renderer, scene.camera, frames);
            r.colour = renderer.frame();
            r.count("frames", frames);
            r.count("median_ms", run.median_ms);
            r.count("threads", renderer.threads());
            r.count("simd", std::string(fast::simd_target()));
            r.count("triangles", run.counts.triangles);
            r.count("pixels_shaded", static_cast<std::size_t>(run.counts.tiles.shaded));
            const fast::StageTimes& t = renderer.times();
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
        "first excluded, and the last frame's stage times");
}

}  // namespace py_rl
