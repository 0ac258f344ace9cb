"""Each lesson's lab from Python: `rasterlab.lesson02.lab(quick=True)` runs
the lesson's lab program (the project's own: in its build folder, or in the
package's labs/ folder once installed with pip) and
returns its tables, read from the CSV files it writes, as lists of dicts."""

import csv
import pathlib
import subprocess
import tempfile

from ._programs import LABS


def _value(text):
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def run_lab(lesson, quick=True):
    """Runs lesson `lesson`'s lab (quick: few repetitions on small inputs, as
    CI runs it; otherwise in full, minutes) and returns {table: rows}, one
    table per CSV file the lab writes, each row a dict of its columns (numbers
    as int or float). Raises RuntimeError with the lab's own message if it
    fails."""
    program = pathlib.Path(__file__).parent / LABS[lesson]  # (an absolute path stays itself)
    with tempfile.TemporaryDirectory(prefix="rasterlab-lab-") as out:
        args = [str(program), "--out", out] + (["--quick"] if quick else [])
        run = subprocess.run(args, capture_output=True, text=True)
        if run.returncode != 0:
            raise RuntimeError(f"{pathlib.Path(program).name} failed: {run.stderr.strip()}")
        tables = {}
        for path in sorted(pathlib.Path(out).glob("*.csv")):
            with open(path, newline="") as f:
                tables[path.stem] = [{k: _value(v) for k, v in row.items()}
                                     for row in csv.DictReader(f)]
        return tables
