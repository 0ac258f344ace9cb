#!/usr/bin/env python3
"""Keeps the code shown in docs/*.md identical to marked regions of the sources.

A source file marks a region with two comment lines:

    // [doc:name]
    ...code...
    // [/doc:name]

A page shows it between two HTML comments, which this script fills:

    <!-- snippet: common/src/tga.cpp#name -->
    ```cpp
    ...code, copied and dedented...
    ```
    From [common/src/tga.cpp, lines 12–20](../common/src/tga.cpp#L12-L20)
    <!-- /snippet -->

The line under the code links the excerpt to its source lines: the code host
opens the file there, and the docs site (site/hooks.py) to its own copy of it.

A page can also include a generated file verbatim (the labs' tables):

    <!-- include: docs/charts/01_lines.md -->
    ...the file's text...
    <!-- /include -->

A measured number in prose is a marked value, taken from a lab's table in
docs/charts/ by the row whose columns have the given values:

    ... takes <!-- value: docs/charts/02_triangles.md | method=edge |
    scene=small (10 px) | ns_per_triangle -->224<!-- /value --> ns ...

(on one line). A value can also be derived from two cells, so that a ratio
or a difference a sentence states follows the tables at every lab run: two
specs in brackets with `/` or `-` between them, the options after both:

    ... <!-- value: (docs/charts/12_sizes.md | size=1024 | renderer=lesson 07 |
    ms_per_frame) / (docs/charts/12_sizes.md | size=1024 | renderer=fast |
    ms_per_frame) | fmt=.1f -->15.3<!-- /value --> times faster ...

Optional last parts: `x=100` multiplies the number (per
million to per cent: `x=0.0001`), `fmt=.1f` formats it with Python's format
spec (`fmt=.0f`, `fmt=,.0f`, `fmt=.2g`), `agg=min` or `agg=max` takes the
least or greatest of the column over every row that matches (a range
"lo–hi" across sizes is two such values). A condition can also bound a
numeric column: `size=1024..` (1024 and up), `size=..2048`, `size=800..2048`.

--check (the default) fails when a page's copy or value is stale, names a
region, table, row or column that does not exist, or when a marked source
region is shown by no page. With --tests-from BUILD_DIR it also checks that
every test a page names where it says *Test:* (the pitfalls), and every test
in docs/robustness.md's case tables, exists in that build's CTest list.
A value marker must not start a line (even indented): a line that begins
`<!-- ` opens an HTML block, which ends the paragraph before it, so the code
host shows the sentence split in two. --check refuses such a line; --fill
joins it to the line before.

--fill rewrites the pages' copies and values from the sources.
"""
import argparse
import os
import math
import pathlib
import re
import subprocess
import sys
import textwrap

ROOT = pathlib.Path(__file__).resolve().parent.parent
MARKER = re.compile(r"^\s*//\s*\[(/?)doc:([\w.-]+)\]\s*$")
SNIPPET = re.compile(
    r"(<!-- snippet: (?P<file>[^#\s]+)#(?P<region>[\w.-]+) -->\n)"
    r"(?P<body>.*?)"
    r"(<!-- /snippet -->)",
    re.S,
)
INCLUDE = re.compile(
    r"(<!-- include: (?P<file>\S+) -->\n)(?P<body>.*?)(<!-- /include -->)",
    re.S,
)
VALUE = re.compile(
    r"<!-- value: (?P<spec>[^>]*?) -->(?P<body>[^<]*)<!-- /value -->",
)
LANGUAGES = {".cpp": "cpp", ".hpp": "cpp", ".h": "cpp", ".cmake": "cmake", ".py": "python", ".sh": "bash"}


def region(path: pathlib.Path, name: str) -> tuple:
    """The region's code, dedented, and its first and last line numbers."""
    lines = path.read_text().splitlines()
    start = end = None
    for number, line in enumerate(lines):
        match = MARKER.match(line)
        if match and match.group(2) == name:
            if match.group(1) == "":
                start = number
            else:
                end = number
    if start is None or end is None or end <= start:
        raise LookupError(f"{path.relative_to(ROOT)} has no complete region [doc:{name}]")
    body = [line for line in lines[start + 1 : end] if not MARKER.match(line)]
    return textwrap.dedent("\n".join(body)).strip("\n") + "\n", start + 2, end


def rendered(match: re.Match) -> str:
    file = match.group("file")
    source = ROOT / file
    if not source.is_file():
        raise LookupError(f"no source file {file}")
    code, first, last = region(source, match.group("region"))
    language = LANGUAGES.get(source.suffix, "")
    lines = f"line {first}" if first == last else f"lines {first}–{last}"
    link = f"From [{file}, {lines}](../{file}#L{first}-L{last})\n"
    return f"{match.group(1)}```{language}\n{code}```\n{link}{match.group(5)}"


def included(match: re.Match) -> str:
    source = ROOT / match.group("file")
    if not source.is_file():
        raise LookupError(f"no file {match.group('file')} to include")
    return f"{match.group(1)}{source.read_text()}{match.group(4)}"


def table_rows(path: pathlib.Path) -> list:
    """The rows of the first Markdown table in a file, as dicts by column."""
    rows, header = [], None
    for line in path.read_text().splitlines():
        if not line.startswith("|"):
            if header:
                break
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if header is None:
            header = cells
        elif not set(line) <= set("|-: "):
            rows.append(dict(zip(header, cells)))
    return rows


DERIVED = re.compile(r"^\((?P<a>.*)\)\s*(?P<op>[/-])\s*\((?P<b>.*)\)(?P<options>.*)$")


def split_spec(spec: str) -> list:
    # Inside a Markdown table a marker separates its fields with "\|", as a
    # bare "|" would split the table's cell.
    return [p.strip() for p in re.split(r"\\?\|", spec) if p.strip()]


def take_options(parts: list) -> dict:
    """Pops the trailing fmt=, x= and agg= parts off a spec's parts."""
    options = {}
    while parts and parts[-1].split("=", 1)[0] in ("fmt", "x", "agg"):
        key, text = parts.pop().split("=", 1)
        options[key] = text
    return options


def cell(parts: list, aggregate) -> str:
    """The text of one table cell: parts are the table, its conditions and
    the column. Conditions are key=value, or key=lo..hi (either end may be
    left out) for a range of rows; agg=min or agg=max takes the least or the
    greatest of the column over the rows (a range quoted as "lo–hi" is two
    such values)."""
    table, *conditions, column = parts
    source = ROOT / table
    if not source.is_file():
        raise LookupError(f"no table {table} for a value")
    tests = []
    for condition in conditions:
        key, wanted = condition.split("=", 1)
        bounds = re.fullmatch(r"(-?[\d.]*)\.\.(-?[\d.]*)", wanted)
        if bounds:  # key=lo..hi, either end left open: a numeric range
            lo = float(bounds.group(1)) if bounds.group(1) else -math.inf
            hi = float(bounds.group(2)) if bounds.group(2) else math.inf
            tests.append(lambda r, k=key, lo=lo, hi=hi: k in r and lo <= float(r[k]) <= hi)
        else:
            tests.append(lambda r, k=key, v=wanted: r.get(k) == v)
    rows = [r for r in table_rows(source) if all(test(r) for test in tests)]
    if aggregate not in (None, "min", "max"):
        raise LookupError(f"agg={aggregate}: only min or max")
    if not rows or (len(rows) != 1 and aggregate is None):
        raise LookupError(f"{len(rows)} rows of {table} match {conditions} (need exactly one,"
                          " or agg=min or agg=max)")
    if column not in rows[0]:
        raise LookupError(f"{table} has no column {column}")
    if aggregate:
        numbers = [float(r[column]) for r in rows]
        return repr(min(numbers) if aggregate == "min" else max(numbers))
    return rows[0][column]


def value(match: re.Match) -> str:
    spec = match.group("spec")
    derived = DERIVED.match(spec)
    if derived:  # (a) / (b) or (a) - (b): each side one cell, its own agg= allowed
        sides = []
        for side in (derived.group("a"), derived.group("b")):
            parts = split_spec(side)
            sides.append(float(cell(parts, take_options(parts).get("agg"))))
        options = take_options(split_spec(derived.group("options")))
        if derived.group("op") == "/":
            if sides[1] == 0:
                raise LookupError(f"a ratio over a zero cell: {spec}")
            number = sides[0] / sides[1]
        else:
            number = sides[0] - sides[1]
        number *= float(options.get("x", "1"))
        text = format(number, options.get("fmt", "g"))
        return f"<!-- value: {spec} -->{text}<!-- /value -->"
    parts = split_spec(spec)
    options = take_options(parts)
    aggregate = options.pop("agg", None)
    text = cell(parts, aggregate)
    if options or aggregate:
        number = float(text) * float(options.get("x", "1"))
        text = format(number, options.get("fmt", "g"))
    return f"<!-- value: {spec} -->{text}<!-- /value -->"


def source_regions() -> set:
    """Every (file, region) marked in the sources (build folders and this
    script, whose docstring shows a marker, left out)."""
    found = set()
    for folder, subfolders, files in os.walk(ROOT):
        subfolders[:] = [d for d in subfolders if not d.startswith(("build", "."))]
        for name in files:
            path = pathlib.Path(folder) / name
            if path.suffix not in LANGUAGES or path.resolve() == pathlib.Path(__file__).resolve():
                continue
            for line in path.read_text(errors="replace").splitlines():
                match = MARKER.match(line)
                if match and match.group(1) == "":
                    found.add((str(path.relative_to(ROOT)), match.group(2)))
    return found


def ctest_names(build_dir: pathlib.Path) -> list:
    listing = subprocess.run(["ctest", "--test-dir", str(build_dir), "-N"], capture_output=True,
                             text=True, check=True).stdout
    return [m.group(1) for m in re.finditer(r"Test +#\d+: (\S+)", listing)]


def test_pattern(name: str) -> re.Pattern:
    """`<lesson>` and `<method>` stand for any lesson or method, `*` for anything."""
    regex = re.escape(name)
    regex = regex.replace(re.escape("<lesson>"), r"[0-9a-z_]+")
    regex = regex.replace(re.escape("<method>"), r"[a-z]+")
    return re.compile(regex.replace(re.escape("*"), r".*"))


def named_tests(page: pathlib.Path, text: str) -> list:
    """(where, [names]) for every pitfall that says *Test:*, and for every row
    of robustness.md's case tables (their last cell names the tests)."""
    found = []
    for bullet in re.findall(r"^> - \*\*(.*?)(?=^> - \*\*|^(?!>))", text, re.S | re.M):
        title = bullet.split("**")[0]
        if "*Test:*" not in bullet:
            found.append((f"pitfall '{title}'", []))
            continue
        found.append((f"pitfall '{title}'",
                      re.findall(r"`([^`]+)`", bullet.split("*Test:*", 1)[1])))
    if page.name == "robustness.md" and "## Every case tried" in text:
        section = text.split("## Every case tried", 1)[1].split("### Fuzzing", 1)[0]
        for line in section.splitlines():
            if not line.startswith("|") or set(line) <= set("|-: "):
                continue
            cell = line.strip().strip("|").split("|")[-1].strip()
            if cell != "test":
                found.append((f"row '{line[:60]}'", re.findall(r"`([^`]+)`", cell)))
    return found


LEADING_VALUE = re.compile(r"^\s*<!-- value:")


def join_leading_values(text: str) -> str:
    """Each line that starts with a value marker, joined to the line before."""
    out = []
    for line in text.split("\n"):
        if LEADING_VALUE.match(line) and out and out[-1].strip():
            out[-1] = out[-1].rstrip() + " " + line.lstrip()
        else:
            out.append(line)
    return "\n".join(out)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="fail on stale snippets (default)")
    mode.add_argument("--fill", action="store_true", help="rewrite snippets from the sources")
    parser.add_argument("--root", type=pathlib.Path, help="project root (default: this checkout)")
    parser.add_argument("--tests-from", type=pathlib.Path, metavar="BUILD_DIR",
                        help="check the tests the pages name against this build's CTest list")
    options = parser.parse_args()
    global ROOT
    if options.root:
        ROOT = options.root.resolve()

    problems, count, values, used = [], 0, 0, set()
    tests = ctest_names(options.tests_from) if options.tests_from else None
    for page in sorted((ROOT / "docs").glob("*.md")):
        text = page.read_text()
        leading = [i + 1 for i, line in enumerate(text.split("\n")) if LEADING_VALUE.match(line)]
        if leading and options.fill:
            text = join_leading_values(text)
            page.write_text(text)
            print(f"joined line-leading value markers in {page.relative_to(ROOT)}")
        elif leading:
            problems.append(f"{page.relative_to(ROOT)}: line {', '.join(map(str, leading))} starts "
                            "with a value marker, which opens an HTML block and splits its "
                            "paragraph (join it to the line before)")
        used.update((m.group("file"), m.group("region")) for m in SNIPPET.finditer(text))
        if tests is not None:
            for where, names in named_tests(page, text):
                if not names:
                    problems.append(f"{page.relative_to(ROOT)}: {where} names no test")
                for name in names:
                    if not any(test_pattern(name).search(t) for t in tests):
                        problems.append(f"{page.relative_to(ROOT)}: {where}: no test {name}")
        try:
            updated = VALUE.sub(value, INCLUDE.sub(included, SNIPPET.sub(rendered, text)))
        except (LookupError, ValueError) as error:
            problems.append(f"{page.relative_to(ROOT)}: {error}")
            continue
        count += len(SNIPPET.findall(text)) + len(INCLUDE.findall(text))
        values += len(VALUE.findall(text))
        if updated != text:
            if options.fill:
                page.write_text(updated)
                print(f"filled {page.relative_to(ROOT)}")
            else:
                problems.append(f"{page.relative_to(ROOT)}: code or a value differs from its source")
    for file, region in sorted(source_regions() - used):
        problems.append(f"{file}: region [doc:{region}] is shown by no page")
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems and not options.fill:
        print("run scripts/doc_snippets.py --fill to update the pages", file=sys.stderr)
    print(f"{count} snippets and {values} values checked" +
          (f"; named tests checked against {len(tests)}" if tests is not None else ""))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
