// The Python module's keyword checks: each refuses what the program's command
// line refuses, with the message the program prints (CLI11's wording for
// ranges and choices, rasterlab's own for numbers), raised as ValueError.
// The option is named as the program spells it (--normal-map for the
// keyword normal_map), so that a message reads the same in both.
//
//   const auto method = py_rl::choice("--raster", raster, triangles::kRasterMethods);
//   py_rl::in_range("--width", width, 1, 16384);
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rasterlab/named_enum.hpp"

namespace py_rl {

namespace py = pybind11;

// Raises ValueError as CLI11 words it: "--raster: foo not in {scanline,bbox,edge}".
[[noreturn]] void refuse_choice(const char* option, const std::string& text,
                                const std::vector<std::string>& names);

// The value of a method enum named `text`.
template <class E, std::size_t N>
E choice(const char* option, const std::string& text, const std::array<E, N>& all) {
    if (const std::optional<E> value = rl::from_name(text, all)) return *value;
    std::vector<std::string> names;
    for (E e : all) names.emplace_back(name(e));
    refuse_choice(option, text, names);
}
// The same for a list of plain names (lesson 03's --scene).
std::string choice(const char* option, const std::string& text,
                   const std::vector<std::string>& names);

// CLI11's Range: "--width: Value 0 not in range 1 to 16384".
void in_range(const char* option, long long value, long long low, long long high);

// rl::finite_number(): a finite float in [low, high] (by default, any finite float).
float finite(const char* option, double value, double low = -3.4028234663852886e38,
             double high = 3.4028234663852886e38);

// Three finite numbers (an eye, a target, a light direction): "--eye: Expected 3 values".
std::vector<float> three(const char* option, const std::vector<double>& values);

}  // namespace py_rl
