// Lesson 01's lab: every line method on the same random segments, timed with
// Google Benchmark and scored against the ideal segment, in three scenes:
// endpoints on pixel centres, endpoints anywhere, and segments reaching far
// across the image's edges (clipped). Writes 01_lines.csv.
#include <benchmark/benchmark.h>

#include <cstdio>

#include "01_lines/draw_line.hpp"
#include "line_measure.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"

namespace {

struct Scene {
    std::string name;
    int size;
    std::vector<lines::Segment> segments;
};

std::string benchmark_name(lines::LineMethod m, const Scene& scene) {
    return std::string("draw/") + lines::name(m) + "/" + scene.name;
}

void draw_all(benchmark::State& state, const Scene* scene, lines::LineMethod method) {
    rl::Image image(scene->size, scene->size);
    for (auto _ : state) {
        for (const lines::Segment& s : scene->segments)
            lines::draw_line(image, s.a, s.b, rl::Rgba{255, 255, 255, 255}, method);
        benchmark::DoNotOptimize(image.pixels().data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(scene->segments.size()));
}

}  // namespace

int main(int argc, char** argv) {
    const rl::lab::Options options = rl::lab::init(
        argc, argv, "Lesson 01 lab: line methods, time against accuracy. Writes 01_lines.csv.");
    return rl::guarded_main("01_lines_lab", [&] {
        const int size = options.quick ? 256 : 1024;
        const std::vector<lines::Segment> centred =
            lines::random_segments(options.quick ? 60 : 2000, size, 1);
        const std::vector<Scene> scenes = {
            {"centred endpoints", size, centred},
            {"off-centre endpoints", size, lines::moved_segments(centred, size, 1.0, 2)},
            {"clipped (3x the image)", size, lines::moved_segments(centred, size, 3.0, 3)}};

        for (const Scene& scene : scenes)
            for (lines::LineMethod m : lines::kLineMethods)
                benchmark::RegisterBenchmark(benchmark_name(m, scene).c_str(), draw_all, &scene, m)
                    ->Unit(benchmark::kMicrosecond);
        const auto timings = rl::lab::run_benchmarks();

        rl::ResultsTable table({"method", "scene", "ns_per_line", "ns_per_pixel", "coverage_error",
                                "max_distance", "mean_distance", "gaps_per_line",
                                "duplicates_per_line", "lines", "image_size", "repetitions"});
        for (const Scene& scene : scenes)
            for (lines::LineMethod m : lines::kLineMethods) {
                lines::LineScore score;
                for (const lines::Segment& s : scene.segments)
                    lines::score_segment(m, s, scene.size, scene.size, score);
                const rl::lab::Timing& t = timings.at(benchmark_name(m, scene));
                const double n = static_cast<double>(scene.segments.size());
                table.add_row(
                    {std::string(lines::name(m)), scene.name, t.median_ns / n,
                     t.median_ns / static_cast<double>(score.plot_calls),
                     score.coverage_error_per_length(), score.max_distance, score.mean_distance(),
                     static_cast<double>(score.gaps) / n, static_cast<double>(score.duplicates) / n,
                     static_cast<long long>(score.segments), static_cast<long long>(scene.size),
                     static_cast<long long>(t.repetitions)});
            }
        const auto path = options.out_dir / "01_lines.csv";
        table.write_csv(path);
        std::printf("%s", table.to_csv().c_str());
        std::printf("wrote %s\n", path.string().c_str());
        return 0;
    });
}
