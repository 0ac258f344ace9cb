// Lesson 12's lab: how fast the fast path is, what each technique buys, and
// how it stands against lesson 07's path and Mesa's llvmpipe on the same
// cores. Every frame is timed over an orbit of the camera (Google Benchmark:
// 5 repetitions interleaved in random order, warm-up excluded); every image
// is also compared, with lesson 07's and with llvmpipe's.
//   1. 12_steps.csv: lesson 07's path, then the fast path with one technique
//      after another turned on, at 1024x1024, on two scenes;
//   2. 12_sizes.csv: 512^2 to 4096^2, four scenes (lesson 07's, the globe
//      filling the frame, and spheres of about 200 thousand and a million
//      triangles with the globe's maps): ours, llvmpipe doing our shader's
//      work and a plain llvmpipe (one light, the colour map), each on 2
//      threads and on 1 (the one-thread cells in a second run of the lab:
//      lab/one_thread_run.hpp), lesson 07 (its scene), and the floor:
//      clearing colour and depth and writing every pixel once;
//   3. 12_triangles.csv: the sphere from 2 thousand to 2 million triangles
//      at 1024x1024, ours and llvmpipe;
//   4. 12_stages.csv: where the fast path's time goes;
//   5. 12_pairs.csv: each technique of the finished fast path turned off,
//      in frames alternated one by one with the fast path as it is (paired
//      frames: a disturbance of the machine slows both of a pair, and the
//      ratio within each pair keeps gains of a few per cent that the five
//      runs of the steps cannot tell from noise).
#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include "05_perspective/view_options.hpp"
#include "06_shading/truths/sphere_truth.hpp"
#include "12_fast/orbit.hpp"
#include "12_fast/renderer.hpp"
#include "hwy/targets.h"
#include "one_thread_run.hpp"
#include "rasterlab/image_metrics.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"
#include "rasterlab/transform.hpp"
#ifdef RASTERLAB_LLVMPIPE
#include "12_fast/peer/llvmpipe_peer.hpp"
#endif

namespace {

using normal_mapping::MappedModel;

constexpr int kOrbitFrames = 30;  // the camera goes round once in this many frames
constexpr int kThreads = 2;       // this machine's cores: ours and llvmpipe's

struct Scene {
    std::string name;
    std::vector<MappedModel> models;
    pipeline::Camera camera;
};

pipeline::Camera framed(const std::vector<MappedModel>& models) {
    pipeline::Box box;
    for (const MappedModel& m : models)
        box.add(pipeline::bounds(m.lit.model.mesh, m.lit.model.transform));
    return pipeline::resolve_camera({}, box, 1.0f);  // what the programs frame
}

// A sphere the globe's size with the globe's maps and `segments` around
// (segments^2 triangles), for the triangle-count sweep.
MappedModel sphere_with_globe_maps(const MappedModel& globe, int segments) {
    MappedModel m{globe.lit, {}, globe.maps};
    m.lit.model.mesh = shading::uv_sphere(segments);
    m.lit.model.mesh.source = globe.lit.model.mesh.source;
    m.lit.model.box = pipeline::bounds(m.lit.model.mesh, rl::mat4::identity());
    m.lit.normals = shading::corner_normals(m.lit.model.mesh, shading::Weighting::angle);
    m.tangents = normal_mapping::corner_tangents(m.lit.model.mesh, m.lit.normals,
                                                 normal_mapping::TangentMethod::split);
    return m;
}

// The unit globe seen so that it touches the top and bottom of the frame.
pipeline::Camera filling_the_frame() {
    pipeline::Camera c;
    c.fov_y = 50;
    const float distance = 1.0f / std::sin(rl::radians(c.fov_y / 2));
    c.eye = rl::vec3{0.3f, 0.35f, 1.0f} * (distance / rl::length(rl::vec3{0.3f, 0.35f, 1.0f}));
    c.target = {0, 0, 0};
    c.near = distance - 1.2f;
    c.far = distance + 1.2f;
    return c;
}

// ------------------------------------------------------------- the timings

struct Cell {
    const Scene* scene;
    int size;
    std::string renderer;         // "fast", "lesson 07", "llvmpipe", "llvmpipe plain", "floor"
    fast::FastOptions options;    // for "fast"
    std::int64_t simd = 0;        // a Highway target to run with (0: the best)
    std::string name;             // the benchmark's
    int peer_threads = kThreads;  // for "llvmpipe" and "llvmpipe plain"
    // For "fast": models other than the scene's (ours at the plain peer's
    // work: the scene's without their specular maps).
    const std::vector<MappedModel>* models = nullptr;
};

void time_fast(benchmark::State& state, const Cell* c) {
    hwy::SetSupportedTargetsForTest(c->simd);
    fast::Renderer renderer(c->models ? *c->models : c->scene->models, c->size, c->size,
                            c->options);
    // A first frame, untimed, as llvmpipe's (which compiles its shaders):
    // it grows the buffers, and a cell of one iteration a run (a million
    // triangles) would otherwise time only that cold frame.
    renderer.render(c->scene->camera);
    int frame = 0;
    for (auto _ : state) {
        renderer.render(fast::orbit(c->scene->camera, frame++ % kOrbitFrames, kOrbitFrames));
        benchmark::DoNotOptimize(renderer.frame().get(0, 0));
    }
    hwy::SetSupportedTargetsForTest(0);
}

void time_lesson07(benchmark::State& state, const Cell* c) {
    pipeline::ColourTarget target = pipeline::colour_target(c->size, c->size);
    int frame = 0;
    for (auto _ : state) {
        target.clear(rl::kBackground);
        normal_mapping::render(c->scene->models,
                               fast::orbit(c->scene->camera, frame++ % kOrbitFrames, kOrbitFrames),
                               c->options.render, target);
        benchmark::DoNotOptimize(target.colour().get(0, 0));
    }
}

// The floor: what any renderer must do per frame at this size, on the same
// threads: clear a colour and a depth buffer and write every pixel once.
void time_floor(benchmark::State& state, const Cell* c) {
    rl::Image colour(c->size, c->size);
    std::vector<float> depth(colour.pixels().size());
    tbb::task_arena arena(kThreads);
    const std::size_t width = static_cast<std::size_t>(c->size);
    for (auto _ : state) {
        arena.execute([&] {
            tbb::parallel_for(0, c->size, [&](int y) {
                const std::size_t row = static_cast<std::size_t>(y) * width;
                std::fill_n(depth.data() + row, width, 1.0f);
                std::fill_n(colour.pixels().data() + row, width, rl::kBackground);
                for (std::size_t x = 0; x < width; ++x) colour.pixels()[row + x].r = 1;
            });
        });
        benchmark::DoNotOptimize(colour.pixels().data());
        benchmark::DoNotOptimize(depth.data());
    }
}

#ifdef RASTERLAB_LLVMPIPE
void time_llvmpipe(benchmark::State& state, const Cell* c) {
    fast::LlvmpipePeer peer(
        c->size, c->size, c->peer_threads,
        c->renderer == "llvmpipe plain" ? fast::PeerShader::plain : fast::PeerShader::same_work);
    peer.upload(c->scene->models, c->options.render);
    peer.render(c->scene->camera);  // the first frame compiles the shaders
    int frame = 0;
    for (auto _ : state)
        peer.render(fast::orbit(c->scene->camera, frame++ % kOrbitFrames, kOrbitFrames));
}
#endif

// `threads`: the peer's in this process, from its first context on.
bool peer_available(int threads) {
#ifdef RASTERLAB_LLVMPIPE
    try {
        fast::LlvmpipePeer probe(8, 8, threads);
        return true;
    } catch (const fast::PeerUnavailable& e) {
        std::printf("llvmpipe peer skipped: %s\n", e.what());
        return false;
    }
#else
    (void)threads;
    std::printf(
        "llvmpipe peer skipped: this build has none (OSMesa, libosmesa6-dev, missing; or a "
        "sanitized build)\n");
    return false;
#endif
}

void register_cell(Cell& c) {
    benchmark::internal::Benchmark* b = nullptr;
    if (c.renderer == "lesson 07")
        b = benchmark::RegisterBenchmark(c.name.c_str(), time_lesson07, &c);
    else if (c.renderer == "floor")
        b = benchmark::RegisterBenchmark(c.name.c_str(), time_floor, &c);
#ifdef RASTERLAB_LLVMPIPE
    else if (c.renderer == "llvmpipe" || c.renderer == "llvmpipe plain")
        b = benchmark::RegisterBenchmark(c.name.c_str(), time_llvmpipe, &c);
#endif
    else
        b = benchmark::RegisterBenchmark(c.name.c_str(), time_fast, &c);
    b->Unit(benchmark::kMillisecond);
}

// A pair of renderers, one with a technique off: `frames` pairs of frames,
// the order within a pair alternating, each frame timed alone.
struct Pair {
    const Scene* scene;
    int size;
    std::string technique;
    fast::FastOptions off;
    int frames;
    std::string name;  // the benchmark's
    // The run's results:
    std::vector<double> ms_off{}, ms_on{}, ratio{};  // per pair: on / off
    int levels_apart = 0;                            // the last pair's two images
};

void time_pair(benchmark::State& state, Pair* p) {
    using Clock = std::chrono::steady_clock;
    fast::Renderer off(p->scene->models, p->size, p->size, p->off);
    fast::Renderer on(p->scene->models, p->size, p->size, {});
    off.render(p->scene->camera), on.render(p->scene->camera);  // buffers grown, untimed
    p->ms_off.clear(), p->ms_on.clear(), p->ratio.clear();
    for (auto _ : state)
        for (int f = 0; f < p->frames; ++f) {
            const pipeline::Camera camera =
                fast::orbit(p->scene->camera, f % kOrbitFrames, kOrbitFrames);
            double ms[2];
            for (int k = 0; k < 2; ++k) {
                const int which = (k + f) % 2;  // 0: off, 1: on
                const Clock::time_point start = Clock::now();
                (which == 0 ? off : on).render(camera);
                ms[which] = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            }
            p->ms_off.push_back(ms[0]), p->ms_on.push_back(ms[1]);
            p->ratio.push_back(ms[1] / ms[0]);
        }
    p->levels_apart = rl::compare_images(off.frame(), on.frame(), 1).max_abs;
}

// The value below which a share q of `values` lies (nearest rank).
double quantile(std::vector<double> values, double q) {
    std::sort(values.begin(), values.end());
    return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5)];
}

// ------------------------------------------------------------- the images

rl::Image fast_frame(const Scene& s, int size, const fast::FastOptions& o, std::int64_t simd) {
    hwy::SetSupportedTargetsForTest(simd);
    fast::Renderer renderer(s.models, size, size, o);
    renderer.render(s.camera);
    hwy::SetSupportedTargetsForTest(0);
    return renderer.frame();
}

rl::Image lesson07_frame(const Scene& s, int size, const normal_mapping::RenderOptions& o) {
    pipeline::ColourTarget target = pipeline::colour_target(size, size);
    normal_mapping::render(s.models, s.camera, o, target);
    return target.colour();
}

std::optional<rl::Image> llvmpipe_frame(const Scene& s, int size,
                                        const normal_mapping::RenderOptions& o) {
#ifdef RASTERLAB_LLVMPIPE
    fast::LlvmpipePeer peer(size, size, kThreads);
    peer.upload(s.models, o);
    peer.render(s.camera);
    return peer.frame();
#else
    (void)s, (void)size, (void)o;
    return std::nullopt;
#endif
}

// The steps: every technique off, then on one after another.
struct Step {
    std::string label;
    fast::FastOptions options;
    std::int64_t simd;
};
std::vector<Step> steps(std::int64_t scalar, const std::vector<std::int64_t>& simd_sets) {
    fast::FastOptions o;
    o.vertex_cache = false;
    o.parallel = false;
    o.threads = 1;
    o.techniques = {false, false, false, false, false, false, false};
    o.specular_in_normal_alpha = false;
    o.albedo_in_one_word = false;
    std::vector<Step> out;
    out.push_back({"one thread, scalar, per corner", o, scalar});
    o.vertex_cache = true;
    out.push_back({"+ vertex cache", o, scalar});
    o.techniques.coarse_blocks = true;
    out.push_back({"+ 8x8 blocks accepted and rejected whole", o, scalar});
    o.techniques.hierarchical_depth = true;
    out.push_back({"+ a depth bound per block", o, scalar});
    o.techniques.shade_once = true;
    out.push_back({"+ visibility buffer: each pixel shaded once", o, scalar});
    // Each instruction set this CPU has, narrowest first, then full vectors.
    for (auto it = simd_sets.rbegin(); it != simd_sets.rend(); ++it) {
        if (*it == scalar) continue;
        out.push_back({std::string("+ SIMD: ") + hwy::TargetName(*it), o, *it});
    }
    o.techniques.full_vectors = true;
    out.push_back({"+ full vectors (a triangle's pixels queued)", o, simd_sets.front()});
    o.techniques.across_triangles = true;
    out.push_back({"+ the queue carried across triangles", o, simd_sets.front()});
    o.techniques.block_rows = true;
    out.push_back({"+ only the rows of a block a triangle reaches", o, simd_sets.front()});
    o.techniques.srgb_one_gather = true;
    out.push_back({"+ sRGB with one gather", o, simd_sets.front()});
    o.specular_in_normal_alpha = true;
    out.push_back({"+ the specular map in the normal map's alpha", o, simd_sets.front()});
    o.albedo_in_one_word = true;
    out.push_back({"+ the albedo in one word", o, simd_sets.front()});
    o.parallel = true;
    o.threads = kThreads;
    out.push_back({"+ 2 threads: the fast path", o, simd_sets.front()});
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    // The one-thread cells' run (a child of the lab's own run), or the lab.
    const bool one_thread_run = fast::lab::take_one_thread_flag(argc, argv);
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    const rl::lab::Options options = rl::lab::init(
        argc, argv,
        "Lesson 12's lab: the fast path, technique by technique, against lesson 07 and Mesa's "
        "llvmpipe. Writes 12_steps.csv, 12_sizes.csv, 12_triangles.csv, 12_pairs.csv and "
        "12_stages.csv.");
    return rl::guarded_main("12_fast_lab", [&] {
        const bool peer = peer_available(one_thread_run ? 1 : kThreads);
        std::vector<std::string> warnings;
        std::vector<Scene> scenes;
        scenes.push_back(
            {"lesson 07's scene",
             normal_mapping::default_scene(normal_mapping::TangentMethod::split, warnings),
             {}});
        scenes.back().camera = framed(scenes.back().models);
        const MappedModel globe =
            normal_mapping::load_mapped_model(rl::project_model("globe"), rl::mat4::identity(),
                                              normal_mapping::TangentMethod::split, warnings);
        scenes.push_back({"the globe filling the frame", {globe}, filling_the_frame()});
        // Spheres of segments^2 triangles: about 200 thousand and a million.
        for (const int segments :
             options.quick ? std::vector<int>{32, 64} : std::vector<int>{448, 1000})
            scenes.push_back({"a sphere of " + std::to_string(segments * segments) + " triangles",
                              {sphere_with_globe_maps(globe, segments)},
                              filling_the_frame()});
        for (const Scene& s : scenes) normal_mapping::build_mip_levels(s.models);

        const std::vector<std::int64_t> simd_sets = fast::simd_targets();
        const std::int64_t scalar = simd_sets.back();  // the portable fallback
        const std::vector<int> sizes =
            options.quick ? std::vector<int>{64, 96} : std::vector<int>{512, 800, 1024, 2048, 4096};
        const int step_size = options.quick ? 96 : 1024;

        std::vector<std::unique_ptr<Cell>> cells;
        const auto add = [&](const Scene& s, int size, const std::string& renderer,
                             const fast::FastOptions& o, std::int64_t simd,
                             const std::string& label) {
            cells.push_back(std::make_unique<Cell>(Cell{
                &s, size, renderer, o, simd, s.name + "/" + std::to_string(size) + "/" + label}));
            return cells.back().get();
        };
        // 1. The steps, on lesson 07's scene and on the globe.
        std::vector<std::pair<const Cell*, std::string>> step_cells;  // cell, its step's label
        const std::vector<Step> ladder = steps(scalar, simd_sets);
        for (int k = 0; k < (one_thread_run ? 0 : 2); ++k) {
            const Scene& s = scenes[static_cast<std::size_t>(k)];
            step_cells.push_back(
                {add(s, step_size, "lesson 07", {}, 0, "step/lesson 07"), "lesson 07"});
            for (const Step& step : ladder)
                step_cells.push_back(
                    {add(s, step_size, "fast", step.options, step.simd, "step/" + step.label),
                     step.label});
            if (peer)
                step_cells.push_back(
                    {add(s, step_size, "llvmpipe", {}, 0, "step/llvmpipe"), "llvmpipe, 2 threads"});
        }
        // 2. The sizes. The one-thread cells (ours, llvmpipe's) are timed
        // in the lab's second run, named alike there and here.
        fast::FastOptions one_thread;
        one_thread.threads = 1;
        std::vector<const Cell*> size_cells;
        std::vector<Cell*> one_thread_cells;
        const auto on_one_thread = [&](Cell* c) {
            c->peer_threads = 1;  // (a "fast" cell's threads are its options')
            one_thread_cells.push_back(c);
            size_cells.push_back(c);
        };
        // Ours at the plain peer's work (and the sRGB encoding on the way
        // out, which the plain peer leaves out): one light, Phong, the colour
        // map, no normal or specular map.
        fast::FastOptions plain_work;
        plain_work.render.normal_map = normal_mapping::NormalMap::none;
        plain_work.render.specular = shading::Specular::phong;
        plain_work.render.lighting.lights.resize(1);
        std::vector<std::vector<MappedModel>> without_specular_maps;
        without_specular_maps.reserve(scenes.size());
        if (peer)  // (its row stands beside the plain peer's)
            for (const Scene& s : scenes) {
                without_specular_maps.push_back(s.models);
                for (MappedModel& m : without_specular_maps.back()) m.maps.specular.reset();
            }
        for (const Scene& s : scenes)
            for (int size : sizes) {
                size_cells.push_back(add(s, size, "fast", {}, 0, "fast, 2 threads"));
                if (peer) {
                    size_cells.push_back(add(s, size, "llvmpipe", {}, 0, "llvmpipe, 2 threads"));
                    size_cells.push_back(
                        add(s, size, "llvmpipe plain", {}, 0, "llvmpipe plain, 2 threads"));
                    Cell* plain = add(s, size, "fast", plain_work, 0,
                                      "fast at the plain peer's work, 2 threads");
                    plain->models =
                        &without_specular_maps[static_cast<std::size_t>(&s - &scenes[0])];
                    size_cells.push_back(plain);
                }
                on_one_thread(add(s, size, "fast", one_thread, 0, "fast, 1 thread"));
                if (peer) {
                    on_one_thread(add(s, size, "llvmpipe", {}, 0, "llvmpipe, 1 thread"));
                    on_one_thread(
                        add(s, size, "llvmpipe plain", {}, 0, "llvmpipe plain, 1 thread"));
                }
                size_cells.push_back(add(s, size, "floor", {}, 0, "floor"));
                if (&s == &scenes[0])
                    size_cells.push_back(add(s, size, "lesson 07", {}, 0, "lesson 07, 1 thread"));
            }
        if (one_thread_run) {  // the child: these cells alone
            for (Cell* c : one_thread_cells) register_cell(*c);
            fast::lab::write_one_thread_timings(rl::lab::run_benchmarks(), options.out_dir);
            return 0;
        }
        // Tables of an earlier run must not pass for this one's when this
        // run (narrowed by --benchmark_filter) leaves them out.
        const char* const kTables[] = {"12_steps.csv", "12_sizes.csv", "12_triangles.csv",
                                       "12_stages.csv", "12_pairs.csv"};
        for (const char* table : kTables) std::filesystem::remove(options.out_dir / table);
        // 3. The triangle counts.
        std::vector<Scene> spheres;
        const std::vector<int> segments = options.quick
                                              ? std::vector<int>{8, 16}
                                              : std::vector<int>{32, 64, 128, 256, 512, 1000, 1414};
        spheres.reserve(segments.size());
        for (int n : segments)
            spheres.push_back({std::to_string(n * n) + " triangles",
                               {sphere_with_globe_maps(globe, n)},
                               filling_the_frame()});
        std::vector<const Cell*> triangle_cells;
        fast::FastOptions each_alone;  // each triangle's last vector shaded part-empty
        each_alone.techniques.across_triangles = false;
        fast::FastOptions every_row;  // each block's eight rows, whatever the triangle's size
        every_row.techniques.block_rows = false;
        for (const Scene& s : spheres) {
            triangle_cells.push_back(add(s, step_size, "fast", {}, 0, "fast, 2 threads"));
            triangle_cells.push_back(add(s, step_size, "fast", each_alone, 0,
                                         "fast, 2 threads, no queue across triangles"));
            triangle_cells.push_back(
                add(s, step_size, "fast", every_row, 0, "fast, 2 threads, every row of a block"));
            if (peer)
                triangle_cells.push_back(
                    add(s, step_size, "llvmpipe", {}, 0, "llvmpipe, 2 threads"));
        }
        // 5. The pairs: each technique off against the fast path as it is.
        const std::pair<const char*, void (*)(fast::FastOptions&)> techniques[] = {
            {"vertex cache", [](fast::FastOptions& o) { o.vertex_cache = false; }},
            {"8x8 blocks accepted and rejected whole",
             [](fast::FastOptions& o) { o.techniques.coarse_blocks = false; }},
            {"a depth bound per block",
             [](fast::FastOptions& o) { o.techniques.hierarchical_depth = false; }},
            {"the queue carried across triangles",
             [](fast::FastOptions& o) { o.techniques.across_triangles = false; }},
            {"only the rows of a block a triangle reaches",
             [](fast::FastOptions& o) { o.techniques.block_rows = false; }},
            {"sRGB with one gather",
             [](fast::FastOptions& o) { o.techniques.srgb_one_gather = false; }},
            {"the specular map in the normal map's alpha",
             [](fast::FastOptions& o) { o.specular_in_normal_alpha = false; }},
            {"the albedo in one word", [](fast::FastOptions& o) { o.albedo_in_one_word = false; }},
        };
        std::vector<std::unique_ptr<Pair>> pairs;
        for (int k = 0; k < 2; ++k)
            for (const auto& [technique, turn_off] : techniques) {
                const Scene& s = scenes[static_cast<std::size_t>(k)];
                fast::FastOptions off;
                turn_off(off);
                pairs.push_back(
                    std::make_unique<Pair>(Pair{.scene = &s,
                                                .size = step_size,
                                                .technique = technique,
                                                .off = off,
                                                .frames = options.quick ? 4 : 200,
                                                .name = "pairs/" + s.name + "/" + technique}));
            }
        if (!one_thread_run)
            for (auto& p : pairs)
                benchmark::RegisterBenchmark(p->name.c_str(), time_pair, p.get())
                    ->Unit(benchmark::kMillisecond)
                    ->Iterations(1)
                    ->Repetitions(1);
        const std::set<const Cell*> in_child(one_thread_cells.begin(), one_thread_cells.end());
        for (auto& c : cells)
            if (!in_child.count(c.get())) register_cell(*c);
        std::map<std::string, rl::lab::Timing> timings = rl::lab::run_benchmarks();
        timings.merge(fast::lab::run_one_thread_child(arguments, options.out_dir));
        // A run narrowed by --benchmark_filter writes the tables whose cells
        // all ran, and only those (a table with a missing cell would be a
        // different table).
        const auto all_ran = [&](const std::vector<const Cell*>& section) {
            return std::all_of(section.begin(), section.end(),
                               [&](const Cell* c) { return timings.count(c->name) > 0; });
        };
        std::vector<const Cell*> step_section;
        for (const auto& step : step_cells) step_section.push_back(step.first);
        std::vector<std::string> written;
        const auto ms = [&](const Cell* c) { return timings.at(c->name).median_ns / 1e6; };
        const auto ms_min = [&](const Cell* c) { return timings.at(c->name).min_ns / 1e6; };
        const auto ms_max = [&](const Cell* c) { return timings.at(c->name).max_ns / 1e6; };

        // 1. The steps, each image against lesson 07's.
        if (all_ran(step_section)) {
            rl::ResultsTable steps_table({"scene", "step", "ms_per_frame", "ms_min", "ms_max",
                                          "times_faster_than_lesson_07", "max_abs_vs_lesson_07",
                                          "percent_off_by_more_than_1"});
            std::map<const Scene*, double> lesson07_ms;
            for (const auto& [c, label] : step_cells) {
                if (c->renderer == "lesson 07") lesson07_ms[c->scene] = ms(c);
                std::optional<rl::Image> image;
                const rl::Image expected = lesson07_frame(*c->scene, c->size, c->options.render);
                if (c->renderer == "fast")
                    image = fast_frame(*c->scene, c->size, c->options, c->simd);
                if (c->renderer == "llvmpipe")
                    image = llvmpipe_frame(*c->scene, c->size, c->options.render);
                if (c->renderer == "lesson 07") image = expected;
                const rl::ImageDiff d = rl::compare_images(expected, *image, 1);
                steps_table.add_row({c->scene->name, label, ms(c), ms_min(c), ms_max(c),
                                     lesson07_ms.at(c->scene) / ms(c),
                                     static_cast<long long>(d.max_abs), 100 * d.share_over});
            }
            steps_table.write_csv(options.out_dir / "12_steps.csv");
            written.push_back("12_steps.csv");
        }
        // 2. The sizes: each against the floor (on 2 threads), ours against
        // llvmpipe on as many threads as ours.
        if (all_ran(size_cells)) {
            rl::ResultsTable sizes_table(
                {"scene", "size", "renderer", "ms_per_frame", "ms_min", "ms_max", "times_the_floor",
                 "times_llvmpipe", "times_plain_llvmpipe", "percent_differing_from_llvmpipe"});
            using Key = std::tuple<const Scene*, int, int>;  // scene, size, threads
            const auto key_of = [](const Cell* c) {
                const int threads = c->renderer == "fast" ? (c->options.threads == 1 ? 1 : kThreads)
                                                          : c->peer_threads;
                return Key{c->scene, c->size, threads};
            };
            std::map<std::pair<const Scene*, int>, double> floor_ms;
            std::map<Key, double> peer_ms, plain_ms;
            for (const Cell* c : size_cells) {
                if (c->renderer == "floor") floor_ms[{c->scene, c->size}] = ms(c);
                if (c->renderer == "llvmpipe") peer_ms[key_of(c)] = ms(c);
                if (c->renderer == "llvmpipe plain") plain_ms[key_of(c)] = ms(c);
            }
            std::map<std::pair<const Scene*, int>, double> differing;
            if (peer)
                for (const Scene& s : scenes)
                    for (int size : sizes) {
                        const rl::Image ours = fast_frame(s, size, {}, 0);
                        differing[{&s, size}] =
                            100 *
                            rl::compare_images(ours, *llvmpipe_frame(s, size, {}), 8).share_over;
                    }
            for (const Cell* c : size_cells) {
                const std::pair<const Scene*, int> key{c->scene, c->size};
                const bool ours = c->renderer == "fast";
                const bool same_work = ours && !c->models;  // (not at the plain peer's work)
                sizes_table.add_row({c->scene->name, static_cast<long long>(c->size),
                                     c->name.substr(c->name.rfind('/') + 1), ms(c), ms_min(c),
                                     ms_max(c), ms(c) / floor_ms.at(key),
                                     same_work && peer ? ms(c) / peer_ms.at(key_of(c)) : NAN,
                                     ours && peer ? ms(c) / plain_ms.at(key_of(c)) : NAN,
                                     same_work && peer ? differing.at(key) : NAN});
            }
            sizes_table.write_csv(options.out_dir / "12_sizes.csv");
            written.push_back("12_sizes.csv");
        }
        // 3. The triangle counts.
        if (all_ran(triangle_cells)) {
            rl::ResultsTable triangles_table({"triangles", "renderer", "ms_per_frame", "ms_min",
                                              "ms_max", "million_triangles_per_s",
                                              "percent_of_lanes_used"});
            for (const Cell* c : triangle_cells) {
                const double triangles =
                    static_cast<double>(c->scene->models[0].lit.model.mesh.faces.size());
                // The share of the shader's lanes that shade a pixel, in the cell's view.
                double lanes_used = NAN;
                if (c->renderer == "fast") {
                    fast::Renderer renderer(c->scene->models, c->size, c->size, c->options);
                    const fast::TileCounts tiles = renderer.render(c->scene->camera).tiles;
                    lanes_used = 100.0 * static_cast<double>(tiles.shaded) /
                                 static_cast<double>(std::max<std::uint64_t>(tiles.lanes, 1));
                }
                triangles_table.add_row({static_cast<long long>(triangles),
                                         c->name.substr(c->name.rfind('/') + 1), ms(c), ms_min(c),
                                         ms_max(c), triangles / ms(c) / 1e3, lanes_used});
            }
            triangles_table.write_csv(options.out_dir / "12_triangles.csv");
            written.push_back("12_triangles.csv");
        }
        // 4. Where the time goes: the stage timers, averaged over an orbit
        // after a first frame (the tiles' split is summed over both threads,
        // so it is shown per thread).
        // 5. The pairs.
        if (std::all_of(pairs.begin(), pairs.end(),
                        [](const auto& p) { return !p->ratio.empty(); })) {  // (each ran)
            rl::ResultsTable pairs_table({"scene", "size", "technique", "pairs", "ms_without",
                                          "ms_with", "percent_saved", "saved_q1", "saved_q3",
                                          "levels_apart"});
            for (const auto& p : pairs)
                pairs_table.add_row(
                    {p->scene->name, static_cast<long long>(p->size), p->technique,
                     static_cast<long long>(p->ratio.size()), quantile(p->ms_off, 0.5),
                     quantile(p->ms_on, 0.5), 100 * (1 - quantile(p->ratio, 0.5)),
                     100 * (1 - quantile(p->ratio, 0.75)), 100 * (1 - quantile(p->ratio, 0.25)),
                     static_cast<long long>(p->levels_apart)});
            pairs_table.write_csv(options.out_dir / "12_pairs.csv");
            written.push_back("12_pairs.csv");
        }
        const bool narrowed = written.size() < 4;
        if (narrowed) {  // the stages are timed in full runs only
            if (written.empty())
                throw std::runtime_error("--benchmark_filter left no section of the lab whole");
            std::string list;
            for (const std::string& w : written) list += (list.empty() ? "" : ", ") + w;
            std::printf("wrote %s to %s\n", list.c_str(), options.out_dir.string().c_str());
            return 0;
        }
        rl::ResultsTable stages_table({"scene", "size", "stage", "ms_per_frame"});
        for (const Scene& s : scenes)
            for (int size : std::set<int>{sizes.front(), step_size, sizes.back()}) {
                fast::Renderer renderer(s.models, size, size, {});
                renderer.render(s.camera);
                fast::StageTimes sum;
                double raster = 0, shade = 0, copy = 0;
                for (int f = 0; f < kOrbitFrames; ++f) {
                    const fast::FrameCounts counts =
                        renderer.render(fast::orbit(s.camera, f, kOrbitFrames));
                    const fast::StageTimes& t = renderer.times();
                    sum.vertex += t.vertex, sum.setup += t.setup, sum.binning += t.binning;
                    sum.tiles += t.tiles;
                    raster += static_cast<double>(counts.tiles.raster_ns) / 1e6 / kThreads;
                    shade += static_cast<double>(counts.tiles.shade_ns) / 1e6 / kThreads;
                    copy += static_cast<double>(counts.tiles.copy_ns) / 1e6 / kThreads;
                }
                const auto row = [&](const char* stage, double total) {
                    stages_table.add_row(
                        {s.name, static_cast<long long>(size), stage, total / kOrbitFrames});
                };
                row("vertex stage", sum.vertex);
                row("cull, clip, set-up", sum.setup);
                row("binning", sum.binning);
                row("tiles: clear and visibility pass (per thread)", raster);
                row("tiles: shading (per thread)", shade);
                row("tiles: copy into the frame (per thread)", copy);
                row("tiles, in all (clock)", sum.tiles);
            }
        stages_table.write_csv(options.out_dir / "12_stages.csv");
        std::printf(
            "wrote 12_steps.csv, 12_sizes.csv, 12_triangles.csv, 12_pairs.csv and 12_stages.csv "
            "to %s\n",
            options.out_dir.string().c_str());
        return 0;
    });
}
