#!/usr/bin/env python3
"""Checks docs/robustness.md against the tests: every row of its case tables
names at least one test, and every test name it gives exists in CTest's list
(`<lesson>` and `<method>` stand for any lesson or method, `*` for anything).

  check_robustness_doc.py BUILD_DIR      (run by CTest as docs_robustness_names_tests)
"""
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PAGE = ROOT / "docs" / "robustness.md"


def ctest_names(build_dir):
    listing = subprocess.run(["ctest", "--test-dir", build_dir, "-N"], capture_output=True,
                             text=True, check=True).stdout
    return [m.group(1) for m in re.finditer(r"Test +#\d+: (\S+)", listing)]


def pattern(name):
    regex = re.escape(name)
    regex = regex.replace(re.escape("<lesson>"), r"[0-9a-z_]+")
    regex = regex.replace(re.escape("<method>"), r"[a-z]+")
    regex = regex.replace(re.escape("*"), r".*")
    return re.compile(regex)


def case_rows(text):
    """The last cell of every table row below '## Every case tried'."""
    section = text.split("## Every case tried", 1)[1].split("### Fuzzing", 1)[0]
    for line in section.splitlines():
        if not line.startswith("|") or set(line) <= set("|- "):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[-1] == "test":
            continue
        yield line, cells[-1]


def main():
    names = ctest_names(sys.argv[1])
    problems = []
    rows = 0
    for line, cell in case_rows(PAGE.read_text()):
        rows += 1
        tests = re.findall(r"`([^`]+)`", cell)
        if not tests:
            problems.append("a row names no test: " + line[:100])
        for test in tests:
            if not any(pattern(test).search(n) for n in names):
                problems.append("no such test: " + test)
    for problem in problems:
        print("docs/robustness.md: " + problem)
    print("%d rows checked against %d tests" % (rows, len(names)))
    return 1 if problems or rows == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
