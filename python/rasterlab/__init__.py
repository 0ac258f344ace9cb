"""rasterlab from Python: every lesson's renderer, pictures as numpy arrays.

    import rasterlab
    result = rasterlab.lesson07.render(normal_map="object")
    result.image          # H x W x 3 uint8, top row first (a view, no copy)
    result.counts         # what the program prints

The API is documented in docs/python.md.
"""

from ._core import (  # noqa: F401  (the package's API)
    Camera,
    Mesh,
    Result,
    load_mesh,
    read_image,
    lesson00,
    lesson01,
    lesson02,
    lesson03,
    lesson04,
    lesson05,
    lesson06,
    lesson07,
    lesson08,
    lesson12,
)
from ._labs import run_lab as _run_lab


def _add_lab(module, lesson):
    def lab(quick=True):
        return _run_lab(lesson, quick)

    lab.__doc__ = (f"Lesson {lesson}'s lab: runs its lab program (quick: few repetitions on "
                   "small inputs) and returns {table: rows}, each row a dict of the CSV's "
                   "columns.")
    module.lab = lab


for _lesson, _module in [("01", lesson01), ("02", lesson02), ("03", lesson03),
                         ("04", lesson04), ("05", lesson05), ("06", lesson06),
                         ("07", lesson07), ("08", lesson08), ("12", lesson12)]:
    _add_lab(_module, _lesson)
