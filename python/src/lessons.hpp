// One function per lesson that adds its submodule (rasterlab.lesson02, ...):
// the lesson's program in Python's terms, the program's options as keyword
// arguments with the program's defaults and its names for every method.
#pragma once

#include <pybind11/pybind11.h>

#include "lesson_list.hpp"  // made by python/CMakeLists.txt

namespace py_rl {

namespace py = pybind11;

// bind_lesson00(), bind_lesson01(), ...: one per lesson of python/CMakeLists.txt's list.
#define RASTERLAB_DECLARE_BIND(number, title) void bind_lesson##number(py::module_ m);
RASTERLAB_PYTHON_LESSONS(RASTERLAB_DECLARE_BIND)
#undef RASTERLAB_DECLARE_BIND

}  // namespace py_rl
