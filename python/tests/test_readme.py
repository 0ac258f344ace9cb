"""README.md's Python commands, exactly as written, run as a user runs them:
from a folder that holds the checkout (here a folder of links to it, so that
what they write stays out of the source tree), with whatever python3 comes
first on the PATH, no PYTHONPATH, and HOME in a scratch folder (the pip
commands make ~/rasterlab-env). The pip build reuses this build
(RASTERLAB_PIP_BUILD_DIR), made for the same interpreter, rather than
compiling everything again."""

import os
import pathlib
import re
import subprocess

from conftest import BUILD

ROOT = pathlib.Path(__file__).resolve().parents[2]


def python_commands():
    readme = (ROOT / "README.md").read_text()
    section = readme.split("## From Python", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```sh\n(.*?)```", section, re.S)
    lines = [line.split("  #", 1)[0].strip() for block in blocks for line in block.splitlines()]
    return [line for line in lines if line]


def test_the_readme_has_its_python_commands():
    commands = python_commands()
    assert any("render.py" in c for c in commands)
    assert any(c.startswith("PYTHONPATH=$PWD/build/python jupyter nbconvert") for c in commands)
    assert any("pip install" in c for c in commands)


def test_the_readme_python_commands_work_as_written(tmp_path):
    checkout = tmp_path / "rasterlab"
    checkout.mkdir()
    for entry in ROOT.iterdir():
        if entry.name != "build":
            (checkout / entry.name).symlink_to(entry)
    (checkout / "build").symlink_to(BUILD)
    home = tmp_path / "home"
    home.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env.update(HOME=str(home), RASTERLAB_PIP_BUILD_DIR=str(BUILD))
    for command in python_commands():
        run = subprocess.run(["bash", "-e", "-c", command], cwd=checkout, env=env,
                             capture_output=True, text=True, timeout=600)
        assert run.returncode == 0, f"{command}\n{run.stdout}\n{run.stderr}"
    assert (checkout / "out.png").stat().st_size > 0
    assert (checkout / "lessons.ipynb").stat().st_size > 0  # the executed notebook
    assert (home / "rasterlab-env" / "bin" / "python").exists()
