// The one place where a program's errors become a message and an exit code
// (the lessons' programs reach it through rl::CommandLine::run, the labs
// directly).
//
//   return rl::guarded_main("02_triangles_lab", [&] {  // an exception: a message, exit code 1
//       const rl::Mesh mesh = rl::load_obj(model, &warnings);
//       rl::print_warnings("02_triangles_lab", warnings);  // each distinct text once, 10 at most
//       return 0;
//   });
#pragma once

#include <exception>
#include <functional>
#include <iostream>
#include <new>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rl {

// Runs `body` and returns its exit code; any exception becomes
// "<program>: error: <message>" on stderr and exit code `error_code`.
// Loaders name the file in their own out-of-memory errors; what reaches here
// as a bare std::bad_alloc came from the image buffers, whose size the
// options set.
inline int guarded_main(const char* program, const std::function<int()>& body, int error_code = 1) {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        std::cerr << program
                  << ": error: out of memory for the image buffers (--width x --height pixels; "
                     "try a smaller size)\n";
        return error_code;
    } catch (const std::exception& e) {
        std::cerr << program << ": error: " << e.what() << '\n';
        return error_code;
    }
}

// The warnings, "<program>: warning: <text>", each distinct text once (with
// how many times it came, if more than once) and at most `shown` of them,
// then how many more there were: 50 000 `mtllib` lines naming a missing file
// would otherwise print 50 000 lines.
inline void print_warnings(const char* program, const std::vector<std::string>& warnings,
                           std::size_t shown = 10) {
    std::vector<std::pair<std::string, std::size_t>> distinct;  // in the order they first came
    std::unordered_map<std::string, std::size_t> index;
    for (const std::string& w : warnings) {
        if (w.empty()) continue;  // (a check that found nothing to warn about)
        const auto [at, added] = index.emplace(w, distinct.size());
        if (added) distinct.push_back({w, 0});
        ++distinct[at->second].second;
    }
    std::size_t hidden = 0;
    for (std::size_t i = 0; i < distinct.size(); ++i) {
        const auto& [text, times] = distinct[i];
        if (i >= shown) {
            hidden += times;
            continue;
        }
        std::cerr << program << ": warning: " << text;
        if (times > 1) std::cerr << " (" << times << " times)";
        std::cerr << '\n';
    }
    if (hidden > 0)
        std::cerr << program << ": warning: and " << hidden << " more warnings like these\n";
}

}  // namespace rl
