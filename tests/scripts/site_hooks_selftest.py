#!/usr/bin/env python3
"""The site's hooks (site/hooks.py) read only the repository's files, write only
into the site folder, and cap what they copy. Each case builds a small stand-in
repository (the real mkdocs.yml with a nav of two pages, the real site/ folder,
a few sources and images) with `mkdocs build --strict`, in a fresh folder of its
own, laid out so that a hook following a hostile link would write inside that
folder where the check sees it (never into the real /etc or /tmp):

    <case>/etc/passwd, <case>/secret-...   files outside the repository
    <case>/a/b/repo/                       the stand-in repository
    <case>/a/b/repo/build/site/            the site folder
    <case>/a/tmp/                          TMPDIR for the build

A legal page (a source file with a line range, a PNG and an SVG of obj/, a
Markdown file of obj/) must build, and every hostile one must fail, naming the
page, the link and the cause, with nothing written outside the site folder (the
test's whole folder is listed before and after, and the folder around it for the
names the hostile links use) and nothing of the outside files in the site:

- a traversal, ../../../../etc/passwd, and an absolute path, ..//<case>/etc/passwd;
- a symbolic link in the repository to a file outside it, and one to a folder;
- a page and an image of docs/ that are symbolic links to files outside the repository;
- a 64 MiB .png (sparse), a 2 MiB source file (sparse): over the caps;
- a text file named .png, an HTML file named .svg, a binary file as a source page;
- a symbolic link inside the site folder that leads out of it.

    tests/scripts/site_hooks_selftest.py [--mkdocs PATH] [--hooks PATH] [--case NAME]...

--hooks tries another hooks.py in place of site/hooks.py (to see this test fail
on a hooks file without the checks). Exit 0 when every case holds, 1 when one
does not, 77 (skipped) without mkdocs or without the site's packages.
"""
import argparse
import os
import pathlib
import re
import shutil
import stat
import struct
import subprocess
import sys
import tempfile
import zlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
SKIP = 77
MARKER = "SECRET-OUTSIDE-THE-REPOSITORY-7f3a"  # in every file outside the repository


def png(width: int = 1, height: int = 1) -> bytes:
    """A small valid PNG (grey)."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    rows = b"".join(b"\0" + b"\x80" * width for _ in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def sparse(path: pathlib.Path, size: int, head: bytes = b"") -> None:
    with open(path, "wb") as file:
        file.write(head)
        file.truncate(size)


def config_text() -> str:
    """The real mkdocs.yml with a nav of the stand-in's two pages."""
    text = (ROOT / "mkdocs.yml").read_text()
    nav = "nav:\n  - Home: index.md\n  - Lessons:\n      - 01 Lines: 01_lines.md\n"
    text, count = re.subn(r"(?ms)^nav:\n.*?(?=^\S)", nav, text)
    if count != 1 or "site/hooks.py" not in text:
        sys.exit("site_hooks_selftest: mkdocs.yml has no nav or no site/hooks.py to copy")
    return text


LEGAL_PAGE = """# Home

The code: [a line range](../lessons/01_lines/main.cpp#L2-L3). The models' notes:
[notes](../obj/README.md).

![a globe](../obj/globe.png)

![a diagram](../obj/diagram.svg)
"""


def make_case(base: pathlib.Path, hooks: pathlib.Path) -> dict:
    """The stand-in repository and its surroundings, in a case folder of their own."""
    case = pathlib.Path(tempfile.mkdtemp(prefix="case-", dir=base))
    repo = case / "a" / "b" / "repo"
    for folder in ["docs", "site", "lessons/01_lines", "obj", "build"]:
        (repo / folder).mkdir(parents=True)
    (case / "a" / "tmp").mkdir()
    (case / "etc").mkdir()
    (case / "etc" / "passwd").write_text(f"root:x:0:0:{MARKER}\n")
    (case / "secret-outside.cpp").write_text(f"int secret = 1; // {MARKER}\n")
    (case / "secret-outside.md").write_text(f"# Outside\n\n{MARKER}\n")
    (case / "outside-folder").mkdir()
    (case / "outside-folder" / "notes.md").write_text(f"# Notes\n\n{MARKER}\n")
    (case / "elsewhere").mkdir()

    (repo / "mkdocs.yml").write_text(config_text())
    shutil.copyfile(hooks, repo / "site" / "hooks.py")
    for name in ["typeset.js", "site.css"]:
        shutil.copyfile(ROOT / "site" / name, repo / "site" / name)
    (repo / "docs" / "index.md").write_text(LEGAL_PAGE)
    (repo / "docs" / "01_lines.md").write_text("# 01 Lines\n\nA line, $y = mx + c$.\n")
    (repo / "lessons" / "01_lines" / "main.cpp").write_text(
        "// the lesson\nint main() {\n    return 0;\n}\n")
    (repo / "obj" / "globe.png").write_bytes(png(4, 4))
    (repo / "obj" / "diagram.svg").write_text(
        '<?xml version="1.0"?>\n<!-- drawn by hand -->\n'
        '<svg xmlns="http://www.w3.org/2000/svg" width="4" height="4"></svg>\n')
    (repo / "obj" / "README.md").write_text("# The models\n\nA globe.\n")
    return {"case": case, "repo": repo, "site": repo / "build" / "site", "tmp": case / "a" / "tmp"}


def snapshot(folder: pathlib.Path, leave_out: pathlib.Path) -> dict:
    """Every entry under folder but leave_out and what is under it: a file's
    kind, size and time, a folder's kind only (its time changes with what is
    made and removed in it, such as the build's temporary folder)."""
    entries = {}
    for top, dirs, names in os.walk(folder):
        top = pathlib.Path(top)
        if top == leave_out or leave_out in top.parents:
            dirs[:] = []
            continue
        for name in dirs + names:
            if top / name == leave_out:
                continue
            info = os.lstat(top / name)
            entries[str((top / name).relative_to(folder))] = (
                (info.st_mode,) if stat.S_ISDIR(info.st_mode)
                else (info.st_mode, info.st_size, info.st_mtime_ns))
    return entries


def hostile_names(folder: pathlib.Path) -> set:
    """The entries of the folder around the cases named like a hostile link's target."""
    return {name for name in os.listdir(folder)
            if "passwd" in name or "secret" in name or "notes" in name or name == "etc"}


def build(mkdocs: str, tree: dict) -> subprocess.CompletedProcess:
    env = dict(os.environ, TMPDIR=str(tree["tmp"]), PYTHONDONTWRITEBYTECODE="1")
    return subprocess.run([mkdocs, "build", "--strict", "--config-file",
                           str(tree["repo"] / "mkdocs.yml"), "--site-dir", str(tree["site"])],
                          cwd=tree["repo"], env=env, capture_output=True, text=True, timeout=300)


def site_files_with_marker(site: pathlib.Path) -> list:
    found = []
    if site.is_dir() and not site.is_symlink():
        for top, _, names in os.walk(site):
            for name in names:
                path = pathlib.Path(top) / name
                if not path.is_symlink() and path.is_file() and path.stat().st_size < (64 << 20):
                    if MARKER.encode() in path.read_bytes():
                        found.append(str(path.relative_to(site)))
    return found


# Each hostile case: what it adds to the stand-in (given its folders), and what
# the build's report must say. A case may leave mkdocs itself to refuse.
def traversal(t):
    (t["repo"] / "docs" / "hostile.md").write_text("# Hostile\n\n[users](../../../../etc/passwd)\n")
    return ["hostile.md links to ../../../../etc/passwd, which leaves the repository"]


def absolute(t):
    target = f'{t["case"]}/etc/passwd'
    (t["repo"] / "docs" / "hostile.md").write_text(f"# Hostile\n\n[users](..//{target.lstrip('/')})\n")
    return [f"hostile.md links to ..//{target.lstrip('/')}, which leaves the repository"]


def symlink_to_file(t):
    (t["repo"] / "lessons" / "01_lines" / "leak.cpp").symlink_to(t["case"] / "secret-outside.cpp")
    (t["repo"] / "docs" / "hostile.md").write_text("# Hostile\n\n[code](../lessons/01_lines/leak.cpp)\n")
    return ["hostile.md links to ../lessons/01_lines/leak.cpp, which goes through a symbolic link "
            f"to {os.path.realpath(t['case'] / 'secret-outside.cpp')}, outside the repository"]


def symlink_to_folder(t):
    (t["repo"] / "lessons" / "shared").symlink_to(t["case"] / "outside-folder")
    (t["repo"] / "docs" / "hostile.md").write_text("# Hostile\n\n[notes](../lessons/shared/notes.md)\n")
    return ["hostile.md links to ../lessons/shared/notes.md, which goes through a symbolic link "
            f"to {os.path.realpath(t['case'] / 'outside-folder' / 'notes.md')}, outside the repository"]


def docs_symlink(t):
    (t["repo"] / "docs" / "leak.md").symlink_to(t["case"] / "secret-outside.md")
    return ["docs/leak.md goes through a symbolic link to "
            f"{os.path.realpath(t['case'] / 'secret-outside.md')}, outside the repository"]


def docs_image_symlink(t):
    (t["repo"] / "docs" / "pictures").mkdir()
    (t["repo"] / "docs" / "pictures" / "leak.png").symlink_to(t["case"] / "etc" / "passwd")
    return ["docs/pictures/leak.png goes through a symbolic link to "
            f"{os.path.realpath(t['case'] / 'etc' / 'passwd')}, outside the repository"]


def huge_image(t):
    sparse(t["repo"] / "obj" / "huge.png", 64 << 20, png())
    (t["repo"] / "docs" / "hostile.md").write_text("# Hostile\n\n![big](../obj/huge.png)\n")
    return ["hostile.md links to ../obj/huge.png, which is too large: over 20971520 bytes "
            "(MAX_IMAGE_BYTES"]


def huge_source(t):
    sparse(t["repo"] / "lessons" / "01_lines" / "big.cpp", 2 << 20, b"// big\n")
    (t["repo"] / "docs" / "hostile.md").write_text("# Hostile\n\n[big](../lessons/01_lines/big.cpp)\n")
    return ["hostile.md links to ../lessons/01_lines/big.cpp, which is too large: over 1048576 "
            "bytes (MAX_SOURCE_PAGE_BYTES"]


def text_as_png(t):
    (t["repo"] / "obj" / "fake.png").write_text("not an image\n")
    (t["repo"] / "docs" / "hostile.md").write_text("# Hostile\n\n![fake](../obj/fake.png)\n")
    return ["hostile.md links to ../obj/fake.png as an image, but it is not a PNG image"]


def html_as_svg(t):
    (t["repo"] / "obj" / "fake.svg").write_text("<html><script>alert(1)</script></html>\n")
    (t["repo"] / "docs" / "hostile.md").write_text("# Hostile\n\n![fake](../obj/fake.svg)\n")
    return ["hostile.md links to ../obj/fake.svg as an image, but it is not an SVG image"]


def binary_source(t):
    (t["repo"] / "obj" / "model.bin").write_bytes(b"\x00\xff\xfe\x80 binary")
    (t["repo"] / "docs" / "hostile.md").write_text("# Hostile\n\n[model](../obj/model.bin)\n")
    return ["hostile.md links to ../obj/model.bin, which is not UTF-8 text"]


def site_symlink(t):
    t["site"].mkdir(parents=True)
    (t["site"] / "source").symlink_to(t["case"] / "elsewhere")
    return ["source/lessons/01_lines/main.cpp.md would be written to "
            f"{os.path.realpath(t['case'] / 'elsewhere')}/lessons/01_lines/main.cpp.html, "
            "outside the site folder"]


HOSTILE = [traversal, absolute, symlink_to_file, symlink_to_folder, docs_symlink,
           docs_image_symlink, huge_image, huge_source, text_as_png, html_as_svg, binary_source,
           site_symlink]


def check_legal(tree: dict) -> list:
    site = tree["site"]
    problems = []
    code = site / "source" / "lessons" / "01_lines" / "main.cpp.html"
    if not code.is_file() or 'id="L2"' not in code.read_text():
        problems.append("no source page with line anchors for lessons/01_lines/main.cpp")
    for name in ["globe.png", "diagram.svg"]:
        copy = site / "source" / "obj" / name
        if not copy.is_file() or copy.read_bytes() != (tree["repo"] / "obj" / name).read_bytes():
            problems.append(f"obj/{name} not copied as it is to source/obj/{name}")
    if not (site / "source" / "obj" / "index.html").is_file():  # MkDocs: README is index
        problems.append("no page for obj/README.md")
    index = (site / "index.html").read_text() if (site / "index.html").is_file() else ""
    for link in ["source/lessons/01_lines/main.cpp.html#L2", "source/obj/globe.png"]:
        if link not in index:
            problems.append(f"index.html does not link to {link}")
    return problems


def run_case(mkdocs: str, base: pathlib.Path, hooks: pathlib.Path, name: str, setup) -> tuple:
    """(problems, the build's report) of one case: setup None is the legal build."""
    outer, around_folder = base.parent, base.parent.parent
    tree = make_case(base, hooks)
    expected = setup(tree) if setup else []
    before, around = snapshot(outer, tree["site"]), hostile_names(around_folder)
    run = build(mkdocs, tree)
    report = run.stdout + run.stderr
    after = snapshot(outer, tree["site"])
    problems = []
    written = sorted(path for path in after if before.get(path) != after[path])
    removed = sorted(set(before) - set(after))
    if written or removed:
        problems.append(f"written outside the site folder: {written + removed}")
    new_around = hostile_names(around_folder) - around
    if new_around:
        problems.append(f"written beside the test's folder, in {around_folder}: "
                        f"{sorted(new_around)}")
    leaked = site_files_with_marker(tree["site"])
    if leaked:
        problems.append(f"files from outside the repository published in the site: {leaked}")
    if setup is None:
        if run.returncode != 0:
            problems.append(f"the legal build failed (exit {run.returncode})")
        else:
            problems += check_legal(tree)
    else:
        if run.returncode == 0:
            problems.append("the build succeeded")
        problems += [f"the report does not say: {line}" for line in expected if line not in report]
    shutil.rmtree(tree["case"])
    return problems, report


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mkdocs", default=shutil.which("mkdocs"))
    parser.add_argument("--hooks", type=pathlib.Path, default=ROOT / "site" / "hooks.py")
    parser.add_argument("--case", action="append", choices=[case.__name__ for case in HOSTILE],
                        help="try only this hostile case (after the legal build); repeatable")
    args = parser.parse_args()
    hostile = [case for case in HOSTILE if not args.case or case.__name__ in args.case]
    if not args.mkdocs or not shutil.which(args.mkdocs):
        print("site_hooks_selftest: skipped: mkdocs is not installed (scripts/setup.sh site)")
        return SKIP
    # A folder of its own inside a folder of its own: what lands beside it is seen.
    with tempfile.TemporaryDirectory(prefix="site-hooks-selftest-") as outer:
        base = pathlib.Path(outer).resolve() / "cases"
        base.mkdir()
        problems, report = run_case(args.mkdocs, base, args.hooks, "legal", None)
        if problems and ("KaTeX is not installed" in report or "Unrecognised theme" in report
                         or "No module named" in report):
            print(report.strip())
            print("site_hooks_selftest: skipped: the site's packages are missing "
                  "(scripts/setup.sh site)")
            return SKIP
        failed = 0
        for name, setup in [("legal", None)] + [(case.__name__, case) for case in hostile]:
            if setup is not None:
                problems, report = run_case(args.mkdocs, base, args.hooks, name, setup)
            if problems:
                failed += 1
                print(f"FAIL {name}:\n  " + "\n  ".join(problems))
                print("  the build said:\n    " + "\n    ".join(
                    line for line in report.splitlines()
                    if "ERROR" in line or "Error" in line or "Aborted" in line or "WARNING" in line))
            else:
                print(f"ok   {name}")
    if failed:
        print(f"site_hooks_selftest: {failed} of {len(hostile) + 1} cases failed")
        return 1
    print(f"site_hooks_selftest: the legal build and all {len(hostile)} hostile cases hold")
    return 0


if __name__ == "__main__":
    sys.exit(main())
