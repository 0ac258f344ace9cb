// The Python module's keyword checks: each refuses what the program's command
// line refuses, with the message the program prints (CLI11's wording for
// ranges and choices, rasterlab's own for numbers), raised as ValueError.
// The option is named as the program spells it (--normal-map for the
// keyword normal_map), so that a message reads the same in both.
//
//   const auto method = py_rl::choice("--raster", raster, triangles::kRasterMethods);
//   py_rl::in_range("--width", width, 1, 16384);
//
// A numeric keyword is declared with its name in its type, so that the
// conversion from Python can refuse a bool (True is an int to Python, and
// width=True drew one pixel) naming the keyword:
//
//   [](py_rl::Int<"width"> width, py_rl::Real<"scale"> scale, py_rl::Numbers<"light"> light)
//
// Each converts to int, double or std::vector<double> where it is used.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
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

// ---------------------------------------------------------------------------
// Numbers that refuse a bool.

// A keyword's name as a template argument: Int<"width">.
template <std::size_t N>
struct Keyword {
    constexpr Keyword(const char (&text)[N]) { std::copy_n(text, N, name); }
    char name[N]{};
};

// An int or a float keyword (T is int or double).
template <class T, Keyword K>
struct Number {
    T value{};
    operator T() const { return value; }
};
template <Keyword K>
using Int = Number<int, K>;
template <Keyword K>
using Real = Number<double, K>;

// A sequence of numbers (a light direction, a point, lesson 04's turn).
template <Keyword K>
struct Numbers : std::vector<double> {};

// Raises TypeError naming the keyword if `value` is a bool (Python's or numpy's).
void refuse_bool(py::handle value, const char* keyword);

// ---------------------------------------------------------------------------
// Paths and text.

// A path argument (str, bytes or os.PathLike) as the file system takes it:
// a str is encoded as os.fsencode() does, so a name that is not UTF-8
// (os.fsdecode(b"\xff.obj")) reaches its file. A path with a NUL in it is
// refused with ValueError naming the keyword (no file name can hold one); a
// str that cannot be encoded raises UnicodeEncodeError.
std::filesystem::path fs_path(py::handle path, const char* keyword);

// A path parameter of a bound function (read_image, load_mesh, save).
struct Path : std::filesystem::path {};

// Text from C++ (a message, a warning) as a Python str: bytes that are not
// UTF-8 (from a file name) are shown as \xff escapes, so it always prints.
py::str text(const std::string& bytes);

// A path from C++ as Python's os functions give one (os.fsdecode): a str
// that names the same file when handed back.
py::str path_text(const std::filesystem::path& path);

// Sets the Python error `type` with a message from C++ (as text() decodes it).
void set_error(PyObject* type, const char* message);

// ---------------------------------------------------------------------------
// Ctrl-C.

// Called between the steps of a render, with the GIL released: on the main
// thread (the only one Python runs signal handlers on), takes the GIL for a
// moment and runs the pending handlers; a KeyboardInterrupt (or whatever a
// handler raises) is thrown as py::error_already_set. On any other thread it
// does nothing. `every_ms` > 0: at most one real check per so many
// milliseconds (for loops of short steps, such as lesson 12's frames).
void check_signals(int every_ms = 0);

// Remembers the interpreter's main thread (called when the module is imported).
void note_main_thread();

}  // namespace py_rl

namespace pybind11::detail {

template <class T, py_rl::Keyword K>
struct type_caster<py_rl::Number<T, K>> {
    using Value = py_rl::Number<T, K>;
    PYBIND11_TYPE_CASTER(Value, make_caster<T>::name);
    bool load(handle source, bool convert) {
        py_rl::refuse_bool(source, K.name);
        make_caster<T> number;
        if (!number.load(source, convert)) return false;
        value.value = cast_op<T>(std::move(number));
        return true;
    }
    static handle cast(const py_rl::Number<T, K>& source, return_value_policy policy,
                       handle parent) {
        return make_caster<T>::cast(source.value, policy, parent);
    }
};

template <py_rl::Keyword K>
struct type_caster<py_rl::Numbers<K>> {
    PYBIND11_TYPE_CASTER(py_rl::Numbers<K>, const_name("List[float]"));
    bool load(handle source, bool convert) {
        if (!isinstance<sequence>(source) || isinstance<bytes>(source) || isinstance<str>(source))
            return false;
        value.clear();
        for (const auto item : reinterpret_borrow<sequence>(source)) {
            const object element = item;
            py_rl::refuse_bool(element, K.name);
            make_caster<double> number;
            if (!number.load(element, convert)) return false;
            value.push_back(cast_op<double>(std::move(number)));
        }
        return true;
    }
    static handle cast(const py_rl::Numbers<K>& source, return_value_policy policy, handle parent) {
        return make_caster<std::vector<double>>::cast(source, policy, parent);
    }
};

template <>
struct type_caster<py_rl::Path> {
    PYBIND11_TYPE_CASTER(py_rl::Path, const_name("os.PathLike"));
    bool load(handle source, bool) {
        if (!isinstance<str>(source) && !isinstance<bytes>(source) &&
            !hasattr(source, "__fspath__"))
            return false;  // (TypeError: incompatible function arguments)
        static_cast<std::filesystem::path&>(value) = py_rl::fs_path(source, "path");
        return true;
    }
    static handle cast(const py_rl::Path& source, return_value_policy, handle) {
        return py_rl::path_text(source).release();
    }
};

}  // namespace pybind11::detail
