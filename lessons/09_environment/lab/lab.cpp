// Lesson 09's lab: the sky behind the scene read from a cube map or a
// lat-long map, by each filter, at map sizes from 16 to 1024 texels, in
// three views (the program's, one into a cube edge, one straight up at the
// pole), against the analytic sky averaged over each pixel; and the time
// the sky pass takes per frame. Writes 09_maps.csv. Then diffuse light: the
// irradiance by spherical harmonics, the convolved map and Monte Carlo at
// 4 to 4096 rays, against the sky's irradiance by quadrature, over normals
// spread evenly on the sphere, with the time per normal and to prepare.
// Writes 09_irradiance.csv. Then glossy light: one bounce off a white
// metal at five roughnesses, by the split sum with blurred maps of 3, 6 or
// 11 levels, 32 to 128 texels and 16 to 256 samples, and by Monte Carlo
// with 16 to 1024 rays, against the integral over the analytic sky, for
// normals spread over the sphere seen head-on, at 45 and at 75 degrees;
// with the time per pixel, to build and the memory. Writes 09_glossy.csv
// (each method and roughness) and 09_prefilter.csv (each blurred-map
// setting, all roughnesses together). The lab's sky has a
// plain ground: the checker's squares shrink without bound towards the
// horizon, so no map and no pixel's 16 rays hold them, and the score would
// measure that aliasing instead of the maps.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>

#include "09_environment/brdf.hpp"
#include "09_environment/environment_shader.hpp"
#include "09_environment/glossy_map.hpp"
#include "09_environment/irradiance.hpp"
#include "09_environment/sphere_sampling.hpp"
#include "09_environment/truths/glossy_truth.hpp"
#include "09_environment/truths/irradiance_truth.hpp"
#include "09_environment/truths/sky_truth.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"
#include "rasterlab/workers.hpp"

namespace {

using namespace environment;

rl::dvec3 lab_sky(rl::dvec3 direction) {
    static const Sky sky = [] {
        Sky s = default_sky();
        s.checker = 0;
        return s;
    }();
    return radiance(sky, direction);
}

struct View {
    const char* name;
    pipeline::Camera camera;
};

std::vector<View> views() {
    pipeline::Camera horizon;  // the program's default view
    horizon.eye = {0.3f, 0.35f, 3.8f};
    horizon.target = {0, 0, 0};
    pipeline::Camera edge;  // along the edge between the -x and -z faces
    edge.eye = {0, 0, 0};
    edge.target = {-1, 0.15f, -1};
    edge.fov_y = 60;
    pipeline::Camera zenith;  // straight up: the lat-long map's pole
    zenith.eye = {0, 0, 0};
    zenith.target = {0, 1, 0};
    zenith.up = {0, 0, -1};
    zenith.fov_y = 90;
    return {{"horizon", horizon}, {"cube edge", edge}, {"zenith", zenith}};
}

struct Method {
    Layout layout;
    MapFilter filter;
    std::string name() const {
        return std::string(environment::name(layout)) + ", " + environment::name(filter);
    }
};

std::vector<Method> methods() {
    std::vector<Method> out;
    for (Layout layout : kLayouts)
        for (MapFilter filter : kMapFilters)
            if (!(layout == Layout::latlong && filter == MapFilter::seamless))  // = bilinear there
                out.push_back({layout, filter});
    return out;
}

// The sky pass alone into a frame the models left empty.
rl::Image sky_picture(const Environment& env, const pipeline::Camera& camera, int size) {
    LightTarget frame = light_target(size, size);
    draw_skybox(env, camera, frame);
    return tone_mapped(frame.colour(), {});
}

void sky_pass(benchmark::State& state, const Environment* env, pipeline::Camera camera, int size) {
    LightTarget frame = light_target(size, size);
    for (auto _ : state) {
        draw_skybox(*env, camera, frame);
        benchmark::DoNotOptimize(frame.colour().pixels().data());
    }
    state.SetItemsProcessed(state.iterations() * size * size);
}

// n directions spread evenly over the sphere (a Fibonacci spiral).
std::vector<rl::vec3> spread_normals(int n) {
    std::vector<rl::vec3> out;
    const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double y = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - y * y);
        out.push_back(
            rl::cast<float>(rl::dvec3{r * std::cos(golden * i), y, r * std::sin(golden * i)}));
    }
    return out;
}

struct IrradianceCase {
    std::string name;
    std::shared_ptr<DiffuseLight> light;
    double prepare_ms;
};

void evaluate(benchmark::State& state, const DiffuseLight* light,
              const std::vector<rl::vec3>* normals) {
    for (auto _ : state)
        for (std::size_t i = 0; i < normals->size(); ++i)
            benchmark::DoNotOptimize(light->at((*normals)[i], static_cast<std::uint32_t>(i)));
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(normals->size()));
}

// A surface point for glossy light: its normal, the direction to the eye.
struct Facing {
    rl::vec3 n, v;
};

// Each normal seen head-on, at 45 and at 75 degrees from it.
std::vector<Facing> facings(const std::vector<rl::vec3>& normals) {
    std::vector<Facing> out;
    for (rl::vec3 n : normals) {
        const Frame frame(rl::cast<double>(n));
        for (double degrees : {0.0, 45.0, 75.0}) {
            const double a = degrees * std::numbers::pi / 180;
            out.push_back({n, rl::cast<float>(frame.n * std::cos(a) + frame.t * std::sin(a))});
        }
    }
    return out;
}

// One way of finding a white metal's one bounce at a point.
struct GlossyCase {
    std::string name;
    int levels = 0, size = 0, samples = 0;  // blurred maps (0: Monte Carlo)
    int rays = 0;                           // Monte Carlo
    bool by_roughness = true;  // in 09_glossy.csv (every setting is in 09_prefilter.csv)
    Lookup lookup = Lookup::dominant;
    std::shared_ptr<GlossyMap> map;
    double build_ms = 0;
};

rl::vec3 one_bounce(const GlossyCase& c, const Environment& env, const Facing& p, float roughness,
                    std::uint32_t seed) {
    if (c.rays > 0) return glossy_monte_carlo(env, p.n, p.v, roughness, {1, 1, 1}, c.rays, seed);
    const float n_dot_v = std::max(rl::dot(p.n, p.v), 1e-4f);
    const auto albedo = static_cast<float>(split_sum_table().at(n_dot_v, roughness).albedo());
    const rl::vec3 r = reflect(-p.v, p.n);
    return c.map->sample(c.lookup == Lookup::dominant ? dominant_direction(p.n, r, roughness) : r,
                         roughness) *
           albedo;
}

void evaluate_glossy(benchmark::State& state, const GlossyCase* c, const Environment* env,
                     const std::vector<Facing>* points, float roughness) {
    for (auto _ : state)
        for (std::size_t i = 0; i < points->size(); ++i)
            benchmark::DoNotOptimize(
                one_bounce(*c, *env, (*points)[i], roughness, static_cast<std::uint32_t>(i)));
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(points->size()));
}

// The mistake the white furnace catches: the BRDF without its masking
// term (G = 1), integrated over a grid of the hemisphere (F = 1).
double albedo_without_masking(double n_dot_v, double roughness) {
    const rl::dvec3 v{std::sqrt(1 - n_dot_v * n_dot_v), 0, n_dot_v};  // n = +z
    const double alpha = ggx_alpha(roughness);
    const int rings = 600, spokes = 600;
    double sum = 0;
    for (int i = 0; i < rings; ++i) {
        const double mu = (i + 0.5) / rings, s = std::sqrt(1 - mu * mu);
        for (int j = 0; j < spokes; ++j) {
            const double phi = 2 * std::numbers::pi * (j + 0.5) / spokes;
            const rl::dvec3 l{s * std::cos(phi), s * std::sin(phi), mu};
            const rl::dvec3 h = rl::normalize(v + l);
            sum += ggx_distribution(h.z, alpha) / (4 * n_dot_v);  // D / (4 n.l n.v) times n.l
        }
    }
    return sum * 2 * std::numbers::pi / (rings * spokes);
}

}  // namespace

int main(int argc, char** argv) {
    return rl::guarded_main("09_environment_lab", [&] {
        const rl::lab::Options options = rl::lab::init(
            argc, argv,
            "Lesson 09 lab: cube and lat-long maps, filters and sizes, against the analytic sky.");
        const int image = options.quick ? 96 : 800;
        const std::vector<int> sizes = options.quick
                                           ? std::vector<int>{16, 64}
                                           : std::vector<int>{16, 32, 64, 128, 256, 512, 1024};
        const std::vector<View> all_views = views();
        std::vector<rl::Image> truths;
        for (const View& v : all_views)
            truths.push_back(tone_mapped(sky_truth(lab_sky, v.camera, image, image, 4), {}));
        struct Row {
            Method method;
            int size;
            std::shared_ptr<Environment> env;
        };
        std::vector<Row> rows;
        std::map<std::string, std::shared_ptr<Environment>> maps;  // one map per layout and size
        for (int size : sizes)
            for (const Method& m : methods()) {
                const std::string key = std::string(name(m.layout)) + std::to_string(size);
                if (!maps.count(key)) {
                    const int samples = texel_samples(size);
                    maps[key] = m.layout == Layout::cube
                                    ? std::make_shared<Environment>(
                                          cube_map(lab_sky, size, samples), m.filter)
                                    : std::make_shared<Environment>(
                                          latlong_map(lab_sky, size, samples), m.filter);
                }
                const Environment& base = *maps[key];
                auto env = base.cube() ? std::make_shared<Environment>(*base.cube(), m.filter)
                                       : std::make_shared<Environment>(*base.latlong(), m.filter);
                rows.push_back({m, size, env});
                const std::string bench = m.name() + "/" + std::to_string(size);
                benchmark::RegisterBenchmark(bench.c_str(), sky_pass, env.get(),
                                             all_views[0].camera, image)
                    ->Unit(benchmark::kMillisecond);
            }
        // Diffuse light: the program's default environment (the sky as a 512
        // cube map), and the exact irradiance of the analytic sky.
        std::vector<std::string> warnings;
        const Environment sky = make_environment({.size = options.quick ? 64 : 512}, warnings);
        const auto sampled = [&sky](rl::vec3 d) { return sky.sample(d); };
        const std::vector<rl::vec3> normals = spread_normals(options.quick ? 8 : 64);
        std::vector<rl::dvec3> exact;
        for (rl::vec3 n : normals)
            exact.push_back(exact_irradiance([](rl::dvec3 d) { return radiance(Analytic::sky, d); },
                                             rl::cast<double>(n), options.quick ? 64 : 384));
        std::vector<IrradianceCase> cases;
        auto add_case = [&](const std::string& label, Irradiance method, int samples) {
            const auto start = std::chrono::steady_clock::now();
            auto light = std::make_shared<DiffuseLight>(sampled, method, samples);
            const std::chrono::duration<double, std::milli> ms =
                std::chrono::steady_clock::now() - start;
            cases.push_back({label, light, ms.count()});
            benchmark::RegisterBenchmark(("irradiance/" + label).c_str(), evaluate, light.get(),
                                         &normals)
                ->Unit(benchmark::kMicrosecond);
        };
        for (Irradiance method :
             {Irradiance::sh1, Irradiance::sh2, Irradiance::sh3, Irradiance::convolved})
            add_case(name(method), method, 1);
        for (int samples :
             options.quick ? std::vector<int>{4, 64} : std::vector<int>{4, 16, 64, 256, 1024, 4096})
            add_case("monte-carlo, " + std::to_string(samples) + " rays", Irradiance::monte_carlo,
                     samples);

        // Glossy light: the same sky as the maps (plain ground), as the
        // program stores it, and the exact one bounce of the analytic one.
        const Environment glossy_sky(cube_map(lab_sky, options.quick ? 64 : 512, 2),
                                     MapFilter::seamless);
        const std::vector<Facing> points = facings(spread_normals(options.quick ? 4 : 48));
        const std::vector<float> roughnesses =
            options.quick ? std::vector<float>{0.5f}
                          : std::vector<float>{0.1f, 0.25f, 0.5f, 0.75f, 1};
        std::vector<std::vector<rl::dvec3>> glossy_truth(roughnesses.size());
        for (std::size_t r = 0; r < roughnesses.size(); ++r) {
            glossy_truth[r].resize(points.size());
            rl::parallel_for(std::size_t{0}, points.size(), [&](std::size_t i) {
                glossy_truth[r][i] = exact_glossy(lab_sky, rl::cast<double>(points[i].n),
                                                  rl::cast<double>(points[i].v), roughnesses[r],
                                                  options.quick ? 12 : 18);
            });
        }
        std::vector<GlossyCase> glossy_cases;
        const std::vector<int> level_counts =
            options.quick ? std::vector<int>{6} : std::vector<int>{3, 6, 11};
        const std::vector<int> glossy_sizes =
            options.quick ? std::vector<int>{32} : std::vector<int>{32, 64, 128};
        const std::vector<int> glossy_samples =
            options.quick ? std::vector<int>{16} : std::vector<int>{16, 64, 256};
        for (int levels : level_counts)
            for (int size : glossy_sizes)
                for (int samples : glossy_samples) {
                    // Three levels blur only for roughness 0.5, on faces of 32
                    // texels whatever the largest allowed: one size is enough.
                    if (levels == 3 && size != glossy_sizes.front()) continue;
                    GlossyCase c;
                    c.name = "split sum, " + std::to_string(levels) + " levels, " +
                             std::to_string(size) + " texels, " + std::to_string(samples) +
                             " samples";
                    c.levels = levels, c.size = size, c.samples = samples;
                    const GlossyOptions defaults;
                    c.by_roughness =
                        options.quick ||
                        (levels == defaults.levels && size == defaults.size &&
                         samples == defaults.samples) ||
                        (levels == level_counts.back() && size == glossy_sizes.back() &&
                         samples == glossy_samples.back());
                    const auto start = std::chrono::steady_clock::now();
                    c.map = std::make_shared<GlossyMap>(
                        glossy_sky,
                        GlossyOptions{.levels = levels, .size = size, .samples = samples});
                    c.build_ms = std::chrono::duration<double, std::milli>(
                                     std::chrono::steady_clock::now() - start)
                                     .count();
                    glossy_cases.push_back(c);
                }
        // The default maps (quick mode: its one setting) read along the
        // mirror direction instead.
        for (const GlossyCase& c : std::vector<GlossyCase>(glossy_cases)) {
            const GlossyOptions defaults;
            if (!options.quick && (c.levels != defaults.levels || c.size != defaults.size ||
                                   c.samples != defaults.samples))
                continue;
            GlossyCase mirror = c;
            mirror.name += ", read along the mirror direction";
            mirror.lookup = Lookup::mirror;
            glossy_cases.push_back(mirror);
        }
        for (int rays :
             options.quick ? std::vector<int>{16} : std::vector<int>{16, 64, 256, 1024}) {
            GlossyCase c;
            c.name = "monte carlo, " + std::to_string(rays) + " rays";
            c.rays = rays;
            glossy_cases.push_back(c);
        }
        split_sum_table();  // built once, before any timing
        // Time per pixel: the split sum's look-ups cost the same at every
        // roughness (timed at 0.5); Monte Carlo's rays too.
        for (const GlossyCase& c : glossy_cases)
            if (c.by_roughness)
                benchmark::RegisterBenchmark(("glossy/" + c.name).c_str(), evaluate_glossy, &c,
                                             &glossy_sky, &points, 0.5f)
                    ->Unit(benchmark::kMicrosecond);

        const std::map<std::string, rl::lab::Timing> timings = rl::lab::run_benchmarks();

        rl::ResultsTable table({"view", "method", "map_size", "mib", "ms_per_frame", "ms_min",
                                "ms_max", "mean_levels", "p99_levels", "percent_over_2"});
        for (std::size_t v = 0; v < all_views.size(); ++v)
            for (const Row& row : rows) {
                const rl::lab::Timing& t =
                    timings.at(row.method.name() + "/" + std::to_string(row.size));
                const SkyError e =
                    sky_error(truths[v], sky_picture(*row.env, all_views[v].camera, image));
                const double texels = row.method.layout == Layout::cube ? 6.0 * row.size * row.size
                                                                        : 2.0 * row.size * row.size;
                const double mib = texels * 16 *
                                   (row.method.filter == MapFilter::trilinear ? 4.0 / 3 : 1) /
                                   (1 << 20);
                table.add_row({std::string(all_views[v].name), row.method.name(),
                               static_cast<long long>(row.size), mib, t.median_ns / 1e6,
                               t.min_ns / 1e6, t.max_ns / 1e6, e.mean_levels, e.p99_levels,
                               e.percent_over_2});
            }
        table.write_csv(options.out_dir / "09_maps.csv");
        std::printf("wrote %s\n", (options.out_dir / "09_maps.csv").c_str());

        rl::ResultsTable diffuse({"method", "ns_per_normal", "ns_min", "ns_max", "prepare_ms",
                                  "mean_error_percent", "max_error_percent", "normals"});
        for (const IrradianceCase& c : cases) {
            const rl::lab::Timing& t = timings.at("irradiance/" + c.name);
            double sum = 0, worst = 0;
            for (std::size_t i = 0; i < normals.size(); ++i) {
                const rl::dvec3 e =
                    rl::cast<double>(c.light->at(normals[i], static_cast<std::uint32_t>(i)));
                const double error = 100 * rl::length(e - exact[i]) / rl::length(exact[i]);
                sum += error;
                worst = std::max(worst, error);
            }
            const double count = static_cast<double>(normals.size());
            diffuse.add_row({c.name, t.median_ns / count, t.min_ns / count, t.max_ns / count,
                             c.prepare_ms, sum / count, worst,
                             static_cast<long long>(normals.size())});
        }
        diffuse.write_csv(options.out_dir / "09_irradiance.csv");
        std::printf("wrote %s\n", (options.out_dir / "09_irradiance.csv").c_str());

        rl::ResultsTable glossy({"method", "roughness", "mean_error_percent", "p90_error_percent",
                                 "ns_per_pixel", "ns_min", "ns_max", "build_ms", "mib"});
        rl::ResultsTable prefilter({"levels", "size", "samples", "setting", "build_ms", "mib",
                                    "mean_error_percent", "worst_roughness_error_percent"});
        const double count = static_cast<double>(points.size());
        for (const GlossyCase& c : glossy_cases) {
            const rl::lab::Timing no_timing;
            const rl::lab::Timing& t = c.by_roughness ? timings.at("glossy/" + c.name) : no_timing;
            const double mib = c.map ? static_cast<double>(c.map->bytes()) / (1 << 20) : 0.0;
            double all = 0, worst = 0;
            for (std::size_t r = 0; r < roughnesses.size(); ++r) {
                std::vector<double> errors;
                for (std::size_t i = 0; i < points.size(); ++i) {
                    const rl::dvec3 got = rl::cast<double>(one_bounce(
                        c, glossy_sky, points[i], roughnesses[r], static_cast<std::uint32_t>(i)));
                    const rl::dvec3& truth = glossy_truth[r][i];
                    errors.push_back(100 * rl::length(got - truth) / rl::length(truth));
                }
                double sum = 0;
                for (double e : errors) sum += e;
                std::sort(errors.begin(), errors.end());
                const double p90 = errors[static_cast<std::size_t>(0.9 * (errors.size() - 1))];
                if (c.by_roughness)
                    glossy.add_row({c.name, static_cast<double>(roughnesses[r]), sum / count, p90,
                                    t.median_ns / count, t.min_ns / count, t.max_ns / count,
                                    c.build_ms, mib});
                all += sum / count;
                worst = std::max(worst, sum / count);
            }
            if (c.map && c.lookup == Lookup::dominant)
                prefilter.add_row({static_cast<long long>(c.levels), static_cast<long long>(c.size),
                                   static_cast<long long>(c.samples),
                                   std::to_string(c.size) + "/" + std::to_string(c.samples),
                                   c.build_ms, mib, all / static_cast<double>(roughnesses.size()),
                                   worst});
        }
        glossy.write_csv(options.out_dir / "09_glossy.csv");
        std::printf("wrote %s\n", (options.out_dir / "09_glossy.csv").c_str());
        prefilter.write_csv(options.out_dir / "09_prefilter.csv");
        std::printf("wrote %s\n", (options.out_dir / "09_prefilter.csv").c_str());

        // One bounce's albedo (what a white metal returns of a white world)
        // with and without the masking term, and with the lost bounces put back.
        rl::ResultsTable albedo({"brdf", "roughness", "n_dot_v", "albedo"});
        for (double roughness :
             options.quick ? std::vector<double>{0.5} : std::vector<double>{0.25, 0.5, 1.0})
            for (int k = 1; k <= (options.quick ? 4 : 20); ++k) {
                const double n_dot_v = k / (options.quick ? 4.0 : 20.0);
                const SplitSum one = split_sum(n_dot_v, roughness, 4096);
                const SpecularShares kept = specular_shares({1, 1, 1}, one);
                char r[32];
                std::snprintf(r, sizeof r, " (roughness %g)", roughness);
                albedo.add_row({std::string("no masking, G = 1") + r, roughness, n_dot_v,
                                albedo_without_masking(n_dot_v, roughness)});
                albedo.add_row({std::string("one bounce") + r, roughness, n_dot_v, one.albedo()});
                albedo.add_row({std::string("lost bounces put back") + r, roughness, n_dot_v,
                                static_cast<double>(kept.single.x + kept.multiple.x)});
            }
        albedo.write_csv(options.out_dir / "09_albedo.csv");
        std::printf("wrote %s\n", (options.out_dir / "09_albedo.csv").c_str());
        return 0;
    });
}
