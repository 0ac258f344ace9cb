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
    <!-- /snippet -->

A page can also include a generated file verbatim (the labs' tables):

    <!-- include: docs/charts/01_lines.md -->
    ...the file's text...
    <!-- /include -->

--check (the default) fails when a page's copy is stale or names a region
that does not exist; --fill rewrites the pages' copies from the sources.
"""
import argparse
import pathlib
import re
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
LANGUAGES = {".cpp": "cpp", ".hpp": "cpp", ".cmake": "cmake", ".py": "python", ".sh": "bash"}


def region(path: pathlib.Path, name: str) -> str:
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
    return textwrap.dedent("\n".join(body)).strip("\n") + "\n"


def rendered(match: re.Match) -> str:
    source = ROOT / match.group("file")
    if not source.is_file():
        raise LookupError(f"no source file {match.group('file')}")
    code = region(source, match.group("region"))
    language = LANGUAGES.get(source.suffix, "")
    return f"{match.group(1)}```{language}\n{code}```\n{match.group(5)}"


def included(match: re.Match) -> str:
    source = ROOT / match.group("file")
    if not source.is_file():
        raise LookupError(f"no file {match.group('file')} to include")
    return f"{match.group(1)}{source.read_text()}{match.group(4)}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="fail on stale snippets (default)")
    mode.add_argument("--fill", action="store_true", help="rewrite snippets from the sources")
    parser.add_argument("--root", type=pathlib.Path, help="project root (default: this checkout)")
    options = parser.parse_args()
    global ROOT
    if options.root:
        ROOT = options.root.resolve()

    problems, count = [], 0
    for page in sorted((ROOT / "docs").glob("*.md")):
        text = page.read_text()
        try:
            updated = INCLUDE.sub(included, SNIPPET.sub(rendered, text))
        except LookupError as error:
            problems.append(f"{page.relative_to(ROOT)}: {error}")
            continue
        count += len(SNIPPET.findall(text)) + len(INCLUDE.findall(text))
        if updated != text:
            if options.fill:
                page.write_text(updated)
                print(f"filled {page.relative_to(ROOT)}")
            else:
                problems.append(f"{page.relative_to(ROOT)}: code differs from its source region")
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems and not options.fill:
        print("run scripts/doc_snippets.py --fill to update the pages", file=sys.stderr)
    print(f"{count} snippets checked")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
