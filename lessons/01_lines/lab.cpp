// Lesson 01's lab: every line method on the same random segments, timed with
// Google Benchmark and scored against the ideal segment. Writes 01_lines.csv.
#include <benchmark/benchmark.h>

#include <cstdio>

#include "draw_line.hpp"
#include "line_measure.hpp"
#include "rasterlab/lab.hpp"
#include "rasterlab/main_guard.hpp"
#include "rasterlab/results_table.hpp"

namespace {

struct Scene {
    int size;
    std::vector<lines::Segment> segments;
};

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
        Scene scene{options.quick ? 256 : 1024, {}};
        scene.segments = lines::random_segments(options.quick ? 60 : 2000, scene.size, 1);

        for (lines::LineMethod m : lines::kLineMethods)
            benchmark::RegisterBenchmark((std::string("draw/") + lines::name(m)).c_str(), draw_all,
                                         &scene, m)
                ->Unit(benchmark::kMicrosecond);
        const auto timings = rl::lab::run_benchmarks();

        rl::ResultsTable table({"method", "ns_per_line", "ns_per_pixel", "coverage_error",
                                "max_distance", "mean_distance", "gaps_per_line",
                                "duplicates_per_line", "lines", "image_size", "repetitions"});
        for (lines::LineMethod m : lines::kLineMethods) {
            lines::LineScore score;
            for (const lines::Segment& s : scene.segments)
                lines::score_segment(m, s, scene.size, scene.size, score);
            const rl::lab::Timing& t = timings.at(std::string("draw/") + lines::name(m));
            const double n = static_cast<double>(score.segments);
            table.add_row(
                {std::string(lines::name(m)), t.median_ns / n,
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
