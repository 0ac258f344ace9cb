// Lesson 10's lab: screen-space ambient occlusion against ray-traced
// occlusion. On lesson 08's scene at the program's default view, the
// G-buffer is drawn once; each method, sample count, radius and blur then
// computes the occlusion from it, timed (the AO pass alone: the depth
// buffer's points, the method, the blur) and scored at every pixel against
// ao_truth.hpp's rays: the mean and 95th percentile of the error away from
// depth edges, and the mean near them (halos). Sweeps:
//   1. every method at 4 to 128 samples, with the default blur and without;
//   2. the radius, for the default method and samples (each radius its own truth);
//   3. the same kernel at every pixel (no rotation);
//   4. baked per vertex, 16 to 1024 rays a vertex (the frame draws it; the
//      bake is timed once, apart);
//   5. the anchor: tinyrenderer's SSAO as its lesson runs it (128 random
//      points a pixel, no blur), ported in tinyrenderer_ssao.hpp;
// and the G-buffer pass itself. Writes 10_methods.csv, 10_radius.csv and
// 10_passes.csv.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <string>

#include "05_perspective/view_options.hpp"
#include "10_ambient_occlusion/truths/ao_truth.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"
#include "tinyrenderer_ssao.hpp"

namespace {

using namespace occlusion;

struct Setup {
    const GBuffer* g = nullptr;
    const Screen* screen = nullptr;
    // For the baked method: what draw_baked needs, and the bakes by rays a vertex.
    const std::vector<normal_mapping::MappedModel>* models = nullptr;
    const pipeline::Camera* camera = nullptr;
    const shadows::ShadowOptions* shadow = nullptr;
    const shadows::ShadowMap* map = nullptr;
    std::map<int, BakedAo> bakes;
};

struct Case {
    std::string group;
    AoOptions ao;
    bool tinyrenderer = false;  // the anchor's port instead of ao's method
};

// The case's occlusion from the setup's G-buffer (or, baked, its draw).
rl::FloatImage occlusion_of(const Setup& s, const Case& c) {
    if (c.tinyrenderer) return tinyrenderer_ssao(Surfaces(*s.g, *s.screen), c.ao.samples);
    if (c.ao.method != AoMethod::baked) return ambient_occlusion(*s.g, *s.screen, c.ao);
    return draw_baked(*s.models, *s.camera, *s.shadow, *s.map, s.bakes.at(c.ao.samples),
                      s.g->width(), s.g->height());
}

std::string method_name(const Case& c) {
    return c.tinyrenderer ? "tinyrenderer" : name(c.ao.method);
}

std::string label(const Case& c) {
    const AoOptions& o = c.ao;
    return method_name(c) + ", " + std::to_string(o.samples) + " samples" +
           (o.blur > 0 ? ", blur " + std::to_string(o.blur) : ", no blur") +
           (o.rotate ? "" : ", no rotation");
}

void time_gbuffer(benchmark::State& state, const Setup* s) {
    for (auto _ : state) {
        const GBuffer g = render_gbuffer(*s->models, *s->camera, *s->shadow, *s->map, s->g->width(),
                                         s->g->height());
        benchmark::DoNotOptimize(g.depth()->get(0, 0));
    }
}

void time_ao(benchmark::State& state, const Setup* s, const Case* c) {
    for (auto _ : state) {
        const rl::FloatImage ao = occlusion_of(*s, *c);
        benchmark::DoNotOptimize(ao.get(0, 0));
    }
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options = rl::lab::init(
        argc, argv, "Lesson 10 lab: screen-space ambient occlusion against ray-traced occlusion.");
    return rl::guarded_main("10_ambient_occlusion_lab", [&] {
        std::vector<std::string> warnings;
        std::vector<normal_mapping::MappedModel> models = shadows::default_scene(warnings);
        normal_mapping::build_mip_levels(models);
        const int size = options.quick ? 96 : 800;
        const int truth_rays = options.quick ? 64 : 1024;
        const pipeline::ViewOptions view;  // the program's default view, framed
        const pipeline::Camera camera =
            pipeline::resolve_camera(view, shadows::scene_box(models), 1);
        SceneOptions scene;
        shadows::set_lights(scene.shadow, view, false);
        const shadows::ShadowMap map = shadows::shadow_map_for(models, camera, 1, scene.shadow);
        const GBuffer g = render_gbuffer(models, camera, scene.shadow, map, size, size);
        const Screen screen(camera, size, size);
        Setup setup{&g, &screen, &models, &camera, &scene.shadow, &map, {}};
        const RayTracedAo rays(models);

        std::vector<Case> cases;
        const AoOptions base;
        const std::vector<int> counts =
            options.quick ? std::vector<int>{8, 16} : std::vector<int>{4, 8, 16, 32, 64, 128};
        for (AoMethod m : {AoMethod::crytek, AoMethod::hemisphere, AoMethod::horizon})
            for (int n : counts)
                for (int blur : {0, base.blur}) {
                    AoOptions o = base;
                    o.method = m, o.samples = n, o.blur = blur;
                    cases.push_back({"methods", o});
                }
        // Baked: `samples` rays a vertex, baked once before the timing.
        std::map<int, double> bake_ms;
        for (int n : options.quick ? std::vector<int>{16} : std::vector<int>{16, 64, 256, 1024}) {
            const auto start = std::chrono::steady_clock::now();
            setup.bakes.emplace(n, bake_vertex_ao(models, rays, base.radius, n));
            bake_ms[n] =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            AoOptions o = base;
            o.method = AoMethod::baked, o.samples = n, o.blur = 0;
            cases.push_back({"methods", o});
        }
        const std::size_t method_cases = cases.size();
        for (float r : {0.125f, 0.25f, 0.5f, 1.0f, 2.0f}) {
            AoOptions o = base;
            o.radius = r;
            cases.push_back({"radius", o});
        }
        {
            AoOptions o = base;
            o.rotate = false;
            cases.push_back({"methods", o});
        }
        {
            AoOptions o = base;
            o.samples = kTinyrendererSamples, o.blur = 0;  // fresh points at every pixel
            cases.push_back({"methods", o, true});
        }
        const auto bench_name = [](const Case& c) {
            return "ao/" + c.group + "/" + label(c) + "/r" + std::to_string(c.ao.radius);
        };
        benchmark::RegisterBenchmark("gbuffer", time_gbuffer, &setup)
            ->Unit(benchmark::kMillisecond);
        for (const Case& c : cases)
            benchmark::RegisterBenchmark(bench_name(c).c_str(), time_ao, &setup, &c)
                ->Unit(benchmark::kMillisecond);
        const auto timings = rl::lab::run_benchmarks();

        std::map<float, TruthFrame> truths;  // by radius
        const auto truth_for = [&](float radius) -> const TruthFrame& {
            if (!truths.count(radius)) {
                const auto start = std::chrono::steady_clock::now();
                truths.emplace(radius, truth_frame(rays, camera, size, size, radius, truth_rays));
                const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
                std::printf("truth at radius %g: %d rays a pixel in %.1f s\n",
                            static_cast<double>(radius), truth_rays, took.count());
            }
            return truths.at(radius);
        };
        const std::vector<std::string> columns = {
            "method", "samples",    "blur",      "rotate",     "radius", "ms_per_frame", "ms_min",
            "ms_max", "mean_error", "p95_error", "edge_error", "pixels", "edge_pixels",  "bake_ms"};
        rl::ResultsTable methods(columns), radius(columns);
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const Case& c = cases[i];
            const rl::FloatImage ao = occlusion_of(setup, c);
            const AoError e = compare(truth_for(c.ao.radius), ao, g, screen, c.ao.radius);
            const rl::lab::Timing& t = timings.at(bench_name(c));
            (i < method_cases || c.group == "methods" ? methods : radius)
                .add_row({method_name(c), static_cast<long long>(c.ao.samples),
                          static_cast<long long>(c.ao.blur),
                          std::string(c.ao.rotate ? "yes" : "no"), static_cast<double>(c.ao.radius),
                          t.median_ns / 1e6, t.min_ns / 1e6, t.max_ns / 1e6, e.mean, e.p95,
                          e.edge_mean, static_cast<long long>(e.pixels),
                          static_cast<long long>(e.edge_pixels),
                          c.ao.method == AoMethod::baked ? bake_ms.at(c.ao.samples) : 0.0});
        }
        rl::ResultsTable passes({"pass", "ms_per_frame", "ms_min", "ms_max"});
        const rl::lab::Timing& t = timings.at("gbuffer");
        passes.add_row({std::string("gbuffer"), t.median_ns / 1e6, t.min_ns / 1e6, t.max_ns / 1e6});
        methods.write_csv(options.out_dir / "10_methods.csv");
        radius.write_csv(options.out_dir / "10_radius.csv");
        passes.write_csv(options.out_dir / "10_passes.csv");
        std::printf("wrote 10_methods.csv, 10_radius.csv and 10_passes.csv to %s\n",
                    options.out_dir.string().c_str());
        return 0;
    });
}
