// Lesson 02's lab: the three rasterizers on the same triangles, timed with
// Google Benchmark and scored against the exact coverage rule. Writes
// 02_triangles.csv (coverage per triangle size) and 02_triangles_mesh.csv
// (watertightness on meshes whose triangles share edges).
#include <benchmark/benchmark.h>

#include <cstdio>

#include "02_triangles/truths/triangle_measure.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"

namespace {

using triangles::RasterMethod;
using triangles::ScreenTriangle;

struct Scene {
    std::string name;
    std::vector<ScreenTriangle> triangles;
};

void fill_all(benchmark::State& state, const std::vector<ScreenTriangle>* scene,
              RasterMethod method, int size) {
    rl::Image image(size, size);
    const rl::Rgba white{255, 255, 255, 255};
    for (auto _ : state) {
        for (const ScreenTriangle& t : *scene)
            triangles::rasterize(method, t, size, size,
                                 [&](int x, int y, rl::vec3) { image.at(x, y) = white; });
        benchmark::DoNotOptimize(image.pixels().data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(scene->size()));
}

std::string bench_name(RasterMethod m, const std::string& scene) {
    return std::string("fill/") + triangles::name(m) + "/" + scene;
}

long pixels_drawn(RasterMethod m, const std::vector<ScreenTriangle>& scene, int size) {
    long n = 0;
    for (const ScreenTriangle& t : scene)
        n += static_cast<long>(triangles::covered_pixels(m, t, size, size).size());
    return n;
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options = rl::lab::init(
        argc, argv,
        "Lesson 02 lab: rasterizers, time against coverage accuracy and watertightness.");
    return rl::guarded_main("02_triangles_lab", [&] {
        const bool quick = options.quick;
        const int size = quick ? 256 : 1024;
        const std::vector<Scene> scenes = {
            {"small (10 px)", triangles::random_triangles(quick ? 500 : 20000, 10, size, 1)},
            {"medium (1k px)", triangles::random_triangles(quick ? 50 : 2000, 1000, size, 2)},
            {"large (100k px)",
             triangles::random_triangles(quick ? 2 : 40, quick ? 20000 : 100000, size, 3)},
            {"ties (on pixel centres)", triangles::tie_triangles(quick ? 200 : 5000, size, 4)},
        };
        const float half = size * 0.5f;
        const std::vector<Scene> meshes = {
            {"disc fan", triangles::disc_fan({half + 0.5f, half + 0.5f}, half * 0.8f, 96)},
            {"jittered grid", triangles::jittered_grid(quick ? 8 : 32, size, size * 0.05f, 5)},
        };
        for (RasterMethod m : triangles::kRasterMethods) {
            for (const Scene& s : scenes)
                benchmark::RegisterBenchmark(bench_name(m, s.name).c_str(), fill_all, &s.triangles,
                                             m, size)
                    ->Unit(benchmark::kMicrosecond);
            for (const Scene& s : meshes)
                benchmark::RegisterBenchmark(bench_name(m, s.name).c_str(), fill_all, &s.triangles,
                                             m, size)
                    ->Unit(benchmark::kMicrosecond);
        }
        const auto timings = rl::lab::run_benchmarks();

        rl::ResultsTable coverage({"method", "scene", "ns_per_triangle", "ns_per_pixel",
                                   "wrong_per_million", "wrongly_set", "missed", "reference_pixels",
                                   "triangles", "image_size"});
        for (const Scene& s : scenes)
            for (RasterMethod m : triangles::kRasterMethods) {
                const auto score = triangles::score_coverage(m, s.triangles, size, size);
                const double ns = timings.at(bench_name(m, s.name)).median_ns;
                coverage.add_row(
                    {std::string(triangles::name(m)), s.name,
                     ns / static_cast<double>(s.triangles.size()),
                     ns / static_cast<double>(std::max(1L, pixels_drawn(m, s.triangles, size))),
                     score.wrong_per_million(), static_cast<long long>(score.wrongly_set),
                     static_cast<long long>(score.missed),
                     static_cast<long long>(score.reference_pixels),
                     static_cast<long long>(s.triangles.size()), static_cast<long long>(size)});
            }
        rl::ResultsTable watertight({"method", "mesh", "ns_per_triangle", "errors",
                                     "double_covered", "holes", "pixels", "triangles"});
        for (const Scene& s : meshes)
            for (RasterMethod m : triangles::kRasterMethods) {
                const auto score = triangles::score_watertight(m, s.triangles, size, size);
                watertight.add_row({std::string(triangles::name(m)), s.name,
                                    timings.at(bench_name(m, s.name)).median_ns /
                                        static_cast<double>(s.triangles.size()),
                                    static_cast<long long>(score.double_covered + score.holes),
                                    static_cast<long long>(score.double_covered),
                                    static_cast<long long>(score.holes),
                                    static_cast<long long>(score.pixels),
                                    static_cast<long long>(s.triangles.size())});
            }
        coverage.write_csv(options.out_dir / "02_triangles.csv");
        watertight.write_csv(options.out_dir / "02_triangles_mesh.csv");
        std::printf("%s\n%s", coverage.to_csv().c_str(), watertight.to_csv().c_str());
        return 0;
    });
}
