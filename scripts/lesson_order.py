#!/usr/bin/env python3
"""Checks that lessons stack in order: a file of lesson NN (and of its tests)
includes only common/ and lessons numbered NN or lower; and that no file
reaches into another lesson's lab/ (a lab is its lesson's own program: the
reference computations other lessons build on sit in that lesson's truths/).

    scripts/lesson_order.py [ROOT]            # exit 1 and list every offence
    scripts/lesson_order.py --selftest        # proves a bad include is caught

A lesson's own files are lessons/NN_name/** ; its tests are
tests/lessons/NN_name/** . An include names an earlier lesson by its folder
("02_triangles/raster.hpp"), so the folder's number is the lesson's.
"""
import pathlib
import re
import shutil
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s+"(\d\d)_[\w-]+/(lab/)?', re.M)
LESSON = re.compile(r"^(\d\d)_")


def offences(root: pathlib.Path):
    found = []
    for base in (root / "lessons", root / "tests" / "lessons"):
        if not base.is_dir():
            continue
        for folder in sorted(base.iterdir()):
            m = LESSON.match(folder.name)
            if not folder.is_dir() or not m:
                continue
            own = int(m.group(1))
            for path in sorted(folder.rglob("*")):
                if path.suffix not in (".hpp", ".cpp", ".h", ".cc"):
                    continue
                try:
                    text = path.read_text(encoding="utf-8", errors="replace")
                except FileNotFoundError:  # removed while the tree was read (a test's scratch file)
                    continue
                for inc in INCLUDE.finditer(text):
                    line = text.count("\n", 0, inc.start(1)) + 1
                    if int(inc.group(1)) > own:
                        found.append(f"{path.relative_to(root)}:{line}: lesson {own:02d} includes "
                                     f"lesson {inc.group(1)} (a later lesson)")
                    elif inc.group(2) and int(inc.group(1)) != own:
                        found.append(f"{path.relative_to(root)}:{line}: lesson {own:02d} includes "
                                     f"lesson {inc.group(1)}'s lab/ (share it from truths/)")
    return found


def selftest(root: pathlib.Path) -> int:
    with tempfile.TemporaryDirectory() as tmp:
        copy = pathlib.Path(tmp)
        shutil.copytree(root / "lessons", copy / "lessons")
        if offences(copy):
            print("selftest: the copy already has offences")
            return 1
        victim = copy / "lessons" / "02_triangles" / "raster.hpp"
        victim.write_text(victim.read_text() + '\n#include "05_perspective/pipeline.hpp"\n')
        caught = offences(copy)
        if len(caught) != 1 or "02_triangles/raster.hpp" not in caught[0]:
            print("selftest: a bad include in lesson 02 was not caught:", caught)
            return 1
        victim.write_text(victim.read_text().replace('"05_perspective/pipeline.hpp"',
                                                     '"01_lines/lab/line_measure.hpp"'))
        caught = offences(copy)
        if len(caught) != 1 or "lab/" not in caught[0]:
            print("selftest: an include of lesson 01's lab/ from lesson 02 was not caught:", caught)
            return 1
    print("selftest: a bad include is caught (a later lesson's, and another lesson's lab/)")
    return 0


def main() -> int:
    args = sys.argv[1:]
    root = pathlib.Path(__file__).resolve().parent.parent
    if args and args[0] == "--selftest":
        return selftest(root)
    if args:
        root = pathlib.Path(args[0])
    found = offences(root)
    for line in found:
        print(line)
    if found:
        print(f"{len(found)} include(s) out of order: a lesson may use only common/ and "
              "earlier lessons, and not their lab/ (docs/index.md#how-the-lessons-stack)")
        return 1
    print("every lesson includes only common/ and earlier lessons")
    return 0


if __name__ == "__main__":
    sys.exit(main())
