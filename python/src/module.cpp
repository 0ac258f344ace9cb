// rasterlab's Python module (rasterlab._core; the package rasterlab re-exports
// it): every lesson's renderer from Python, pictures as numpy arrays. The
// API is documented in docs/python.md.
#include <pybind11/pybind11.h>

#include "keywords.hpp"
#include "lessons.hpp"
#include "rasterlab/checkpoint.hpp"
#include "rasterlab/file_io.hpp"
#include "rasterlab/image_io.hpp"
#include "result.hpp"
#include "scene_args.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
    m.doc() = "rasterlab: a CPU software rasterizer built one stage per lesson (C++ core)";
    // A file the lessons cannot read or write: OSError, with the message the
    // programs print (it starts with the file's path); a refused option
    // (std::invalid_argument): ValueError. A file name that is not UTF-8
    // shows its bytes as \xff escapes (PyErr_SetString would have left the
    // message empty).
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const rl::FileError& e) {
            py_rl::set_error(PyExc_OSError, e.what());
        } catch (const std::invalid_argument& e) {
            py_rl::set_error(PyExc_ValueError, e.what());
        }
    });
    py_rl::note_main_thread();
    // Inside a frame too: the pipeline calls this between bands of a
    // triangle's rows and lesson 12 between tiles, so Ctrl-C stops a render
    // within about 50 ms plus one band's or tile's time.
    rl::set_checkpoint_hook([] { py_rl::check_signals(50); });
    py_rl::bind_result(m);
    py_rl::bind_scene_args(m);
    m.def(
        "read_image",
        [](const py_rl::Path& path) {
            py_rl::Result r;
            {
                py::gil_scoped_release unlocked;
                r.colour = rl::load_image(path);
            }
            return r;
        },
        py::arg("path"), "Reads a TGA, PNG or JPG file as the lessons do, as a Result");
    // rasterlab.lesson00, rasterlab.lesson01, ...: python/CMakeLists.txt's list.
#define RASTERLAB_BIND(number, title) \
    py_rl::bind_lesson##number(m.def_submodule("lesson" #number, title));
    RASTERLAB_PYTHON_LESSONS(RASTERLAB_BIND)
#undef RASTERLAB_BIND
}
