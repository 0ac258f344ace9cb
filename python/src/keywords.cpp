#include "keywords.hpp"

#include <pythread.h>

#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
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

void refuse_bool(py::handle value, const char* keyword) {
    // numpy.bool_ is no int, but converts to one (and to a float) as readily.
    const char* type = Py_TYPE(value.ptr())->tp_name;
    if (PyBool_Check(value.ptr()) || std::strcmp(type, "numpy.bool_") == 0 ||
        std::strcmp(type, "numpy.bool") == 0)
        throw py::type_error(std::string(keyword) + ": expected a number, not the bool " +
                             std::string(py::str(value)));
}

std::filesystem::path fs_path(py::handle path, const char* keyword) {
    const auto given = py::reinterpret_steal<py::object>(PyOS_FSPath(path.ptr()));
    if (!given) throw py::error_already_set();  // TypeError: not str, bytes or os.PathLike
    py::object encoded = given;
    if (PyUnicode_Check(given.ptr())) {
        encoded = py::reinterpret_steal<py::object>(PyUnicode_EncodeFSDefault(given.ptr()));
        if (!encoded) throw py::error_already_set();  // UnicodeEncodeError: names the character
    }
    char* bytes = nullptr;
    Py_ssize_t size = 0;
    if (PyBytes_AsStringAndSize(encoded.ptr(), &bytes, &size) != 0) throw py::error_already_set();
    const std::string native(bytes, static_cast<std::size_t>(size));
    if (native.find('\0') != std::string::npos)
        throw py::value_error(std::string(keyword) + ": " + std::string(py::repr(given)) +
                              " has a NUL character in it, which no file name can hold");
    return native;
}

py::str text(const std::string& bytes) {
    PyObject* decoded = PyUnicode_DecodeUTF8(bytes.data(), static_cast<Py_ssize_t>(bytes.size()),
                                             "backslashreplace");
    if (!decoded) throw py::error_already_set();
    return py::reinterpret_steal<py::str>(decoded);
}

py::str path_text(const std::filesystem::path& path) {
    const std::string& native = path.native();
    PyObject* decoded =
        PyUnicode_DecodeFSDefaultAndSize(native.data(), static_cast<Py_ssize_t>(native.size()));
    if (!decoded) throw py::error_already_set();
    return py::reinterpret_steal<py::str>(decoded);
}

void set_error(PyObject* type, const char* message) {
    PyObject* decoded = PyUnicode_DecodeUTF8(message, static_cast<Py_ssize_t>(std::strlen(message)),
                                             "backslashreplace");
    if (!decoded) return;  // (the decoder's own error stands)
    PyErr_SetObject(type, decoded);
    Py_DECREF(decoded);
}

namespace {

std::atomic<unsigned long> g_main_thread{0};

}  // namespace

void note_main_thread() {
    const py::object main = py::module_::import("threading").attr("main_thread")();
    g_main_thread.store(main.attr("ident").cast<unsigned long>());
}

void check_signals(int every_ms) {
    if (PyThread_get_thread_ident() != g_main_thread.load()) return;
    if (every_ms > 0) {
        // Only the main thread gets here, so one clock will do.
        using Clock = std::chrono::steady_clock;
        static Clock::time_point last;
        const Clock::time_point now = Clock::now();
        if (now - last < std::chrono::milliseconds(every_ms)) return;
        last = now;
    }
    py::gil_scoped_acquire held;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

}  // namespace py_rl
