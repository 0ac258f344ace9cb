#!/usr/bin/env python3
"""Checks the calling example at the top of every stage header against the
code: each qualified name it uses (perspective::draw, rl::Image,
shading::ShadingModel::phong, ...) must exist in the sources, so that an
example cannot go on naming a function or type that was renamed or removed.

    scripts/stage_examples.py [ROOT]     # exit 1 and list every stale name
    scripts/stage_examples.py --selftest # proves a stale name is caught

The example is the header's opening comment, before `#pragma once`: its
lines indented by three spaces after `//` are code.
"""
import pathlib
import re
import shutil
import sys
import tempfile

NAMESPACES = {"rl", "lines", "triangles", "zbuffer", "textures", "perspective", "shading",
              "normal_mapping", "tinyrenderer_port", "framebuffer", "assets"}
QUALIFIED = re.compile(r"\b([a-z_]+)::(?:[A-Za-z_]\w*::)*([A-Za-z_]\w*)")


def examples(root):
    for base in ("lessons", "common/include"):
        for header in sorted((root / base).rglob("*.hpp")):
            lines = []
            for line in header.read_text(encoding="utf-8").splitlines():
                if line.startswith("#pragma once"):
                    break
                if line.startswith("//   "):
                    lines.append(line[5:])
            yield header, lines


def code_words(root):
    words = set()
    for base in ("lessons", "common", "generator"):
        for path in (root / base).rglob("*"):
            if path.suffix not in (".hpp", ".cpp"):
                continue
            for line in path.read_text(encoding="utf-8").splitlines():
                stripped = line.strip()
                if stripped.startswith("//"):
                    continue
                words.update(re.findall(r"[A-Za-z_]\w*", stripped.split("//")[0]))
    return words


def stale(root):
    words = code_words(root)
    found = []
    for header, lines in examples(root):
        for number, line in enumerate(lines, 1):
            for m in QUALIFIED.finditer(line):
                if m.group(1) in NAMESPACES and m.group(2) not in words:
                    found.append(f"{header.relative_to(root)}: example names {m.group(0)}, "
                                 "which no source declares")
    return found


def selftest(root):
    with tempfile.TemporaryDirectory() as tmp:
        copy = pathlib.Path(tmp)
        for base in ("lessons", "common", "generator"):
            shutil.copytree(root / base, copy / base)
        if stale(copy):
            print("selftest: the copy already has stale examples")
            return 1
        header = copy / "lessons" / "05_perspective" / "render_target.hpp"
        text = header.read_text()
        header.write_text(text.replace("perspective::resolve(", "perspective::resolve_samples(", 1))
        caught = stale(copy)
        if not any("resolve_samples" in line for line in caught):
            print("selftest: a renamed function in an example was not caught:", caught)
            return 1
    print("selftest: a stale example is caught")
    return 0


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    if sys.argv[1:] == ["--selftest"]:
        return selftest(root)
    if sys.argv[1:]:
        root = pathlib.Path(sys.argv[1])
    found = stale(root)
    for line in found:
        print(line)
    if found:
        return 1
    print("every stage header's example names only what the sources declare")
    return 0


if __name__ == "__main__":
    sys.exit(main())
