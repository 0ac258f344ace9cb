#!/usr/bin/env python3
"""The snippet checker itself: it must fail on a stale or missing region."""
import pathlib
import subprocess
import sys
import tempfile

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "doc_snippets.py"


def run(root, *flags):
    return subprocess.run([sys.executable, SCRIPT, "--root", root, *flags],
                          capture_output=True, text=True).returncode


with tempfile.TemporaryDirectory() as tmp:
    root = pathlib.Path(tmp)
    (root / "docs").mkdir()
    (root / "src.cpp").write_text("int a;\n    // [doc:part]\n    int b = 1;\n    // [/doc:part]\n")
    page = root / "docs" / "page.md"
    page.write_text("<!-- snippet: src.cpp#part -->\n```cpp\nint b = 0;\n```\n<!-- /snippet -->\n")
    assert run(root) == 1, "a stale snippet passed the check"
    assert run(root, "--fill") == 0
    assert "int b = 1;" in page.read_text(), page.read_text()
    assert run(root) == 0, "a filled snippet failed the check"
    page.write_text("<!-- snippet: src.cpp#gone -->\n<!-- /snippet -->\n")
    assert run(root) == 1, "a missing region passed the check"
print("doc_snippets self-test: ok")
