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
    # ...with a link to the region's lines under the code.
    assert "From [src.cpp, line 3](../src.cpp#L3-L3)\n<!-- /snippet -->" in page.read_text()
    assert run(root) == 0, "a filled snippet failed the check"
    # The same code moved down a line: the link's line numbers are stale.
    source = (root / "src.cpp").read_text()
    (root / "src.cpp").write_text("// a new first line\n" + source)
    assert run(root) == 1, "a snippet whose source lines moved passed the check"
    (root / "src.cpp").write_text(source)
    page.write_text("<!-- snippet: src.cpp#gone -->\n<!-- /snippet -->\n")
    assert run(root) == 1, "a missing region passed the check"

    # A region no page shows fails the check.
    page.write_text("no snippets here\n")
    assert run(root) == 1, "an unused region passed the check"

    # Values come from a table's row; a stale one fails, --fill mends it.
    (root / "docs" / "charts").mkdir()
    (root / "docs" / "charts" / "t.md").write_text(
        "| method | scene | ns |\n|---|---|---|\n| a | big (1 px) | 12.5 |\n| b | big (1 px) | 99 |\n")
    shown = ("<!-- snippet: src.cpp#part -->\n```cpp\nint b = 1;\n```\n"
             "From [src.cpp, line 3](../src.cpp#L3-L3)\n<!-- /snippet -->\n")
    stale = "takes <!-- value: docs/charts/t.md | method=a | scene=big (1 px) | ns -->11<!-- /value --> ns\n"
    page.write_text(shown + stale)
    assert run(root) == 1, "a stale value passed the check"
    assert run(root, "--fill") == 0
    assert "-->12.5<!--" in page.read_text(), page.read_text()
    assert run(root) == 0, "a filled value failed the check"
    page.write_text(shown + stale.replace("| ns -->", "| ns | fmt=.0f -->"))
    assert run(root, "--fill") == 0 and "-->12<!--" in page.read_text(), page.read_text()
    page.write_text(shown + stale.replace("method=a", "method=c"))
    assert run(root) == 1, "a value from no row passed the check"

    # A value marker starting a line splits its paragraph: refused, and --fill
    # joins it to the line before.
    page.write_text(shown + "takes\n<!-- value: docs/charts/t.md | method=a | scene=big (1 px) | ns -->12.5<!-- /value --> ns\n")
    assert run(root) == 1, "a line-leading value marker passed the check"
    assert run(root, "--fill") == 0
    assert "takes <!-- value:" in page.read_text(), page.read_text()
    assert run(root) == 0, "a joined value marker failed the check"

    # A derived value: the ratio or the difference of two cells, kept up to
    # date with the table like any other (99 / 12.5 = 7.92, 99 - 12.5 = 86.5).
    a = "docs/charts/t.md | method=b | scene=big (1 px) | ns"
    b = "docs/charts/t.md | method=a | scene=big (1 px) | ns"
    page.write_text(shown + f"<!-- value: ({a}) / ({b}) | fmt=.2f -->8<!-- /value --> times, "
                    f"<!-- value: ({a}) - ({b}) | fmt=.1f -->0<!-- /value --> ns more\n")
    assert run(root) == 1, "a stale ratio passed the check"
    assert run(root, "--fill") == 0
    assert "-->7.92<!--" in page.read_text() and "-->86.5<!--" in page.read_text(), page.read_text()
    assert run(root) == 0, "a filled ratio failed the check"
    page.write_text(shown + f"<!-- value: ({a}) / ({b.replace('method=a', 'method=c')}) -->1<!-- /value -->\n")
    assert run(root) == 1, "a ratio over no row passed the check"
print("doc_snippets self-test: ok")
