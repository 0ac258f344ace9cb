// Lesson 03's lab. Hidden surfaces: the painter's algorithm and the BSP tree
// against the z-buffer, on scenes with cycles and interpenetration. Depth
// precision: each depth format on two planes 0.01 apart, over distance and
// near/far range. Writes 03_hsr.csv, 03_depth.csv, 03_depth_sweep.csv and
// 03_depth_near.csv.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>

#include "03_zbuffer/hsr_scenes.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"
#include "03_zbuffer/zfight.hpp"

namespace {

using namespace zbuffer;

struct Scene {
    std::string name;
    std::vector<SceneTriangle> triangles;
};

void render_scene(benchmark::State& state, const Scene* scene, HsrMethod method, int size) {
    for (auto _ : state) {
        Frame frame(size, size);
        render(method, scene->triangles, frame);
        benchmark::DoNotOptimize(frame.ids.pixels().data());
    }
}

// The painter's sort alone (on a fresh copy each time, as the painter sorts).
void painter_sort(benchmark::State& state, const Scene* scene) {
    for (auto _ : state) {
        std::vector<SceneTriangle> copy = scene->triangles;
        sort_far_to_near(copy);
        benchmark::DoNotOptimize(copy.data());
    }
}

// Encode both planes' depths and run the depth test, as a buffer would per fragment.
void depth_test(benchmark::State& state, const std::vector<float>* distances, DepthFormat format,
                DepthRange range) {
    std::vector<double> buffer(distances->size());
    for (auto _ : state) {
        for (std::size_t i = 0; i < distances->size(); ++i)
            buffer[i] = depth_key(format, (*distances)[i], range);
        long passed = 0;
        for (std::size_t i = 0; i < distances->size(); ++i) {
            const double key = depth_key(format, (*distances)[i] * 1.0001f, range);
            if (key < buffer[i]) buffer[i] = key, ++passed;
        }
        benchmark::DoNotOptimize(passed);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(2 * distances->size()));
}

std::string hsr_name(HsrMethod m, const std::string& scene) {
    return std::string("hsr/") + name(m) + "/" + scene;
}
std::string depth_name(DepthFormat f) {
    return std::string("depth/") + name(f);
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options =
        rl::lab::init(argc, argv, "Lesson 03 lab: hidden-surface methods and depth formats.");
    return rl::guarded_main("03_zbuffer_lab", [&] {
        const int size = options.quick ? 128 : 512;
        const std::vector<Scene> scenes = {
            {"cyclic sticks", cyclic_sticks(size)},
            {"random soup", random_soup(options.quick ? 20 : 200, size, 9)},
            {"rock and torus", build_scene(default_placements(), size, size)},
        };
        for (HsrMethod m : kHsrMethods)
            for (const Scene& s : scenes)
                benchmark::RegisterBenchmark(hsr_name(m, s.name).c_str(), render_scene, &s, m, size)
                    ->Unit(benchmark::kMicrosecond);
        for (const Scene& s : scenes)
            benchmark::RegisterBenchmark(("sort/" + s.name).c_str(), painter_sort, &s)
                ->Unit(benchmark::kMicrosecond);

        TwoPlanes planes;
        planes.size = options.quick ? 64 : 512;
        const DepthRange loose{0.1f, 1000.0f};
        std::vector<float> distances;
        for (int i = 0; i < 512 * 64; ++i)
            distances.push_back(static_cast<float>(90.0 + 240.0 * (i % 512) / 512.0));
        for (DepthFormat f : kDepthFormats)
            benchmark::RegisterBenchmark(depth_name(f).c_str(), depth_test, &distances, f, loose)
                ->Unit(benchmark::kMicrosecond);
        const auto timings = rl::lab::run_benchmarks();

        rl::ResultsTable hsr({"method", "scene", "ns_per_triangle", "wrong_percent", "triangles_in",
                              "triangles_drawn", "bsp_build_ms", "bsp_depth",
                              "sort_ns_per_triangle"});
        for (const Scene& s : scenes) {
            Frame reference(size, size);
            draw_zbuffer(s.triangles, reference);
            for (HsrMethod m : kHsrMethods) {
                Frame frame(size, size);
                render(m, s.triangles, frame);
                long long drawn = static_cast<long long>(s.triangles.size()), depth = 0;
                double build_ms = 0;
                if (m == HsrMethod::bsp) {
                    const auto start = std::chrono::steady_clock::now();
                    const BspTree tree = build_bsp(s.triangles);
                    build_ms = std::chrono::duration<double, std::milli>(
                                   std::chrono::steady_clock::now() - start)
                                   .count();
                    drawn = static_cast<long long>(tree.triangles);
                    depth = tree.depth;
                }
                hsr.add_row({std::string(name(m)), s.name,
                             timings.at(hsr_name(m, s.name)).median_ns /
                                 static_cast<double>(s.triangles.size()),
                             100.0 * wrong_share(frame, reference),
                             static_cast<long long>(s.triangles.size()), drawn, build_ms, depth,
                             m == HsrMethod::painter ? timings.at("sort/" + s.name).median_ns /
                                                           static_cast<double>(s.triangles.size())
                                                     : 0.0});
            }
        }

        planes.distance = 100;
        const DepthRange fitted = fitted_range(planes);
        rl::ResultsTable depth(
            {"format", "ns_per_fragment", "zfight_percent", "zfight_percent_fitted"});
        for (DepthFormat f : kDepthFormats)
            depth.add_row({std::string(name(f)),
                           timings.at(depth_name(f)).median_ns / (2.0 * distances.size()),
                           100.0 * zfight_share(f, loose, planes),
                           100.0 * zfight_share(f, fitted, planes)});

        rl::ResultsTable sweep({"format", "range", "distance", "zfight_percent"});
        // The loose range stops at 400, where the planes' far edge (2.36 x the
        // distance) nears the far plane; fitted ranges go on to 1600, far enough
        // for 16-bit depth to fail even fitted.
        for (DepthFormat f : kDepthFormats)
            for (double d : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 400.0, 800.0, 1600.0}) {
                TwoPlanes at = planes;
                at.distance = d;
                if (d <= 400.0)
                    sweep.add_row({std::string(name(f)), std::string("near 0.1, far 1000"), d,
                                   100.0 * zfight_share(f, loose, at)});
                sweep.add_row({std::string(name(f)), std::string("fitted to the planes"), d,
                               100.0 * zfight_share(f, fitted_range(at), at)});
            }
        // Over the near/far ratio: the planes at distance 50, far 1000, near from 10 down to 1e-4.
        rl::ResultsTable by_near({"format", "near_far_ratio", "zfight_percent"});
        TwoPlanes at50 = planes;
        at50.distance = 50;
        for (DepthFormat f : kDepthFormats)
            for (double n : {10.0, 1.0, 0.1, 0.01, 1e-3, 1e-4})
                by_near.add_row({std::string(name(f)), 1000.0 / n,
                                 100.0 * zfight_share(f, {static_cast<float>(n), 1000.0f}, at50)});
        by_near.write_csv(options.out_dir / "03_depth_near.csv");
        hsr.write_csv(options.out_dir / "03_hsr.csv");
        depth.write_csv(options.out_dir / "03_depth.csv");
        sweep.write_csv(options.out_dir / "03_depth_sweep.csv");
        std::printf("%s\n%s", hsr.to_csv().c_str(), depth.to_csv().c_str());
        return 0;
    });
}
