#include "rasterlab/lab.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

namespace rl::lab {
namespace {

// Keeps the console output of Google Benchmark and records every repetition.
class CollectingReporter : public benchmark::ConsoleReporter {
  public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.run_type != Run::RT_Iteration || run.error_occurred) continue;
            const double ns =
                run.GetAdjustedRealTime() * 1e9 / benchmark::GetTimeUnitMultiplier(run.time_unit);
            samples[run.run_name.str()].push_back(ns);
        }
    }
    std::map<std::string, std::vector<double>> samples;
};

std::vector<std::string>& kept_arguments() {
    static std::vector<std::string> arguments;  // argv must outlive Initialize's parsing
    return arguments;
}

}  // namespace

Options init(int& argc, char** argv, const std::string& description) {
    Options options;
    std::vector<std::string>& args = kept_arguments();
    args.assign({argv[0]});
    std::vector<std::string> user;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--quick") {
            options.quick = true;
        } else if (arg == "--out" && i + 1 < argc) {
            options.out_dir = argv[++i];
        } else if (arg.rfind("--out=", 0) == 0) {
            options.out_dir = arg.substr(6);
        } else if (arg == "--help" || arg == "-h") {
            std::cout << description << "\n\nOptions:\n"
                      << "  --quick       few repetitions on small inputs (what CI runs)\n"
                      << "  --out DIR     where to write the results CSV (default: .)\n"
                      << "  --benchmark_* any Google Benchmark flag, e.g. "
                         "--benchmark_filter=REGEX\n";
            std::exit(0);
        } else {
            user.push_back(arg);
        }
    }
    if (options.quick) {
        args.push_back("--benchmark_repetitions=1");
        args.push_back("--benchmark_min_time=0.001");
    } else {
        args.push_back("--benchmark_repetitions=5");
        args.push_back("--benchmark_min_time=0.2");
        // Repetitions of all the benchmarks in a random order, not each one's
        // five in a row: a slow spell of the machine then falls on every
        // method alike instead of on whichever ran during it.
        args.push_back("--benchmark_enable_random_interleaving=true");
    }
    args.insert(args.end(), user.begin(), user.end());

    static std::vector<char*> pointers;
    pointers.clear();
    for (std::string& a : args) pointers.push_back(a.data());
    pointers.push_back(nullptr);
    int count = static_cast<int>(args.size());
    benchmark::Initialize(&count, pointers.data());
    if (benchmark::ReportUnrecognizedArguments(count, pointers.data())) std::exit(2);
    std::filesystem::create_directories(options.out_dir);
    return options;
}

std::map<std::string, Timing> run_benchmarks() {
    CollectingReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    std::map<std::string, Timing> timings;
    for (auto& [name, samples] : reporter.samples) {
        std::sort(samples.begin(), samples.end());
        const std::size_t n = samples.size();
        Timing t;
        t.median_ns = n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
        t.min_ns = samples.front();
        t.max_ns = samples.back();
        t.repetitions = static_cast<int>(n);
        timings[name] = t;
    }
    return timings;
}

}  // namespace rl::lab
