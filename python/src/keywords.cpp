#include "keywords.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace py_rl {

namespace {

// A number as a user would have typed it: the shortest text that reads back
// as the same double (0, 2.5, 1e+39).
std::string as_typed(double value) {
    char text[64];
    const auto [end, error] = std::to_chars(text, text + sizeof text, value);
    if (error != std::errc{}) return std::to_string(value);
    return std::string(text, end);
}

}  // namespace

void refuse_choice(const char* option, const std::string& text,
                   const std::vector<std::string>& names) {
    std::string message = std::string(option) + ": " + text + " not in {";
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) message += ',';
        message += names[i];
    }
    throw py::value_error(message + "}");
}

std::string choice(const char* option, const std::string& text,
                   const std::vector<std::string>& names) {
    for (const std::string& n : names)
        if (n == text) return n;
    refuse_choice(option, text, names);
}

void in_range(const char* option, long long value, long long low, long long high) {
    if (value < low || value > high)
        throw py::value_error(std::string(option) + ": Value " + std::to_string(value) +
                              " not in range " + std::to_string(low) + " to " +
                              std::to_string(high));
}

float finite(const char* option, double value, double low, double high) {
    const std::string text = as_typed(value);
    if (!std::isfinite(value))
        throw py::value_error(std::string(option) + ": '" + text + "' is not a finite number");
    if (value < low || value > high)
        throw py::value_error(std::string(option) + ": '" + text + "' is outside [" +
                              std::to_string(low) + ", " + std::to_string(high) + "]");
    return static_cast<float>(value);
}

std::vector<float> three(const char* option, const std::vector<double>& values) {
    if (values.size() < 3)
        throw py::value_error(std::string(option) + ": At least 3 required but received " +
                              std::to_string(values.size()));
    if (values.size() > 3)
        throw py::value_error(std::string(option) + ": At Most 3 required but received " +
                              std::to_string(values.size()));
    std::vector<float> out;
    for (double v : values) out.push_back(finite(option, v));
    return out;
}

}  // namespace py_rl
