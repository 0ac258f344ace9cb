"""rasterlab from Python: every lesson's renderer, pictures as numpy arrays.

    import rasterlab
    result = rasterlab.lesson07.render(normal_map="object")
    result.image          # H x W x 3 uint8, top row first (a view, no copy)
    result.counts         # what the program prints

The API is documented in docs/python.md.
"""

import sys as _sys

from ._programs import LABS as _LABS, LESSONS as _LESSONS
from ._programs import PYTHON as _BUILT_FOR, PYTHON_VERSION as _BUILT_VERSION

# An extension loads only into the Python version it was built for, and the
# module needs numpy: say which interpreter to use rather than fail deep
# inside an import.
if _sys.version_info[:2] != _BUILT_VERSION:
    raise ImportError(
        f"rasterlab was built for Python {_BUILT_VERSION[0]}.{_BUILT_VERSION[1]} ({_BUILT_FOR}); "
        f"this is Python {_sys.version_info[0]}.{_sys.version_info[1]} ({_sys.executable}). "
        f"Run it with {_BUILT_FOR} (build/python/python3 does), or install it into this "
        "Python: python3 -m pip install --no-build-isolation . (README.md)")
try:
    import numpy as _numpy  # noqa: F401
except ImportError:
    raise ImportError(
        f"rasterlab needs numpy, which this Python ({_sys.executable}) does not have. Run it "
        f"with {_BUILT_FOR}, which it was built for (build/python/python3 does), or install "
        "numpy into this one") from None

from . import _core  # noqa: E402
from ._core import Camera, Mesh, Result, load_mesh, read_image  # noqa: E402,F401  (the API)
from ._labs import run_lab as _run_lab  # noqa: E402


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
