// libFuzzer target: a lesson's command line. The input is split into
// arguments at NUL bytes and newlines (at most 24, each at most 200 bytes);
// the size and output options are replaced by a small image written to a
// scratch folder, so that every run stays fast. The program must return
// normally (success or a refused input), never crash or trip a sanitizer.
// One binary per lesson: it links the lesson's objects, its main.cpp compiled
// with main renamed to lesson_main (rasterlab_lesson() in lessons/CMakeLists.txt).
// Run: build-fuzz/tests/fuzz/fuzz_cli_02_triangles tests/fuzz/corpus/cli
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

int lesson_main(int argc, char** argv);

namespace {

// Options that take a value the harness owns: sizes (a 16384 x 16384 image
// is legal and slow) and output paths (the fuzzer must not write anywhere).
// Lesson 09 (FUZZ_SMALL_MAP) also builds an environment map of --map-size
// texels a side (up to 2048: seconds of work under the sanitizers), and
// blurred maps of --glossy-size and --glossy-samples (up to 2^30 reads of
// the map: minutes under the sanitizers).
const std::set<std::string_view> kOwned = {
    "-o",         "--output",      "--png",           "--depth-out",
    "--width",    "--height",      "--diff",
#ifdef FUZZ_SMALL_MAP
    "--map-size", "--glossy-size", "--glossy-samples"
#endif
};

bool owned(std::string_view argument) {
    for (std::string_view option : kOwned)
        if (argument == option || argument.starts_with(std::string(option) + "=")) return true;
    return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string output = [] {
        auto dir = std::filesystem::temp_directory_path() /
                   ("rasterlab-fuzz-cli-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        return (dir / "out.tga").string();
    }();
    std::vector<std::string> arguments = {"lesson"};
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    bool skip_value = false;
    for (std::size_t start = 0; start <= input.size() && arguments.size() < 25;) {
        std::size_t end = input.find_first_of(std::string_view("\0\n", 2), start);
        if (end == std::string_view::npos) end = input.size();
        const std::string_view argument =
            input.substr(start, std::min<std::size_t>(end - start, 200));
        start = end + 1;
        if (skip_value) {
            skip_value = false;
            continue;
        }
        if (owned(argument)) {
            skip_value = argument.find('=') == std::string_view::npos;
            continue;
        }
        if (argument == "--help" || argument == "-h") continue;  // prints only
        arguments.emplace_back(argument);
    }
    for (const char* fixed : {"--width", "40", "--height", "32", "-o"})
        arguments.emplace_back(fixed);
#ifdef FUZZ_SMALL_MAP
    arguments.insert(arguments.end() - 1,
                     {"--map-size", "8", "--glossy-size", "8", "--glossy-samples", "4"});
#endif
    arguments.push_back(output);
    std::vector<char*> argv;
    for (std::string& a : arguments) argv.push_back(a.data());
    argv.push_back(nullptr);
    lesson_main(static_cast<int>(arguments.size()), argv.data());
    return 0;
}
