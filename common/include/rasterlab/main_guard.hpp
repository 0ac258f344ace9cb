// The one place where a program's errors become a message and an exit code.
#pragma once

#include <exception>
#include <functional>
#include <iostream>
#include <new>
#include <string>
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

inline void print_warnings(const char* program, const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings) std::cerr << program << ": warning: " << w << '\n';
}

}  // namespace rl
