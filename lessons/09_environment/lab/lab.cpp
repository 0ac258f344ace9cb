// Lesson 09's lab: the sky behind the scene read from a cube map or a
// lat-long map, by each filter, at map sizes from 16 to 1024 texels, in
// three views (the program's, one into a cube edge, one straight up at the
// pole), against the analytic sky averaged over each pixel; and the time
// the sky pass takes per frame. Writes 09_maps.csv. Then diffuse light: the
// irradiance by spherical harmonics, the convolved map and Monte Carlo at
// 4 to 4096 rays, against the sky's irradiance by quadrature, over normals
// spread evenly on the sphere, with the time per normal and to prepare.
// Writes 09_irradiance.csv. The lab's sky has a
// plain ground: the checker's squares shrink without bound towards the
// horizon, so no map and no pixel's 16 rays hold them, and the score would
// measure that aliasing instead of the maps.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>

#include "09_environment/irradiance.hpp"
#include "irradiance_truth.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"
#include "sky_truth.hpp"

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
    perspective::Camera camera;
};

std::vector<View> views() {
    perspective::Camera horizon;  // the program's default view
    horizon.eye = {0.3f, 0.35f, 3.8f};
    horizon.target = {0, 0, 0};
    perspective::Camera edge;  // along the edge between the -x and -z faces
    edge.eye = {0, 0, 0};
    edge.target = {-1, 0.15f, -1};
    edge.fov_y = 60;
    perspective::Camera zenith;  // straight up: the lat-long map's pole
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
rl::Image sky_picture(const Environment& env, const perspective::Camera& camera, int size) {
    LightTarget frame = light_target(size, size);
    draw_skybox(env, camera, frame);
    return tone_mapped(frame.colour(), {});
}

void sky_pass(benchmark::State& state, const Environment* env, perspective::Camera camera,
              int size) {
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
        return 0;
    });
}
