"""Every Python example of docs/python.md runs as written (from the
project's root, where obj/ is), and prints what the page says it prints."""

import contextlib
import io
import os
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "python.md"


def examples():
    """(python source, the output the page shows for it or None), in order."""
    text = PAGE.read_text()
    blocks = list(re.finditer(r"```(\w*)\n(.*?)```", text, re.S))
    out = []
    for i, block in enumerate(blocks):
        if block.group(1) != "python":
            continue
        shown = None
        if i + 1 < len(blocks) and blocks[i + 1].group(1) == "":
            between = text[block.end():blocks[i + 1].start()]
            if between.strip().startswith("prints"):  # "prints, as the programs do,"
                shown = blocks[i + 1].group(2)
        out.append((block.group(2), shown))
    return out


@pytest.mark.parametrize("source,shown", examples(),
                         ids=lambda v: v.splitlines()[-1][:40] if v else "")
def test_page_example(source, shown):
    previous = os.getcwd()
    os.chdir(ROOT)
    try:
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            exec(compile(source, str(PAGE), "exec"), {})
    finally:
        os.chdir(previous)
    if shown is not None:
        assert printed.getvalue() == shown
