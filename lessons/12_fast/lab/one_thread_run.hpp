// Llvmpipe reads its thread count (LP_NUM_THREADS) once in a process, when
// its first context is made, so one process can time it on one number of
// threads only. The lab therefore times its one-thread cells (ours and
// llvmpipe's, interleaved with each other) in a second run of itself, a
// child process started with a flag of its own, and reads their timings
// back from a file the child writes.
//
//   const bool child = fast::lab::take_one_thread_flag(argc, argv);  // before rl::lab::init
//   ...
//   if (child) fast::lab::write_one_thread_timings(rl::lab::run_benchmarks(), out_dir);
//   else timings.merge(fast::lab::run_one_thread_child(arguments, out_dir));
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "rasterlab/lab.hpp"

namespace fast::lab {

// Removes the child's flag from the command line; returns whether it was there.
bool take_one_thread_flag(int& argc, char** argv);

// Runs this program again with the child's flag and `arguments` (the lab's
// own, so that --quick, --out and Google Benchmark's flags hold there too),
// waits for it, and returns the timings it wrote into `out_dir`. Throws
// std::runtime_error when the child fails or writes nothing readable.
std::map<std::string, rl::lab::Timing> run_one_thread_child(
    const std::vector<std::string>& arguments, const std::filesystem::path& out_dir);

// The child's side: the timings, where run_one_thread_child reads them.
void write_one_thread_timings(const std::map<std::string, rl::lab::Timing>& timings,
                              const std::filesystem::path& out_dir);

}  // namespace fast::lab
