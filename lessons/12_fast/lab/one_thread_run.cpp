#include "one_thread_run.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace fast::lab {

namespace {

constexpr const char* kFlag = "--one-thread-run";

std::filesystem::path timings_file(const std::filesystem::path& out_dir) {
    return out_dir / "12_one_thread_timings.txt";
}

}  // namespace

bool take_one_thread_flag(int& argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], kFlag) == 0) {
            for (int j = i; j + 1 < argc; ++j) argv[j] = argv[j + 1];
            argv[--argc] = nullptr;
            return true;
        }
    return false;
}

std::map<std::string, rl::lab::Timing> run_one_thread_child(
    const std::vector<std::string>& arguments, const std::filesystem::path& out_dir) {
    const std::filesystem::path file = timings_file(out_dir);
    std::filesystem::remove(file);  // a file left by an earlier run must not pass for this one's
    std::vector<std::string> args{"/proc/self/exe", kFlag};
    args.insert(args.end(), arguments.begin(), arguments.end());
    std::vector<char*> pointers;
    for (std::string& a : args) pointers.push_back(a.data());
    pointers.push_back(nullptr);
    pid_t child = 0;
    if (const int error =
            posix_spawn(&child, pointers[0], nullptr, nullptr, pointers.data(), environ))
        throw std::runtime_error(std::string("could not start the lab's one-thread run: ") +
                                 std::strerror(error));
    int status = 0;
    while (waitpid(child, &status, 0) < 0)
        if (errno != EINTR) throw std::runtime_error("lost the lab's one-thread run");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("the lab's one-thread run failed (its output is above)");
    // One line a cell: median, min and max in nanoseconds, repetitions, then the name.
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": the one-thread run wrote no timings");
    std::map<std::string, rl::lab::Timing> timings;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        rl::lab::Timing t;
        std::string name;
        if (!(fields >> t.median_ns >> t.min_ns >> t.max_ns >> t.repetitions) ||
            !std::getline(fields >> std::ws, name) || name.empty())
            throw std::runtime_error(file.string() + ": not a line of timings: " + line);
        timings[name] = t;
    }
    std::filesystem::remove(file);
    // (none, when --benchmark_filter keeps no one-thread cell)
    return timings;
}

void write_one_thread_timings(const std::map<std::string, rl::lab::Timing>& timings,
                              const std::filesystem::path& out_dir) {
    std::ofstream out(timings_file(out_dir));
    out.precision(17);
    for (const auto& [name, t] : timings)
        out << t.median_ns << ' ' << t.min_ns << ' ' << t.max_ns << ' ' << t.repetitions << ' '
            << name << '\n';
    if (!out) throw std::runtime_error(timings_file(out_dir).string() + ": could not be written");
}

}  // namespace fast::lab
