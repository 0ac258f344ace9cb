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
"""
import pathlib
import posixpath
import re
import shutil
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
IMAGES = {".png", ".jpg", ".jpeg", ".svg", ".gif"}
# A Markdown link or image whose target leaves docs/: ](../path#anchor)
OUTSIDE_LINK = re.compile(r"\]\(\.\./(?P<path>[^)\s#]+)(?P<anchor>#[^)\s]*)?\)")
# The code host's line ranges (#L40-L42) become the site's line anchors (#L40).
LINE_RANGE = re.compile(r"^#L(\d+)(-L\d+)?$")

_generated = None  # the folder the generated pages live in during a build


def _outside_targets(docs_dir: pathlib.Path) -> dict:
    """Every file outside docs/ that a page links to, with the pages that do."""
    targets = {}
    for page in sorted(docs_dir.glob("*.md")):
        for match in OUTSIDE_LINK.finditer(page.read_text()):
            path = match.group("path")
            if not (ROOT / path).is_file():
                raise PluginError(f"{page.name} links to ../{path}, which is not a file")
            targets.setdefault(path, []).append(page.name)
    return targets


def _title(page: str) -> str:
    """A docs page's own title: its first heading."""
    for line in (ROOT / "docs" / page).read_text().splitlines():
        if line.startswith("# "):
            return line[2:].strip()
    return page


def _code_page(path: str, pages: list) -> str:
    """A page that shows one source file with anchored line numbers."""
    text = (ROOT / path).read_text()
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

    _generated = tempfile.TemporaryDirectory(prefix="rasterlab-site-")
    generated = pathlib.Path(_generated.name)
    for path, pages in _outside_targets(docs_dir).items():
        suffix = pathlib.PurePosixPath(path).suffix.lower()
        name = _site_name(path)
        (generated / name).parent.mkdir(parents=True, exist_ok=True)
        if suffix in IMAGES:
            shutil.copyfile(ROOT / path, generated / name)
        elif suffix == ".md":  # a Markdown file is a page as it is
            (generated / name).write_text((ROOT / path).read_text())
        else:
            (generated / name).write_text(_code_page(path, pages))
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
    return files


def on_nav(nav, config, files):
    """Every lesson page is in mkdocs.yml's nav, in the order of its number:
    a new lesson's page cannot be left out of the site's navigation."""
    lessons = sorted(p.name for p in pathlib.Path(config["docs_dir"]).glob("[0-9][0-9]_*.md"))
    listed = [page.file.src_uri for page in nav.pages if re.match(r"\d\d_", page.file.src_uri)]
    if listed != lessons:
        missing = sorted(set(lessons) - set(listed))
        raise PluginError("mkdocs.yml's nav must list every lesson page in order: "
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


def on_post_build(config):
    global _generated
    if _generated is not None:
        _generated.cleanup()
        _generated = None
