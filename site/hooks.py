"""MkDocs hooks that turn docs/ into a site that works offline (mkdocs.yml).

The pages are written for the code host first: they link to the project's
sources with paths that leave docs/ (`../lessons/01_lines/main.cpp#L40-L42`),
show a few images from obj/, and count on the host to typeset `$...$`. The
site has none of that, so these hooks

- give every file outside docs/ that a page links to a page of its own under
  source/ (the code with numbered, anchored lines: `#L40` works as on the code
  host), copy the images a page shows from outside docs/ beside it, and point
  the pages' links there;
- serve KaTeX from Debian's libjs-katex and the script that typesets with it
  (site/typeset.js), so nothing is fetched from the network when a page is
  read;
- refuse a nav that leaves out a lesson's page or lists the lessons out of
  order;
- leave out what is not a page: docs/CMakeLists.txt, and the lab tables of
  docs/charts/*.md, which each page already includes where it refers to them.

The build reads only the repository's files and writes only into the site
folder (and its own temporary folder): a link that leaves the repository
(`../../../../etc/passwd`), or goes through a symbolic link to a file outside
it, is refused, as is a file of docs/ that is such a link; every file's
destination must resolve inside the site folder. What it copies is capped
(MAX_SOURCE_PAGE_BYTES, MAX_IMAGE_BYTES, MAX_DOCS_FILE_BYTES), and an image
must be one by its first bytes. A refusal raises PluginError from on_files,
which ends every build, strict or not, before anything is written to the site
folder (a logged error would end only a --strict build, and only once every
page had been written); docs/robustness.md lists the cases and
tests/scripts/site_hooks_selftest.py tries them.
"""
import os
import pathlib
import posixpath
import re
import stat
import tempfile

from mkdocs.exceptions import PluginError
from mkdocs.structure.files import File
from pygments import highlight
from pygments.formatters import HtmlFormatter
from pygments.lexers import get_lexer_for_filename
from pygments.util import ClassNotFound

ROOT = pathlib.Path(__file__).resolve().parent.parent
KATEX = pathlib.Path("/usr/share/javascript/katex")
SOURCE = "source"  # where the files from outside docs/ go in the site
# The caps on what the site takes from the repository (docs/robustness.md):
MAX_SOURCE_PAGE_BYTES = 1 << 20  # a file from outside docs/ shown as a page (code, Markdown)
MAX_IMAGE_BYTES = 20 << 20  # an image from outside docs/ (the largest of obj/ is 1 MB)
MAX_DOCS_FILE_BYTES = 20 << 20  # any file of docs/ itself, which MkDocs copies or renders
# What an image's first bytes must be, by its name: a .png must be a PNG.
IMAGE_SIGNATURES = {
    ".png": ("a PNG", (b"\x89PNG\r\n\x1a\n",)),
    ".jpg": ("a JPEG", (b"\xff\xd8\xff",)),
    ".jpeg": ("a JPEG", (b"\xff\xd8\xff",)),
    ".gif": ("a GIF", (b"GIF87a", b"GIF89a")),
}
# An SVG: an XML declaration, comments and a doctype at most before <svg.
SVG_START = re.compile(
    rb"(\xef\xbb\xbf)?\s*(<\?xml[^>]*>\s*)?((<!--.*?-->|<!DOCTYPE[^>]*>)\s*)*<svg[\s>]", re.S)
IMAGES = set(IMAGE_SIGNATURES) | {".svg"}
# A Markdown link or image whose target leaves docs/: ](../path#anchor)
OUTSIDE_LINK = re.compile(r"\]\(\.\./(?P<path>[^)\s#]+)(?P<anchor>#[^)\s]*)?\)")
# The code host's line ranges (#L40-L42) become the site's line anchors (#L40).
LINE_RANGE = re.compile(r"^#L(\d+)(-L\d+)?$")

_generated = None  # the folder the generated pages live in during a build


def _inside(path: pathlib.Path, folder: pathlib.Path) -> bool:
    """Whether a path, its symbolic links followed, is in a folder (itself resolved)."""
    return pathlib.Path(os.path.realpath(path)).is_relative_to(folder)


def _regular_file_inside(path: pathlib.Path, goes: str, not_a_file: str):
    """(the resolved path, its stat) of a regular file of the repository;
    refuses one reached through a symbolic link leading outside it ("<goes>
    through a symbolic link to ..."), or anything but a regular file."""
    real = pathlib.Path(os.path.realpath(path))
    if not real.is_relative_to(ROOT):
        raise PluginError(f"{goes} through a symbolic link to {real}, outside the "
                          f"repository {ROOT}: the site takes only the repository's files")
    try:
        info = os.stat(real)
    except OSError:
        info = None
    if info is None or not stat.S_ISREG(info.st_mode):
        raise PluginError(not_a_file)
    return real, info


def _check_docs_file(path: pathlib.Path) -> None:
    """Refuses a file of docs/ that is a symbolic link to a file outside the
    repository, is not a regular file or is over MAX_DOCS_FILE_BYTES."""
    name = os.path.relpath(path, ROOT)
    _, info = _regular_file_inside(path, f"{name} goes", f"{name} is not a regular file")
    if info.st_size > MAX_DOCS_FILE_BYTES:
        raise PluginError(f"{name} is too large: over {MAX_DOCS_FILE_BYTES} bytes "
                          "(MAX_DOCS_FILE_BYTES, for a file of docs/)")


def _repository_file(page: str, path: str, image: bool) -> bytes:
    """The bytes of the file a page links to as ../path: a regular file of the
    repository, reached without leaving it (no '..', no symbolic link to a file
    outside it), of at most MAX_IMAGE_BYTES for an image, MAX_SOURCE_PAGE_BYTES
    for a file shown as a page."""
    link = f"{page} links to ../{path}"
    parts = path.split("/")
    if path.startswith("/") or ".." in parts:
        raise PluginError(f"{link}, which leaves the repository {ROOT}: the site takes only "
                          "the repository's files")
    if "" in parts or "." in parts or "\0" in path:
        raise PluginError(f"{link}: not a plain path (an empty or '.' part, a NUL)")
    real, info = _regular_file_inside(ROOT / path, f"{link}, which goes",
                                      f"{link}, which is not a file")
    limit, name = ((MAX_IMAGE_BYTES, "MAX_IMAGE_BYTES, for an image") if image else
                   (MAX_SOURCE_PAGE_BYTES, "MAX_SOURCE_PAGE_BYTES, for a file shown as a page"))
    if info.st_size > limit:
        raise PluginError(f"{link}, which is too large: over {limit} bytes ({name})")
    with open(real, "rb") as file:  # no more than it held when measured
        data = file.read(info.st_size + 1)
    if len(data) != info.st_size:
        raise PluginError(f"{link}, which changed while the site was built")
    return data


def _check_image(page: str, path: str, data: bytes) -> None:
    """An image must be one by its first bytes, of the kind its name says."""
    suffix = pathlib.PurePosixPath(path).suffix.lower()
    if suffix == ".svg":
        kind, ok = "an SVG", SVG_START.match(data[:4096]) is not None
    else:
        kind, signatures = IMAGE_SIGNATURES[suffix]
        ok = data.startswith(signatures)
    if not ok:
        raise PluginError(f"{page} links to ../{path} as an image, but it is not {kind} "
                          f"image (it starts with {data[:8]!r})")


def _outside_targets(docs_dir: pathlib.Path) -> dict:
    """Every file outside docs/ that a page links to, with the pages that do
    and the file's bytes, checked (_repository_file, _check_image)."""
    targets = {}
    for page in sorted(docs_dir.glob("*.md")):
        _check_docs_file(page)
        for match in OUTSIDE_LINK.finditer(page.read_text()):
            path = match.group("path")
            if path not in targets:
                suffix = pathlib.PurePosixPath(path).suffix.lower()
                data = _repository_file(page.name, path, suffix in IMAGES)
                if suffix in IMAGES:
                    _check_image(page.name, path, data)
                targets[path] = (data, [])
            targets[path][1].append(page.name)
    return targets


def _text(page: str, path: str, data: bytes) -> str:
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        raise PluginError(f"{page} links to ../{path}, which is not UTF-8 text "
                          f"(byte {error.start}): a source page shows text only") from None


def _title(page: str) -> str:
    """A docs page's own title: its first heading."""
    for line in (ROOT / "docs" / page).read_text().splitlines():
        if line.startswith("# "):
            return line[2:].strip()
    return page


def _code_page(path: str, text: str, pages: list) -> str:
    """A page that shows one source file with anchored line numbers."""
    try:
        lexer = get_lexer_for_filename(path, stripnl=False)
    except ClassNotFound:
        lexer = get_lexer_for_filename("plain.txt", stripnl=False)
    formatter = HtmlFormatter(linenos="inline", lineanchors="L", cssclass="highlight", wrapcode=True)
    code = highlight(text, lexer, formatter)
    # Pygments names its anchors L-40; the code host's are L40.
    code = re.sub(r'(id|name|href)="(#?)L-(\d+)"', r'\1="\2L\3"', code)
    back = ", ".join(f"[{_title(name)}](/{name})" for name in sorted(set(pages)))
    return (f"# {path}\n\nQuoted on: {back}. The file as it stands in the project, "
            f"line by line.\n\n<div class=\"source-file\" markdown=\"0\">{code}</div>\n")


def _site_name(path: str) -> str:
    """Where a file from outside docs/ goes in the docs: an image or a Markdown
    page as it is, any other file as a page that shows it."""
    suffix = pathlib.PurePosixPath(path).suffix.lower()
    return f"{SOURCE}/{path}" if suffix in IMAGES or suffix == ".md" else f"{SOURCE}/{path}.md"


def on_files(files, config):
    global _generated
    docs_dir = pathlib.Path(config["docs_dir"])
    for file in list(files):
        if file.src_uri == "CMakeLists.txt" or (
                file.src_uri.startswith("charts/") and file.src_uri.endswith(".md")):
            files.remove(file)

    # Everything is read and checked before anything is written.
    for file in files:
        if pathlib.Path(file.abs_src_path).is_relative_to(docs_dir):
            _check_docs_file(pathlib.Path(file.abs_src_path))
    contents = {}
    for path, (data, pages) in _outside_targets(docs_dir).items():
        suffix = pathlib.PurePosixPath(path).suffix.lower()
        if suffix in IMAGES:
            contents[_site_name(path)] = data
        elif suffix == ".md":  # a Markdown file is a page as it is
            contents[_site_name(path)] = _text(pages[0], path, data).encode()
        else:
            text = _code_page(path, _text(pages[0], path, data), pages)
            contents[_site_name(path)] = text.encode()

    _generated = tempfile.TemporaryDirectory(prefix="rasterlab-site-")
    generated = pathlib.Path(os.path.realpath(_generated.name))
    for name, data in contents.items():
        target = generated / name
        if not _inside(target, generated):  # cannot be: _repository_file refuses '..'
            raise PluginError(f"{name} would be written to {os.path.realpath(target)}, outside "
                              f"the build's temporary folder {generated}")
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
        files.append(File(name, str(generated), config["site_dir"], config["use_directory_urls"]))

    if not (KATEX / "katex.min.js").is_file():
        raise PluginError(f"KaTeX is not installed ({KATEX}): scripts/setup.sh site installs "
                          "libjs-katex")
    for path in ["katex.min.js", "katex.min.css"]:
        files.append(File(f"katex/{path}", str(KATEX.parent), config["site_dir"],
                          config["use_directory_urls"]))
    for font in sorted((KATEX / "fonts").iterdir()):
        files.append(File(f"katex/fonts/{font.name}", str(KATEX.parent), config["site_dir"],
                          config["use_directory_urls"]))
    for name in ["typeset.js", "site.css"]:
        files.append(File(name, str(ROOT / "site"), config["site_dir"],
                          config["use_directory_urls"]))

    # Nothing is written outside the site folder, a symbolic link in it included.
    site_dir = pathlib.Path(os.path.realpath(config["site_dir"]))
    for file in files:
        if not _inside(pathlib.Path(file.abs_dest_path), site_dir):
            raise PluginError(f"{file.src_uri} would be written to "
                              f"{os.path.realpath(file.abs_dest_path)}, outside the site "
                              f"folder {site_dir}")
    return files


def on_nav(nav, config, files):
    """Every lesson page is in mkdocs.yml's nav, in the order of its number,
    and so is every lab page (NN_name_lab.md, in the labs' part of the nav):
    a new lesson's page or lab page cannot be left out of the site's
    navigation."""
    pages = sorted(p.name for p in pathlib.Path(config["docs_dir"]).glob("[0-9][0-9]_*.md"))
    listed_all = [page.file.src_uri for page in nav.pages if re.match(r"\d\d_", page.file.src_uri)]
    for kind, wanted in (("lesson", [p for p in pages if not p.endswith("_lab.md")]),
                         ("lab", [p for p in pages if p.endswith("_lab.md")])):
        listed = [p for p in listed_all if p.endswith("_lab.md") == (kind == "lab")]
        if listed != wanted:
            missing = sorted(set(wanted) - set(listed))
            raise PluginError(f"mkdocs.yml's nav must list every {kind} page in order: "
                              + (f"{', '.join(missing)} missing" if missing else f"it has {listed}"))
    return nav


def _site_target(match: re.Match, page_dir: str) -> str:
    path, anchor = match.group("path"), match.group("anchor") or ""
    lines = LINE_RANGE.match(anchor)
    if lines:
        anchor = f"#L{lines.group(1)}"
    return f"]({posixpath.relpath(_site_name(path), page_dir or '.')}{anchor})"


def on_page_markdown(markdown, page, config, files):
    page_dir = posixpath.dirname(page.file.src_uri)
    if page.file.src_uri.startswith(f"{SOURCE}/"):
        # A generated page: its "Quoted on" links are written from the site's root.
        return re.sub(r"\]\(/([^)]+)\)",
                      lambda m: f"]({posixpath.relpath(m.group(1), page_dir)})", markdown)
    return OUTSIDE_LINK.sub(lambda m: _site_target(m, page_dir), markdown)


def _remove_generated():
    global _generated
    if _generated is not None:
        _generated.cleanup()
        _generated = None


def on_post_build(config):
    _remove_generated()


def on_build_error(error):
    """A refused build leaves no temporary folder behind."""
    _remove_generated()
