"""Each lab from Python: lessonNN.lab(quick=True) runs the lesson's lab in
quick mode and returns its tables as lists of dicts."""

import pytest

import rasterlab


def test_lesson01_lab_rows():
    tables = rasterlab.lesson01.lab(quick=True)
    assert list(tables) == ["01_lines"]
    rows = tables["01_lines"]
    methods = {row["method"] for row in rows}
    assert {"parametric", "dda", "bresenham", "wu"} <= methods
    timed = [row for row in rows if isinstance(row.get("ns_per_line"), float)]
    assert timed and all(row["ns_per_line"] > 0 for row in timed)


@pytest.mark.parametrize("lesson", ["02", "03", "04", "05", "06", "07", "08", "12"])
def test_every_lab_returns_tables(lesson):
    tables = getattr(rasterlab, f"lesson{lesson}").lab(quick=True)
    assert tables, f"lesson {lesson}'s lab wrote no table"
    for name, rows in tables.items():
        assert name.startswith(lesson) and rows, name
        assert all(isinstance(row, dict) and row for row in rows)
