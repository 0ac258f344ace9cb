#!/usr/bin/env python3
"""Checks the calling example at the top of every header of lessons/ and
common/include against what the sources declare, as the compiler sees them
(libclang parses every header in one translation unit):

- every header has an example;
- each qualified name an example uses (pipeline::draw, rl::Image,
  shading::ShadingModel::phong, ...) is declared, whole path included;
- each call of a qualified function (textures::sample(a, b, c, d)) passes a
  number of arguments one of its overloads takes (defaults and packs counted).

    scripts/stage_examples.py [ROOT]     # exit 1 and list every problem
    scripts/stage_examples.py --selftest # proves stale examples are caught

The example is the header's opening comment, before `#pragma once`: its lines
indented by three spaces after `//` are code. Needs python3-clang-14
(scripts/setup.sh installs it).
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

import clang.cindex as ci

# Headers that need a library's own include paths or build settings to parse
# (Highway's per-target code, SDL, Mesa) are parsed too, with those paths.
PKG_CONFIG = ["stb", "sdl2", "osmesa", "egl"]
QUALIFIED = re.compile(r"\b([a-z_][a-z_0-9]*)((?:::[A-Za-z_]\w*)+)")


def headers(root):
    for base in ("lessons", "common/include"):
        yield from sorted((root / base).rglob("*.hpp"))


def example_of(header):
    lines = []
    for line in header.read_text(encoding="utf-8").splitlines():
        if line.startswith("#pragma once"):
            break
        if line.startswith("//   "):
            lines.append(line[5:])
    return lines


def compile_args(root):
    args = ["-x", "c++", "-std=c++20", f"-I{root / 'lessons'}", f"-I{root / 'common/include'}",
            f"-I{root / 'common/src'}"]
    for package in PKG_CONFIG:
        flags = subprocess.run(["pkg-config", "--cflags", package], capture_output=True,
                               text=True)
        if flags.returncode == 0:
            args += flags.stdout.split()
    return args


def parse(root):
    """One translation unit including every header; exits on a parse error."""
    source = "".join(f'#include "{h.resolve()}"\n' for h in headers(root))
    tu = ci.Index.create().parse("all_headers.cpp", args=compile_args(root),
                                 unsaved_files=[("all_headers.cpp", source)],
                                 options=ci.TranslationUnit.PARSE_SKIP_FUNCTION_BODIES)
    errors = [d for d in tu.diagnostics if d.severity >= ci.Diagnostic.Error]
    if errors:
        for d in errors[:20]:
            print(f"parse error: {d.location.file}:{d.location.line}: {d.spelling}")
        sys.exit(2)
    return tu


SCOPES = {"NAMESPACE", "STRUCT_DECL", "CLASS_DECL", "CLASS_TEMPLATE", "ENUM_DECL",
          "UNION_DECL", "CLASS_TEMPLATE_PARTIAL_SPECIALIZATION"}
CALLABLE = {"FUNCTION_DECL", "FUNCTION_TEMPLATE", "CXX_METHOD", "CONSTRUCTOR"}


def kind_name(cursor):
    try:
        return cursor.kind.name
    except ValueError:  # a kind this version of the bindings does not name
        return ""


def arity(cursor):
    """(fewest, most) arguments a function takes; most None with a pack."""
    fewest = most = 0
    for child in cursor.get_children():
        if kind_name(child) != "PARM_DECL":
            continue
        tokens = [t.spelling for t in child.get_tokens()]
        if "..." in tokens:
            return fewest, None
        most += 1
        if "=" not in tokens:
            fewest = most
    return fewest, most


def declarations(tu, root):
    """Every qualified name the repository's code declares -> its arities
    (empty for anything that is not a function)."""
    declared = {}
    top = set()
    aliases = set()  # their members are the aliased type's: not followed here

    def visit(cursor, scope):
        for child in cursor.get_children():
            location = child.location.file
            if location is None or not str(location.name).startswith(str(root)):
                continue
            kind = kind_name(child)
            name = child.spelling
            if kind == "NAMESPACE" and name and not scope:
                top.add(name)
            if not name or kind in ("PARM_DECL", "TEMPLATE_TYPE_PARAMETER",
                                    "TEMPLATE_NON_TYPE_PARAMETER", ""):
                continue
            path = scope + (name,)
            entry = declared.setdefault("::".join(path), [])
            if kind in ("TYPE_ALIAS_DECL", "TYPEDEF_DECL", "TYPE_ALIAS_TEMPLATE_DECL"):
                aliases.add("::".join(path))
            if kind in CALLABLE:
                entry.append(arity(child))
            if kind in SCOPES:
                visit(child, path)
                if kind == "ENUM_DECL" and not child.is_scoped_enum():
                    for constant in child.get_children():  # unscoped: also ns::constant
                        declared.setdefault("::".join(scope + (constant.spelling,)), [])

    visit(tu.cursor, ())
    return declared, top, aliases


def call_arguments(text, start):
    """The number of arguments of the call whose '(' is at text[start]."""
    depth, count, seen = 0, 0, False
    text = text[:start] + re.sub(r'"(?:[^"\\\n]|\\.)*"', '""', text[start:])  # commas in strings
    for i in range(start, len(text)):
        c = text[i]
        if c in "({[":
            depth += 1
            if depth == 1:
                continue
        elif c in ")}]":
            depth -= 1
            if depth == 0:
                return count + 1 if seen else 0
        elif c == "," and depth == 1:
            count += 1
        if depth >= 1 and not c.isspace():
            seen = True
    return None  # unbalanced: not checked


def skip_template_arguments(text, i):
    if i < len(text) and text[i] == "<":
        depth = 0
        for j in range(i, len(text)):
            depth += {"<": 1, ">": -1}.get(text[j], 0)
            if depth == 0:
                return j + 1
    return i


def problems(root):
    tu = parse(root)
    declared, top, aliases = declarations(tu, root)
    found = []
    for header in headers(root):
        name = header.relative_to(root)
        lines = example_of(header)
        if not lines:
            found.append(f"{name}: no usage example before #pragma once")
            continue
        text = "\n".join(lines)
        for m in QUALIFIED.finditer(text):
            if m.group(1) not in top:
                continue
            path = m.group(1) + m.group(2)
            parts = path.split("::")
            if any("::".join(parts[:k]) in aliases for k in range(2, len(parts))):
                continue  # a member of an alias (rl::mat3::identity): the alias is declared
            if path not in declared:
                found.append(f"{name}: example names {path}, which no source declares")
                continue
            overloads = declared[path]
            after = skip_template_arguments(text, m.end())
            if not overloads or after >= len(text) or text[after] != "(":
                continue
            given = call_arguments(text, after)
            if given is None:
                continue
            if not any(lo <= given and (hi is None or given <= hi) for lo, hi in overloads):
                takes = ", ".join(f"{lo}" if lo == hi else f"{lo}-{'any' if hi is None else hi}"
                                  for lo, hi in sorted(set(overloads), key=str))
                found.append(f"{name}: example calls {path} with {given} arguments; "
                             f"it takes {takes}")
    return found


def selftest(root):
    """Three stale examples, each in a copy of the sources, each caught."""
    breakages = [
        ("lessons/11_antialiasing/coverage.hpp", "antialiasing::resolve(",
         "antialiasing::resolve_samples(", "resolve_samples"),
        ("lessons/04_textures/sampling.hpp", "{du_dx, du_dy}, {textures::Filter::trilinear})",
         "{du_dx, du_dy})", "with 3 arguments"),
        ("lessons/06_shading/shaders.hpp", "shading::Uniforms u;", "shading::uniforms u;",
         "shading::uniforms"),
        ("lessons/06_shading/scene.hpp", "(Output::srgb, Weighting::angle, warnings)",
         "(Output::srgb, warnings)", "default_scene with 2 arguments"),
    ]
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        copy = pathlib.Path(tmp)
        for base in ("lessons", "common"):
            shutil.copytree(root / base, copy / base)
        if problems(copy):
            print("selftest: the copy already has problems")
            return 1
        for path, old, new, expected in breakages:
            header = copy / path
            text = header.read_text()
            if old not in text:
                print(f"selftest: {path} no longer holds {old!r}")
                return 1
            header.write_text(text.replace(old, new, 1))
            caught = problems(copy)
            header.write_text(text)
            if any(expected in line for line in caught):
                print(f"selftest: caught in {path}: {[l for l in caught if expected in l][0]}")
            else:
                print(f"selftest: NOT caught in {path} ({new!r}):", caught)
                failed += 1
    return 1 if failed else 0


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    if sys.argv[1:] == ["--selftest"]:
        return selftest(root)
    if sys.argv[1:]:
        root = pathlib.Path(sys.argv[1]).resolve()
    found = problems(root)
    for line in found:
        print(line)
    if found:
        return 1
    print("every header's example names only what the sources declare, with arguments they take")
    return 0


if __name__ == "__main__":
    sys.exit(main())
