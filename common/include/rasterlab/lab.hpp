// The labs' shared harness: Google Benchmark for the timing, a quick mode for
// CI, and one CSV per lab that the plotting script turns into a chart.
//
//   const rl::lab::Options options = rl::lab::init(argc, argv, "Lesson 02 lab: rasterizers.");
//   benchmark::RegisterBenchmark("edge/small", fill_all, &scene)->Unit(benchmark::kMicrosecond);
//   const std::map<std::string, rl::lab::Timing> timings = rl::lab::run_benchmarks();
//   const double ns = timings.at("edge/small").median_ns;  // then a CSV in options.out_dir
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace rl::lab {

struct Options {
    bool quick = false;                   // few repetitions, small inputs: proves the lab runs
    std::filesystem::path out_dir = ".";  // where the lab writes <name>.csv
};

// Takes --quick and --out DIR off the command line, answers --help, and
// hands the rest to Google Benchmark with the repetition settings of the
// mode: full mode 5 repetitions of at least 0.2 s each, interleaved in a
// random order across the benchmarks; quick mode one short run. Flags given by the user
// (--benchmark_...) win over these defaults.
Options init(int& argc, char** argv, const std::string& description);

struct Timing {
    double median_ns = 0;  // median over repetitions of the real time per iteration
    double min_ns = 0;
    double max_ns = 0;
    int repetitions = 0;
};

// Runs every registered benchmark (console output as usual) and returns
// each one's timing, keyed by the benchmark's name.
std::map<std::string, Timing> run_benchmarks();

}  // namespace rl::lab
