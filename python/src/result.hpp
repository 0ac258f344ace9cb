// What every render function of the module returns: the picture, the depth
// buffer where the lesson keeps one, the counts its program prints and the
// warnings it would have printed. Python sees the pixels as numpy arrays that
// look into this object's own buffers (no copy), top row first.
//
//   py_rl::Result r;
//   r.colour = std::move(image);
//   r.count("faces", counts.faces);
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "made_by_init.hpp"
#include "rasterlab/image.hpp"

namespace py_rl {

namespace py = pybind11;

struct Result {
    rl::Image colour;
    std::optional<rl::FloatImage> depth;  // window depth in [0, 1], 1 where nothing was drawn
    using Value = std::variant<long long, double, std::string, std::vector<double>>;
    std::vector<std::pair<std::string, Value>> counts;  // in the order the program prints them
    std::vector<std::string> warnings;

    void count(const std::string& name, std::size_t value) {
        counts.emplace_back(name, static_cast<long long>(value));
    }
    void count(const std::string& name, int value) {
        counts.emplace_back(name, static_cast<long long>(value));
    }
    void count(const std::string& name, double value) { counts.emplace_back(name, value); }
    void count(const std::string& name, const std::string& value) {
        counts.emplace_back(name, value);
    }
    void count(const std::string& name, const std::vector<double>& value) {
        counts.emplace_back(name, value);
    }
};

// Registers rasterlab.Result.
void bind_result(py::module_& m);

}  // namespace py_rl

RASTERLAB_REFUSE_USE_BEFORE_INIT(Result, "Result")
