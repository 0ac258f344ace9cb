"""rasterlab from Python: every lesson's renderer, pictures as numpy arrays.

    import rasterlab
    result = rasterlab.lesson07.render(normal_map="object")
    result.image          # H x W x 3 uint8, top row first (a view, no copy)
    result.counts         # what the program prints

The API is documented in docs/python.md.
"""

from . import _core
from ._core import Camera, Mesh, Result, load_mesh, read_image  # noqa: F401  (the package's API)
from ._labs import run_lab as _run_lab
from ._programs import LABS as _LABS, LESSONS as _LESSONS


def _add_lab(module, lesson):
    def lab(quick=True):
        return _run_lab(lesson, quick)

    lab.__doc__ = (f"Lesson {lesson}'s lab: runs its lab program (quick: few repetitions on "
                   "small inputs) and returns {table: rows}, each row a dict of the CSV's "
                   "columns.")
    module.lab = lab


# rasterlab.lesson00, rasterlab.lesson01, ...: the lessons python/CMakeLists.txt
# lists, each with its lab() if the lesson has a lab program.
for _lesson in _LESSONS:
    _module = getattr(_core, f"lesson{_lesson}")
    globals()[f"lesson{_lesson}"] = _module
    if _lesson in _LABS:
        _add_lab(_module, _lesson)
