#!/usr/bin/env python3
"""The site's browser check itself (site/check_site.py) must fail on each
breakage it claims to catch. It is run on a copy of the built site with one
breakage per page: a missing image, a link to an anchor that is not there, a
formula KaTeX cannot read, a formula left untypeset, a search index that
has lost a word, and what issue 34 found on the pages: a value marker shown as
text, a list run into the paragraph above it, table rows cut off from their
table, Markdown left in a table cell, a figure shown smaller than its own
width, and a code block cut at the right. Each must be named in the check's report, and the check must exit 1.

    tests/scripts/check_site_selftest.py SITE_DIR
"""
import json
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

CHECK = pathlib.Path(__file__).resolve().parents[2] / "site" / "check_site.py"
SKIP = 77
BROKEN_PAGES = ["01_lines.html", "02_triangles.html", "03_zbuffer.html", "04_textures.html"]


def first_formula(page: pathlib.Path) -> re.Match:
    match = re.search(r'<span class="arithmatex">(.*?)</span>', page.read_text(), re.S)
    if not match:
        sys.exit(f"check_site_selftest: {page.name} has no inline formula to break")
    return match


def break_site(site: pathlib.Path) -> list:
    """Breaks the copy; returns what the report must say of each breakage."""
    expected = []
    # An image that is gone: the picture does not load, and the browser says so.
    (site / "images" / "01_lines.png").unlink()
    expected += ["01_lines.html: image images/01_lines.png did not load",
                 "01_lines.html: console: Failed to load resource"]
    # A link to a heading that does not exist.
    page = site / "02_triangles.html"
    page.write_text(page.read_text().replace(
        "</article>", '<a href="03_zbuffer.html#no-such-heading">gone</a></article>', 1))
    expected.append("02_triangles.html: link to 03_zbuffer.html#no-such-heading: "
                    "no element #no-such-heading")
    # A formula KaTeX cannot read: a console error names it.
    page = site / "03_zbuffer.html"
    match = first_formula(page)
    text = page.read_text()
    page.write_text(text[:match.start(1)] + r"\(\frac{1}{\)" + text[match.end(1):])
    expected.append('03_zbuffer.html: console: KaTeX cannot typeset "\\frac{1}{"')
    # A formula the page leaves as raw TeX (not marked for the typesetter).
    page = site / "04_textures.html"
    match = first_formula(page)
    text = page.read_text()
    page.write_text(text[:match.start()] + "<span>" + match.group(1) + "</span>"
                    + text[match.end():])
    expected += ["04_textures.html: formula not typeset", "where 04_textures.md holds"]
    # What a page's Markdown can turn into when it goes wrong (issue 34).
    page = site / "02_triangles.html"
    page.write_text(page.read_text().replace("</article>", (
        # a "|" inside a value marker split its table cell
        "<table><tr><td>&lt;!-- value: docs/charts/12_sizes.md</td><td>**42**</td></tr></table>"
        # a list line directly under a caption line
        "<p>Where it breaks:\n- near the eye\n- far away</p>"
        # table rows after a blank line
        "<p>| 64 | 3.1 |\n| 128 | 6.0 |</p>"
        # a 2x crop squeezed into a quarter of the column
        '<img src="images/02_overdraw_edge.png" style="width: 20px">'
        # a code line that does not wrap, past the column
        '<pre><code style="white-space: pre">auto far_too_long = ' + "x" * 300 + ";</code></pre>"
        "</article>"), 1))
    expected += ["02_triangles.html: markup left in the text: <!-- value: docs/charts/12_sizes.md",
                 "02_triangles.html: a table cell holding markup: **42**",
                 "02_triangles.html: a list run into a paragraph: Where it breaks:",
                 "02_triangles.html: table rows shown as a paragraph: | 64 | 3.1 |",
                 "02_triangles.html: an image shown smaller than its own width: "
                 "02_overdraw_edge.png at 20 px",
                 "02_triangles.html: a code block cut at the right: auto far_too_long"]
    # A search index that has lost a word finds nothing for it.
    index = site / "search" / "search_index.json"
    entries = json.loads(index.read_text())
    for entry in entries["docs"]:
        for key in ("title", "text"):
            entry[key] = re.sub("bresenham", "a line method", entry[key], flags=re.I)
    index.write_text(json.dumps(entries))
    expected.append("search: no result for 'Bresenham'")
    return expected


def main() -> int:
    site = pathlib.Path(sys.argv[1])
    with tempfile.TemporaryDirectory() as folder:
        copy = pathlib.Path(folder) / "site"
        shutil.copytree(site, copy)
        expected = break_site(copy)
        run = subprocess.run([sys.executable, str(CHECK), str(copy), "--pages", *BROKEN_PAGES],
                             capture_output=True, text=True)
    if run.returncode == SKIP:
        print(run.stdout.strip())
        return SKIP
    report = run.stdout + run.stderr
    missing = [line for line in expected if line not in report]
    if run.returncode != 1 or missing:
        print(report)
        print(f"check_site_selftest: exit {run.returncode} (want 1); not reported: {missing}")
        return 1
    print(f"check_site_selftest: all {len(expected)} breakages reported")
    return 0


if __name__ == "__main__":
    sys.exit(main())
