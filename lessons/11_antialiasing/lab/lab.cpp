// Lesson 11's lab: every antialiasing method against the truth (256
// samples a pixel, each shaded, box-filtered), on lesson 08's scene at the
// program's default view. Per method, pattern, sample count and resolve:
// the frame's time (median of the runs; lesson 05's pipeline draws on one
// thread), its memory (bytes a pixel of the target), the
// error at depth edges and away from them (shading and textures), and, over
// a slow orbit, the flicker at edges that the truth does not have.
// Writes 11_methods.csv.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "05_perspective/view_options.hpp"
#include "11_antialiasing/truths/aa_truth.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"

namespace {

using namespace antialiasing;

struct Setup {
    const std::vector<normal_mapping::MappedModel>* models;
    const pipeline::Camera* camera;
    const shadows::ShadowOptions* shadow;
    int size;
};

// The line a case belongs to on the chart: everything but its sample count.
std::string variant(const AaOptions& o) {
    if (samples_of(o) == 1) return name(o.method);
    std::string v = std::string(name(o.method)) + ", " + name(o.pattern);
    if (o.resolve != Resolve::box) v += ", " + std::string(name(o.resolve));
    if (o.method == Method::msaa && o.shade_at != ShadeAt::centre)
        v += ", " + std::string(name(o.shade_at));
    if (o.tone != ToneOrder::none) v += ", +3 stops, tone map " + std::string(name(o.tone));
    return v;
}

std::string label(const AaOptions& o) {
    if (o.tone != ToneOrder::none) return variant(o) + " " + std::to_string(o.samples);
    if (samples_of(o) == 1) return name(o.method);
    return std::string(name(o.method)) + " " + std::to_string(o.samples) + " " + name(o.pattern) +
           " " + name(o.resolve) +
           (o.method == Method::msaa ? std::string(" ") + name(o.shade_at) : std::string());
}

void time_frame(benchmark::State& state, const Setup* s, const AaOptions* o) {
    for (auto _ : state) {
        const Frame f = render(*s->models, *s->camera, *s->shadow, *o, s->size, s->size);
        benchmark::DoNotOptimize(f.picture.get(0, 0));
    }
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options = rl::lab::init(
        argc, argv, "Lesson 11 lab: antialiasing methods against a 256-sample truth.");
    return rl::guarded_main("11_antialiasing_lab", [&] {
        std::vector<std::string> warnings;
        std::vector<normal_mapping::MappedModel> models = shadows::default_scene(warnings);
        normal_mapping::build_mip_levels(models);
        const int size = options.quick ? 96 : 800;
        const int motion_size = options.quick ? 64 : 400;
        const int truth_side = options.quick ? 4 : 16;
        const pipeline::ViewOptions view;  // the program's default view, framed
        const pipeline::Camera camera =
            pipeline::resolve_camera(view, shadows::scene_box(models), 1);
        shadows::ShadowOptions shadow;
        shadows::set_lights(shadow, view, false);
        const Setup setup{&models, &camera, &shadow, size};

        std::vector<AaOptions> cases = {{.method = Method::none, .samples = 1}};
        const auto add = [&](Method m, int n, Pattern p, Resolve r = Resolve::box,
                             ShadeAt at = ShadeAt::centre) {
            cases.push_back({m, n, p, r, at});
        };
        add(Method::ssaa, 4, Pattern::grid);
        add(Method::ssaa, 4, Pattern::rotated);
        add(Method::ssaa, 16, Pattern::grid);
        add(Method::ssaa, 16, Pattern::standard);
        for (int n : {2, 4, 8, 16}) add(Method::msaa, n, Pattern::standard);
        add(Method::msaa, 4, Pattern::standard, Resolve::box, ShadeAt::centroid);
        add(Method::msaa, 4, Pattern::standard, Resolve::tent);
        add(Method::msaa, 8, Pattern::standard, Resolve::tent);
        cases.push_back({.method = Method::post, .samples = 1});
        // HDR: 3 stops brighter, lesson 09's tone map after the resolve or
        // on each sample before it, each scored against the truth of its order.
        for (ToneOrder order : {ToneOrder::after_resolve, ToneOrder::before_resolve})
            for (const auto& [m, n, p] : {std::tuple{Method::msaa, 4, Pattern::standard},
                                          std::tuple{Method::ssaa, 16, Pattern::grid}}) {
                AaOptions o{m, n, p, Resolve::box, ShadeAt::centroid, order, 3};
                cases.push_back(o);
            }
        if (options.quick) cases = {cases[0], cases[1], cases[6], cases[12], cases[13]};

        for (const AaOptions& o : cases)
            benchmark::RegisterBenchmark(("frame/" + label(o)).c_str(), time_frame, &setup, &o)
                ->Unit(benchmark::kMillisecond);
        const auto timings = rl::lab::run_benchmarks();

        // The truths, still and moving, one per tone order (the method is
        // scored against the truth of its own order): found when first asked.
        const int frames = options.quick ? 2 : 6;  // of the orbit, a quarter degree apart
        std::map<ToneOrder, rl::Grid<rl::vec3>> truths;
        std::map<ToneOrder, std::vector<rl::Grid<rl::vec3>>> moving_truths;
        const auto truth_for = [&](const AaOptions& o) -> const rl::Grid<rl::vec3>& {
            if (!truths.count(o.tone)) {
                const auto start = std::chrono::steady_clock::now();
                truths.emplace(o.tone,
                               truth_light(models, camera, shadow, size, size, truth_side, o));
                const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
                std::printf("truth (tone map %s): %d samples a pixel at %dx%d in %.1f s\n",
                            name(o.tone), truth_side * truth_side, size, size, took.count());
                for (int k = 0; k < frames; ++k)
                    moving_truths[o.tone].push_back(truth_light(models, orbit(camera, 0.25 * k),
                                                                shadow, motion_size, motion_size,
                                                                options.quick ? 4 : 8, o));
            }
            return truths.at(o.tone);
        };
        const rl::Grid<std::uint8_t> edges = depth_edges(models, camera, shadow, size, size);
        std::vector<rl::Grid<std::uint8_t>> moving_edges;
        for (int k = 0; k < frames; ++k)
            moving_edges.push_back(
                depth_edges(models, orbit(camera, 0.25 * k), shadow, motion_size, motion_size));

        rl::ResultsTable table({"variant", "method", "samples", "pattern", "resolve", "shade_at",
                                "tone_map", "ms_per_frame", "ms_min", "ms_max", "bytes_per_pixel",
                                "edge_error", "shading_error", "p95_error", "flicker",
                                "edge_pixels"});
        for (const AaOptions& o : cases) {
            const Frame f = render(models, camera, shadow, o, size, size);
            const AaError e = compare(truth_for(o), f.light, edges);
            const std::vector<rl::Grid<rl::vec3>>& truths_moving = moving_truths.at(o.tone);
            double moving = 0;
            rl::Grid<rl::vec3> before;
            for (int k = 0; k < frames; ++k) {
                const Frame m =
                    render(models, orbit(camera, 0.25 * k), shadow, o, motion_size, motion_size);
                if (k > 0)
                    moving += flicker(truths_moving[static_cast<std::size_t>(k - 1)],
                                      truths_moving[static_cast<std::size_t>(k)], before, m.light,
                                      moving_edges[static_cast<std::size_t>(k - 1)],
                                      moving_edges[static_cast<std::size_t>(k)]);
                before = m.light;
            }
            const rl::lab::Timing& t = timings.at("frame/" + label(o));
            const int n = samples_of(o);
            table.add_row({variant(o), std::string(name(o.method)), static_cast<long long>(n),
                           std::string(n == 1 ? "centre" : name(o.pattern)),
                           std::string(name(o.resolve)),
                           std::string(o.method == Method::msaa ? name(o.shade_at) : "sample"),
                           std::string(name(o.tone)), t.median_ns / 1e6, t.min_ns / 1e6,
                           t.max_ns / 1e6, static_cast<long long>(16 * n), e.edges, e.shading,
                           e.p95, moving / (frames - 1), static_cast<long long>(e.edge_pixels)});
        }
        table.write_csv(options.out_dir / "11_methods.csv");
        std::printf("wrote 11_methods.csv to %s\n", options.out_dir.string().c_str());
        return 0;
    });
}
