"""Shared fixtures: the programs of this build, run the way a learner runs
them, so that every Python render can be compared with its program's file."""

import os
import pathlib
import subprocess

import pytest

import rasterlab

BUILD = pathlib.Path(os.environ.get("RASTERLAB_BUILD", "build")).resolve()

PROGRAMS = {
    "00": "00_framebuffer",
    "01": "01_lines",
    "02": "02_triangles",
    "03": "03_zbuffer",
    "04": "04_textures",
    "05": "05_perspective",
    "06": "06_shading",
    "07": "07_normal_mapping",
    "08": "08_shadows",
    "09": "09_environment",
    "10": "10_ambient_occlusion",
    "11": "11_antialiasing",
    "12": "12_fast",
}


def program_path(lesson):
    name = PROGRAMS[lesson]
    return BUILD / "lessons" / name / name


class Programs:
    def __init__(self, tmp_path):
        self.tmp = tmp_path

    def image(self, lesson, *args):
        """The program's picture for these arguments, read back as a Result."""
        out = self.tmp / f"{PROGRAMS[lesson]}_{len(list(self.tmp.iterdir()))}.tga"
        subprocess.run([str(program_path(lesson)), "-o", str(out), *map(str, args)],
                       check=True, capture_output=True, text=True)
        return rasterlab.read_image(str(out))

    def error(self, lesson, *args, output=None):
        """The message the program refuses these arguments with (its first line,
        without the program's name), with `-o output` (by default a file in a
        scratch folder). Bytes that are not UTF-8 (a file name) read as \\xff
        escapes, as the module shows them."""
        out = self.tmp / "refused.tga" if output is None else output
        run = subprocess.run([str(program_path(lesson)), "-o", str(out), *map(str, args)],
                             capture_output=True, text=True, errors="backslashreplace")
        assert run.returncode != 0, f"{PROGRAMS[lesson]} accepted {args}"
        first = run.stderr.splitlines()[0]
        prefix = f"{PROGRAMS[lesson]}: error: "
        return first[len(prefix):] if first.startswith(prefix) else first


@pytest.fixture
def programs(tmp_path):
    return Programs(tmp_path)
