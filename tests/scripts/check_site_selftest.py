#!/usr/bin/env python3
"""The site's browser check itself (site/check_site.py) must fail on each
breakage it claims to catch. It is run on a copy of the built site with one
breakage per page: a missing image, a link to an anchor that is not there, a
formula KaTeX cannot read, a formula left untypeset, a search index that
has lost a word, and what issue 34 found on the pages: a value marker shown as
text, a list run into the paragraph above it, table rows cut off from their
table, Markdown left in a table cell, a figure shown smaller than its own
width, and a code block cut at the right; and what issue 59 found: inline
code broken at a hyphen, chart text that overlaps or runs over its axes, a
series drawn exactly under another, diagram text too small to read, a dark
opening picture and a lesson page over its budget of words. Each must be
named in the check's report, and the check must exit 1.

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
    # What issue 59 found. Inline code broken at a hyphen: the site's script
    # that keeps a code word whole is taken out, and a narrow paragraph holds
    # an option.
    script = site / "typeset.js"
    script.write_text(script.read_text().replace("  keepCodeWordsWhole();\n", ""))
    page = site / "03_zbuffer.html"
    page.write_text(page.read_text().replace("</article>", (
        '<p style="width: 6ch"><code>--tangents</code></p>'
        '<img src="charts/selftest_chart.svg" style="width: 600px">'
        '<img src="diagrams/selftest_diagram.svg" style="width: 600px">'
        "</article>"), 1))
    expected.append("03_zbuffer.html: inline code broken inside a word: --tangents")
    draw_figures(site)
    expected += ['03_zbuffer.html: figure text overlapping: charts/selftest_chart.svg: '
                 '"the first note" and "the second note"',
                 '03_zbuffer.html: figure text out of place: charts/selftest_chart.svg: '
                 '"a note that runs over the edge" runs over the edge of its axes',
                 "03_zbuffer.html: a chart's series hidden: charts/selftest_chart.svg: "
                 "a series in #1f77b4 lies exactly under one in #ff7f0e",
                 '03_zbuffer.html: figure text smaller than 8 px as shown: '
                 'diagrams/selftest_diagram.svg: "tiny"',
                 '03_zbuffer.html: figure text out of place: diagrams/selftest_diagram.svg: '
                 '"cut at the edge" cut at the figure\'s edge']
    # A dark, flat opening picture, put before the page's first.
    page = site / "04_textures.html"
    text = page.read_text()
    first = text.index("<img", text.index("<article"))
    page.write_text(text[:first] + '<img src="images/selftest_dark.png">' + text[first:])
    expected.append("04_textures.html: the opening picture selftest_dark.png is too dark or too flat")
    # A search index that has lost a word finds nothing for it.
    index = site / "search" / "search_index.json"
    entries = json.loads(index.read_text())
    for entry in entries["docs"]:
        for key in ("title", "text"):
            entry[key] = re.sub("bresenham", "a line method", entry[key], flags=re.I)
    index.write_text(json.dumps(entries))
    expected.append("search: no result for 'Bresenham'")
    return expected


def draw_figures(site: pathlib.Path) -> None:
    """A chart and a diagram drawn as the project draws them (matplotlib,
    text as glyphs), each with the faults the check must find, and a dark
    picture."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy

    figure, axes = plt.subplots(figsize=(6, 4))
    axes.plot([0, 1, 2], [0, 1, 4], label="shown")      # C0, #1f77b4: hidden under the next
    axes.plot([0, 1, 2], [0, 1, 4], label="over it")    # C1, #ff7f0e
    axes.text(0.5, 2, "the first note", fontsize=10)
    axes.text(0.55, 2.05, "the second note", fontsize=10)
    axes.text(0.9, 0.5, "a note that runs over the edge", transform=axes.transAxes, fontsize=10)
    axes.legend()
    figure.savefig(site / "charts" / "selftest_chart.svg")
    plt.close(figure)
    figure, axes = plt.subplots(figsize=(6, 4))
    axes.set_axis_off()
    axes.text(0.5, 0.5, "tiny", fontsize=3)
    axes.text(1.05, 0.2, "cut at the edge", transform=axes.transAxes, fontsize=10)
    figure.savefig(site / "diagrams" / "selftest_diagram.svg")
    plt.close(figure)
    plt.imsave(site / "images" / "selftest_dark.png", numpy.full((64, 64, 3), 0.05))


def pad_page(docs: pathlib.Path) -> None:
    """A lesson page over its budget: 9 000 words more, no formula."""
    page = docs / "01_lines.md"
    page.write_text(page.read_text() + "\n" + "word " * 9000 + "\n")


def main() -> int:
    site = pathlib.Path(sys.argv[1])
    with tempfile.TemporaryDirectory() as folder:
        copy = pathlib.Path(folder) / "site"
        shutil.copytree(site, copy)
        expected = break_site(copy)
        docs = pathlib.Path(folder) / "docs"
        shutil.copytree(CHECK.parents[1] / "docs", docs, ignore=shutil.ignore_patterns("*.png", "*.svg"))
        pad_page(docs)
        expected.append("words, over a lesson page's budget of 8000")
        run = subprocess.run([sys.executable, str(CHECK), str(copy), "--docs", str(docs),
                              "--pages", *BROKEN_PAGES], capture_output=True, text=True)
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
