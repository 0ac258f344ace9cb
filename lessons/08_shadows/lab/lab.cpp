// Lesson 08's lab: shadow maps against ray-cast visibility. On the default
// scene at the program's default view, every shadow setting is scored at
// every pixel against the truth of visibility_truth.hpp (a ray in double
// from the visible point to the light, through a BVH of the scene): the
// share of pixels wrongly lit (peter-panning, light leaking) and wrongly
// shadowed (acne), and the time of a whole frame, both passes. Sweeps:
//   1. bias: slope-scaled, constant and normal offset, each alone, hard test;
//   2. the map's size, with the defaults, and its memory;
//   3. the filters; the fit (scene or view); front or back faces in the map;
//      the spot light; and tinyrenderer's way, an 8000 x 8000 map with a
//      constant bias only;
//   4. the fit again, at the default view and at a close one whose shadow
//      comes from a caster outside the view.
// Writes 08_bias.csv, 08_resolution.csv, 08_filters.csv and 08_fit.csv.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "05_perspective/view_options.hpp"
#include "08_shadows/truths/visibility_truth.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"

namespace {

using namespace shadows;

struct Setup {
    std::vector<normal_mapping::MappedModel> models;
    pipeline::Camera camera;
    int size = 800;
};

struct Case {
    std::string group, label;
    double value = 0;  // the swept setting (a bias, a map size), for the charts
    ShadowOptions options;
};

// Both passes, as the program runs them, into a frame the caller keeps.
void draw_frame(const Setup& s, const ShadowOptions& o, pipeline::ColourTarget& frame) {
    frame.clear(rl::kBackground);
    const ShadowMap map = shadow_map_for(s.models, s.camera, 1, o);
    render(s.models, s.camera, o, map, frame);
}

void time_frame(benchmark::State& state, const Setup* s, const Case* c) {
    pipeline::ColourTarget frame = pipeline::colour_target(s->size, s->size);
    for (auto _ : state) {
        draw_frame(*s, c->options, frame);
        benchmark::DoNotOptimize(frame.colour().get(0, 0));
    }
}

ShadowOptions hard_without_bias(const ShadowOptions& base, int map_size) {
    ShadowOptions o = base;
    o.map.size = map_size;
    o.map.slope_bias = 0;
    o.map.constant_bias = 0;
    o.lookup.normal_offset = 0;
    o.lookup.filter = ShadowFilter::hard;
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options =
        rl::lab::init(argc, argv, "Lesson 08 lab: shadow maps against ray-cast visibility.");
    return rl::guarded_main("08_shadows_lab", [&] {
        std::vector<std::string> warnings;
        Setup setup;
        setup.models = default_scene(warnings);
        normal_mapping::build_mip_levels(setup.models);
        setup.size = options.quick ? 96 : 800;
        const pipeline::ViewOptions view;  // the program's default view, framed
        setup.camera = pipeline::resolve_camera(view, scene_box(setup.models), 1);
        ShadowOptions base;
        base.light.direction = rl::normalize(rl::vec3{1.0f, 0.6f, 0.6f});  // the program's default
        base.render.lighting = shading::default_lighting(base.light.direction);
        // Quick mode's maps are small too (CI runs it under the sanitizers,
        // where a 2048^2 map costs about a second a case).
        if (options.quick) base.map.size = 256;
        const int bias_map = options.quick ? 128 : 2048;

        std::vector<Case> cases;
        // 1. Each bias alone, on the hard test.
        cases.push_back({"none", "no bias", 0, hard_without_bias(base, bias_map)});
        for (double b : {0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0}) {
            Case c{"slope", "slope bias", b, hard_without_bias(base, bias_map)};
            c.options.map.slope_bias = static_cast<float>(b);
            cases.push_back(c);
        }
        for (double b : {1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1}) {
            Case c{"constant", "constant bias", b, hard_without_bias(base, bias_map)};
            c.options.map.constant_bias = static_cast<float>(b);
            cases.push_back(c);
        }
        for (double b : {0.25, 0.5, 1.0, 2.0, 4.0, 8.0}) {
            Case c{"normal-offset", "normal offset", b, hard_without_bias(base, bias_map)};
            c.options.lookup.normal_offset = static_cast<float>(b);
            cases.push_back(c);
        }
        const std::size_t bias_cases = cases.size();
        // 2. The map's size, with the default bias and filter.
        const std::vector<int> sizes =
            options.quick ? std::vector<int>{32, 64, 128, 256}
                          : std::vector<int>{128, 256, 512, 1024, 2048, 4096, 8192};
        for (int n : sizes) {
            Case c{"resolution", "map " + std::to_string(n), static_cast<double>(n), base};
            c.options.map.size = n;
            cases.push_back(c);
        }
        const std::size_t resolution_cases = cases.size();
        // 3. Filters, fits, faces, the spot light, and tinyrenderer's way.
        for (ShadowFilter f : kShadowFilters) {
            Case c{"filter", name(f), 0, base};
            c.options.lookup.filter = f;
            cases.push_back(c);
        }
        {
            Case scene_fit{"setup", "fit to the whole scene", 0, base};
            scene_fit.options.fit = Fit::scene;
            cases.push_back(scene_fit);
            Case back{"setup", "back faces in the map (no bias)", 0,
                      hard_without_bias(base, base.map.size)};
            back.options.map.cull = pipeline::Cull::front;
            cases.push_back(back);
            Case spot{"setup", "spot light", 0, base};
            spot.options.light.type = LightType::spot;
            spot.options.light.position =
                default_spot_position(scene_box(setup.models), base.light.direction);
            cases.push_back(spot);
            for (const char* b : {"1e-4", "1e-3", "3e-3", "1e-2"}) {
                Case t{"setup", std::string("tinyrenderer's way: 8000^2, constant bias ") + b,
                       std::stod(b), hard_without_bias(base, options.quick ? 512 : 8000)};
                t.options.map.constant_bias = static_cast<float>(t.value);
                t.options.fit = Fit::scene;
                cases.push_back(t);
            }
        }
        const auto bench_name = [](const Case& c) {
            return "frame/" + c.group + "/" + c.label + "/" + std::to_string(c.value);
        };
        for (const Case& c : cases)
            benchmark::RegisterBenchmark(bench_name(c).c_str(), time_frame, &setup, &c)
                ->Unit(benchmark::kMillisecond);
        const auto timings = rl::lab::run_benchmarks();

        // The truth, once per light.
        const SceneRays rays(setup.models);
        std::map<int, TruthFrame> truths;  // by light type
        rl::ResultsTable bias({"bias", "value", "wrongly_lit_percent", "wrongly_shadowed_percent",
                               "mean_error", "ms_per_frame"});
        rl::ResultsTable resolution({"map_size", "map_mib", "ms_per_frame", "ms_min", "ms_max",
                                     "wrongly_lit_percent", "wrongly_shadowed_percent",
                                     "wrong_percent", "mean_error"});
        rl::ResultsTable filters({"method", "map_size", "ms_per_frame", "ms_min", "ms_max",
                                  "wrongly_lit_percent", "wrongly_shadowed_percent",
                                  "wrong_percent", "mean_error", "sun_error", "scored_pixels"});
        // The soft truth: the directional light as a disc the sun's size (0.27 degrees in radius).
        std::optional<rl::FloatImage> sun;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const Case& c = cases[i];
            const ShadowMap map = shadow_map_for(setup.models, setup.camera, 1, c.options);
            const int key = static_cast<int>(c.options.light.type);
            if (!truths.count(key))
                truths.emplace(key, rays.truth(setup.camera, setup.size, setup.size, map.light,
                                               c.options.light.cone_degrees));
            const ShadowError e =
                compare(truths.at(key),
                        probe(setup.models, setup.camera, setup.size, setup.size, c.options, map));
            const rl::lab::Timing& t = timings.at(bench_name(c));
            const double ms = t.median_ns / 1e6;
            if (i < bias_cases) {
                bias.add_row({c.group, c.value, 100 * e.wrongly_lit, 100 * e.wrongly_shadowed,
                              e.mean_error, ms});
            } else if (i < resolution_cases) {
                const double n = c.value;
                resolution.add_row({static_cast<long long>(n), n * n * 4 / (1 << 20), ms,
                                    t.min_ns / 1e6, t.max_ns / 1e6, 100 * e.wrongly_lit,
                                    100 * e.wrongly_shadowed, 100 * e.wrong(), e.mean_error});
            } else {
                const bool directional = c.options.light.type == LightType::directional;
                if (directional && !sun)
                    sun = rays.soft(truths.at(key), setup.camera, map.light, 0.27);
                const ProbeFrame answers =
                    probe(setup.models, setup.camera, setup.size, setup.size, c.options, map);
                filters.add_row({c.label, static_cast<long long>(c.options.map.size), ms,
                                 t.min_ns / 1e6, t.max_ns / 1e6, 100 * e.wrongly_lit,
                                 100 * e.wrongly_shadowed, 100 * e.wrong(), e.mean_error,
                                 directional ? soft_error(truths.at(key), *sun, answers) : NAN,
                                 static_cast<long long>(e.scored)});
            }
        }
        // 4. The fit at the program's view and at a close one: the camera low
        // over the floor, looking away from the crate into its shadow. The
        // crate is outside the view, yet between the light and most of what
        // the view holds: the view's map must still hold it.
        rl::ResultsTable fits({"view", "fit", "texel_size", "wrongly_lit_percent",
                               "wrongly_shadowed_percent", "wrong_percent", "scored_pixels"});
        pipeline::ViewOptions close_view;
        close_view.eye = {0.2f, 0.25f, -0.35f};
        close_view.target = {-1.0f, 0.05f, -0.9f};
        const std::pair<const char*, pipeline::Camera> views[] = {
            {"the program's default", setup.camera},
            {"close to the floor, the crate behind the eye",
             pipeline::resolve_camera(close_view, scene_box(setup.models), 1)}};
        for (const auto& [view_name, camera] : views) {
            std::optional<TruthFrame> truth;
            for (Fit fit : kFits) {
                ShadowOptions o = base;
                o.fit = fit;
                const ShadowMap map = shadow_map_for(setup.models, camera, 1, o);
                if (!truth) truth = rays.truth(camera, setup.size, setup.size, map.light);
                const ShadowError e =
                    compare(*truth, probe(setup.models, camera, setup.size, setup.size, o, map));
                fits.add_row({std::string(view_name), std::string(name(fit)),
                              map.light.width / static_cast<double>(map.size()),
                              100 * e.wrongly_lit, 100 * e.wrongly_shadowed, 100 * e.wrong(),
                              static_cast<long long>(e.scored)});
            }
        }
        fits.write_csv(options.out_dir / "08_fit.csv");
        bias.write_csv(options.out_dir / "08_bias.csv");
        resolution.write_csv(options.out_dir / "08_resolution.csv");
        filters.write_csv(options.out_dir / "08_filters.csv");
        std::printf("wrote 08_bias.csv, 08_resolution.csv, 08_filters.csv and 08_fit.csv to %s\n",
                    options.out_dir.string().c_str());
        return 0;
    });
}
