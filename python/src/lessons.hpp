// One function per lesson that adds its submodule (rasterlab.lesson02, ...):
// the lesson's program in Python's terms, the program's options as keyword
// arguments with the program's defaults and its names for every method.
#pragma once

#include <pybind11/pybind11.h>

namespace py_rl {

namespace py = pybind11;

void bind_lesson00(py::module_ m);
void bind_lesson01(py::module_ m);
void bind_lesson02(py::module_ m);
void bind_lesson03(py::module_ m);
void bind_lesson04(py::module_ m);
void bind_lesson05(py::module_ m);
void bind_lesson06(py::module_ m);
void bind_lesson07(py::module_ m);
void bind_lesson08(py::module_ m);
void bind_lesson12(py::module_ m);

}  // namespace py_rl
