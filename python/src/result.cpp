#include "result.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "keywords.hpp"
#include "rasterlab/file_io.hpp"
#include "rasterlab/image_io.hpp"

namespace py_rl {

namespace {

// A read-only array over a bottom-row-first grid, seen top row first: the
// first row of the view is the grid's last, and each next row sits one row
// *lower* in memory (a negative row stride), so no pixel is copied. `owner`
// keeps the Result (and so the grid) alive as long as the array.
template <class T, class Pixel>
py::array top_first_view(const rl::Grid<Pixel>& grid, std::vector<py::ssize_t> pixel_shape,
                         std::vector<py::ssize_t> pixel_strides, py::handle owner) {
    const py::ssize_t w = grid.width(), h = grid.height();
    const py::ssize_t row = w * static_cast<py::ssize_t>(sizeof(Pixel));
    std::vector<py::ssize_t> shape{h, w}, strides{-row, static_cast<py::ssize_t>(sizeof(Pixel))};
    shape.insert(shape.end(), pixel_shape.begin(), pixel_shape.end());
    strides.insert(strides.end(), pixel_strides.begin(), pixel_strides.end());
    const auto* last_row =
        reinterpret_cast<const T*>(grid.pixels().data() + static_cast<std::size_t>((h - 1) * w));
    py::array view(py::dtype::of<T>(), shape, strides, last_row, owner);
    view.attr("setflags")(py::arg("write") = false);
    return view;
}

}  // namespace

void bind_result(py::module_& m) {
    py::class_<Result>(m, "Result",
                       "A lesson's picture, its depth buffer (if the lesson keeps one), the "
                       "counts its program prints and the warnings it would print.")
        .def_property_readonly(
            "image",
            [](py::object self) {
                return top_first_view<std::uint8_t>(self.cast<const Result&>().colour, {3}, {1},
                                                    self);
            },
            "H x W x 3 uint8 RGB, top row first: a read-only view of the result's own pixels "
            "(no copy; its row stride is negative, as rasterlab stores the bottom row first)")
        .def_property_readonly(
            "rgba",
            [](py::object self) {
                return top_first_view<std::uint8_t>(self.cast<const Result&>().colour, {4}, {1},
                                                    self);
            },
            "H x W x 4 uint8 RGBA, top row first (a view, as image is)")
        .def_property_readonly(
            "depth",
            [](py::object self) -> py::object {
                const Result& r = self.cast<const Result&>();
                if (!r.depth) return py::none();
                return top_first_view<float>(*r.depth, {}, {}, self);
            },
            "H x W float32 window depth (0 near, 1 far or empty), top row first, or None where "
            "the lesson keeps no depth buffer (a view)")
        .def_property_readonly("width", [](const Result& r) { return r.colour.width(); })
        .def_property_readonly("height", [](const Result& r) { return r.colour.height(); })
        .def_property_readonly(
            "counts",
            [](const Result& r) {
                py::dict d;
                for (const auto& [name, value] : r.counts)
                    d[py::str(name)] = std::holds_alternative<std::string>(value)
                                           ? text(std::get<std::string>(value))  // a file name
                                           : py::cast(value);
                return d;
            },
            "What the program prints about the run (faces drawn, fragments shaded, ...)")
        .def_property_readonly(
            "warnings",
            [](const Result& r) {
                py::list out;
                for (const std::string& w : r.warnings) out.append(text(w));
                return out;
            },
            "The warnings the program would have printed (a missing texture, ...)")
        .def(
            "save",
            [](const Result& r, const Path& path) {
                py::gil_scoped_release unlocked;
                // The path first, as the programs check -o: a folder or a
                // device is named as such, not as "unknown image extension ''".
                rl::check_image_output(path);
                const std::vector<std::uint8_t> bytes = rl::encode_image(path, r.colour);
                check_signals();  // Ctrl-C while encoding: nothing is written
                rl::write_file_atomically(path, bytes);
            },
            py::arg("path"),
            "Writes the picture as the programs do (.tga or .png by the extension; never over "
            "a file this process has read)")
        .def("_repr_png_",
             [](const Result& r) {
                 const std::vector<std::uint8_t> png = rl::encode_image("result.png", r.colour);
                 return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
             })
        .def("__repr__", [](const Result& r) {
            return "<rasterlab.Result " + std::to_string(r.colour.width()) + "x" +
                   std::to_string(r.colour.height()) + (r.depth ? " with depth" : "") + ">";
        });
}

}  // namespace py_rl
