"""The module in a Python it was not built for, or one without numpy, says
which interpreter to use instead of failing deep inside an import."""

import pathlib
import re
import shutil
import subprocess
import sys

import rasterlab


def test_another_python_version_is_told_which_interpreter_to_use(tmp_path):
    package = tmp_path / "rasterlab"
    shutil.copytree(pathlib.Path(rasterlab.__file__).parent, package)
    programs = package / "_programs.py"
    programs.write_text(re.sub(r"PYTHON_VERSION = .*", "PYTHON_VERSION = (2, 7)",
                               programs.read_text()))
    run = subprocess.run([sys.executable, "-c", "import rasterlab"], cwd=tmp_path,
                         capture_output=True, text=True)
    assert run.returncode != 0
    assert "rasterlab was built for Python 2.7" in run.stderr
    assert f"this is Python {sys.version_info[0]}.{sys.version_info[1]}" in run.stderr


def test_a_python_without_numpy_is_told_which_interpreter_to_use():
    # -S: without site-packages, where numpy lives; the package found by path.
    folder = pathlib.Path(rasterlab.__file__).parent.parent
    run = subprocess.run([sys.executable, "-S", "-c",
                          f"import sys; sys.path.insert(0, {str(folder)!r}); import rasterlab"],
                         capture_output=True, text=True)
    assert run.returncode != 0
    assert "rasterlab needs numpy" in run.stderr
    assert "build/python/python3" in run.stderr
