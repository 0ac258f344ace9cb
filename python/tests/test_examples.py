"""The examples run as a learner runs them: render.py writes lesson 07's
picture, and the notebook executes headless with every cell's picture drawn."""

import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import rasterlab

EXAMPLES = pathlib.Path(__file__).resolve().parents[1] / "examples"


def test_render_script_writes_lesson07s_picture(programs, tmp_path):
    out = tmp_path / "render.png"
    run = subprocess.run([sys.executable, str(EXAMPLES / "render.py"), str(out)],
                         capture_output=True, text=True, env=os.environ)
    assert run.returncode == 0, run.stderr
    assert "wrote" in run.stdout and "of the pixels change" in run.stdout
    assert np.array_equal(rasterlab.read_image(out).image, programs.image("07").image)


def test_notebook_runs_headless(tmp_path):
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    notebook = nbformat.read(EXAMPLES / "lessons.ipynb", as_version=4)
    assert all(not cell.get("outputs") for cell in notebook.cells if cell.cell_type == "code"), \
        "the notebook is committed without outputs"
    nbclient.NotebookClient(notebook, timeout=300, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}}).execute()
    pictures = 0
    for cell in notebook.cells:
        for output in cell.get("outputs", []):
            assert output.output_type != "error", output
            png = output.get("data", {}).get("image/png")
            if png:
                assert len(png) > 1000, "an empty picture"
                pictures += 1
    # Each lesson's cell draws one figure of its two pictures and one chart (lesson 03 its
    # depth buffer too).
    assert pictures == 7 * 2 + 1
