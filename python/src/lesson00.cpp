// rasterlab.lesson00: the test card of 00_framebuffer.
#include <pybind11/stl.h>

#include "00_framebuffer/test_card.hpp"
#include "keywords.hpp"
#include "lessons.hpp"
#include "rasterlab/tga.hpp"
#include "result.hpp"
#include "scene_args.hpp"

namespace py_rl {

void bind_lesson00(py::module_ m) {
    m.def(
        "test_card",
        [](Int<"width"> width, Int<"height"> height, const std::string& misread) {
            check_size(width, height);
            const auto mistake = choice("--misread", misread, lesson00::kMisreadings);
            Result r;
            py::gil_scoped_release unlocked;
            const rl::Image card = lesson00::make_test_card(width, height);
            rl::TgaWriteOptions raw;
            raw.rle = false;
            r.count("raw_tga_bytes", rl::encode_tga(card, raw).size());
            r.count("rle_tga_bytes", rl::encode_tga(card, {}).size());
            r.colour =
                mistake == lesson00::Misreading::none ? card : lesson00::misread(card, mistake);
            return r;
        },
        py::kw_only(), py::arg("width") = 256, py::arg("height") = 256, py::arg("misread") = "none",
        "00_framebuffer's test card (or, with misread, the card as a decoder with that "
        "mistake shows it), and the sizes of its raw and RLE TGA files");
}

}  // namespace py_rl
