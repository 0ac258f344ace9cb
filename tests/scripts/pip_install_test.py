#!/usr/bin/env python3
"""Installs rasterlab with pip into a fresh virtual environment, offline, as
README.md says, and runs the examples with that environment's python:

    pip_install_test.py BUILD_DIR

The venv sees the system's packages (numpy from python3-numpy); pip builds
through setup.py with RASTERLAB_PIP_BUILD_DIR=BUILD_DIR, which this build has
already made for this interpreter, so the wheel is packed without compiling
again. Exit 77 (skipped) without the venv module or pip.
"""
import os
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    build = pathlib.Path(sys.argv[1]).resolve()
    try:
        import ensurepip  # noqa: F401  (python3-venv)
        import venv  # noqa: F401
    except ImportError:
        print("skipped: this Python has no venv/ensurepip (Debian: python3-venv)")
        return 77
    work = build / "pip-test"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir()
    env_dir = work / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", env_dir], check=True)
    python = env_dir / "bin" / "python"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # the venv's package only
    env["RASTERLAB_PIP_BUILD_DIR"] = str(build)
    subprocess.run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index",
                    "--quiet", ROOT], check=True, env=env, cwd=work)
    # The package imported is the installed one, and its labs are inside it.
    where = subprocess.run([python, "-c", "import rasterlab; print(rasterlab.__file__)"],
                           check=True, env=env, cwd=work, capture_output=True, text=True)
    if not where.stdout.startswith(str(env_dir)):
        print("rasterlab was not imported from the venv:", where.stdout)
        return 1
    subprocess.run([python, ROOT / "python/examples/render.py", work / "out.png"], check=True,
                   env=env, cwd=work)
    if not (work / "out.png").stat().st_size:
        print("render.py wrote nothing")
        return 1
    lab = subprocess.run(
        [python, "-c", "import rasterlab; t = rasterlab.lesson02.lab(quick=True); "
         "print(sorted(t)); assert t['02_triangles']"],
        check=True, env=env, cwd=work, capture_output=True, text=True)
    print("installed into", env_dir, "; lesson 02's lab from the package:", lab.stdout.strip())
    return 0


if __name__ == "__main__":
    sys.exit(main())
