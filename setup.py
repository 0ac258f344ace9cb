"""Builds the package for pip: CMake configures the project for the Python
that runs pip (-DPython3_EXECUTABLE), builds the module and the lessons' lab
programs, and the package is the module's folder with the labs beside it.

    python3 -m pip install --no-build-isolation .       # into the active venv or user site

The CMake build lives in build-pip/ (RASTERLAB_PIP_BUILD_DIR overrides it),
kept between installs so that a second one only rebuilds what changed. The
lessons' models are read from this checkout's obj/ folder: keep it.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

ROOT = pathlib.Path(__file__).resolve().parent
BUILD = pathlib.Path(os.environ.get("RASTERLAB_PIP_BUILD_DIR", ROOT / "build-pip")).resolve()


def run(*args):
    print("rasterlab:", " ".join(str(a) for a in args), flush=True)
    subprocess.run([str(a) for a in args], check=True)


def lab_programs(package):
    """{lesson: path} of the labs the build's _programs.py names."""
    text = (package / "_programs.py").read_text()
    return dict(re.findall(r'"(\d\d)": "([^"]+)"', text))


def built_for(package):
    """The interpreter a build's module is for, or None if there is none yet."""
    programs = package / "_programs.py"
    found = re.search(r'^PYTHON = "([^"]*)"', programs.read_text(), re.M) if programs.exists() else None
    return found.group(1) if found else None


class BuildWithCMake(build_py):
    def run(self):
        built = BUILD / "python" / "rasterlab"
        # A build already made for this very interpreter (a venv's python is
        # its base's) is only brought up to date: `cmake --preset release`'s
        # build/ serves `RASTERLAB_PIP_BUILD_DIR=build pip install .`.
        previous = built_for(built)
        if not previous or os.path.realpath(previous) != os.path.realpath(sys.executable):
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            run("cmake", "-S", ROOT, "-B", BUILD, *generator, "-DCMAKE_BUILD_TYPE=Release",
                f"-DPython3_EXECUTABLE={sys.executable}")
        labs = [pathlib.Path(p).name for p in lab_programs(built).values()]
        jobs = str(os.cpu_count() or 1)
        run("cmake", "--build", BUILD, "--parallel", jobs, "--target", "rasterlab_python", *labs)
        package = pathlib.Path(self.build_lib) / "rasterlab"
        shutil.rmtree(package, ignore_errors=True)
        shutil.copytree(built, package, ignore=shutil.ignore_patterns("__pycache__"))
        (package / "labs").mkdir()
        for lab in lab_programs(built).values():
            shutil.copy2(lab, package / "labs")
        # The installed package names its labs beside it, not in the build.
        programs = package / "_programs.py"
        programs.write_text(re.sub(r'"(\d\d)": "[^"]*/([^"/]+)"', r'"\1": "labs/\2"',
                                   programs.read_text()))


class BinaryDistribution(Distribution):
    def has_ext_modules(self):  # a compiled module: a platform wheel, not a pure one
        return True


BUILD.mkdir(parents=True, exist_ok=True)
setup(
    packages=["rasterlab"],
    package_dir={"rasterlab": "python/rasterlab"},
    cmdclass={"build_py": BuildWithCMake},
    distclass=BinaryDistribution,
    options={"build": {"build_base": str(BUILD / "setuptools")},
             "egg_info": {"egg_base": str(BUILD)}},
    zip_safe=False,
)
