#!/usr/bin/env python3
"""Reads every page of the built docs site in headless Chromium, as a reader would.

    site/check_site.py SITE_DIR [--docs docs] [--screenshots DIR] [--pages PAGE ...]

It serves SITE_DIR from http.server on 127.0.0.1 (a free port) and opens
every HTML page in Chromium, driven over the DevTools protocol on a pipe
(--remote-debugging-pipe: JSON messages ended by a NUL byte on fds 3 and 4),
so it needs nothing but Python and Debian's chromium. On each page it checks
that

- no console error occurs: a script's console.error (site/typeset.js reports
  a formula KaTeX cannot read that way), an uncaught exception, or a failed
  load of any of the page's files;
- every image (the pictures, the charts, the diagrams) loaded: naturalWidth > 0;
- every link inside the site reaches a file the server answers with 200, and
  its #anchor names an element of that page;
- every formula was typeset: no `$`, `\\(` or `\\[` is left in the page's text
  outside code, the count of KaTeX's formulas equals the count of formulas in
  the page's Markdown (docs/NAME.md), counted here on their own, and KaTeX's
  stylesheet applies to them;
- no display formula is wider than the page's column (it would need scrolling),
  and no code block's lines run past it;
- no figure is shown smaller than its own pixels where the column has room
  for it two to a row (at most 45% of the column);
- a lesson's page links to the previous and the next page;
- no Markdown table is left as text (a table inside HTML that the Markdown
  reader did not enter);
- no inline code is broken across lines inside a word (`--tangents` shown
  as "-" and "-tangents");
- no text of a chart or diagram overlaps another or is cut at the figure's
  edge, no note of a chart runs over the edge of its axes, no series of a
  chart lies exactly under another, and no text of a diagram is smaller
  than 8 px as shown;
- a lesson's opening picture is not too dark or too flat (its luma's mean
  and standard deviation above a floor);
- a lesson's page stays within its budget of words (the lab's full tables
  and method go to its lab page);

and that the search box finds a lesson by a word of its text. A screenshot of
each page goes to the screenshots folder. Exit 0 when every check holds, 1
with every failure listed, 77 (CTest's skip) when Chromium is not installed.
"""
import argparse
import base64
import fcntl
import functools
import html.parser
import http.server
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import urllib.error
import urllib.parse
import urllib.request

SKIP = 77
PAGE_TIMEOUT = 30.0  # seconds for one page to load; the slowest here took under 2
WIDTH, HEIGHT = 1280, 900
WORD_BUDGET = 8000  # words of a lesson's page, its HTML comments (value markers) left out
# The opening picture of a lesson's page, its luma on 0-255: the mean (how
# bright) and the standard deviation (how much contrast) at least these.
OPENING_MIN_MEAN, OPENING_MIN_SPREAD = 25.0, 15.0  # the lessons' measure 28-40 and 20-45


class Browser:
    """Headless Chromium, one tab, spoken to over --remote-debugging-pipe."""

    def __init__(self, chromium: str):
        self.profile = tempfile.TemporaryDirectory(prefix="rasterlab-chromium-")
        # Chromium reads commands on fd 3 and writes answers on fd 4. The pipe's
        # ends are first moved above 9 so that the shell's redirections cannot
        # overwrite one with the other.
        to_browser_read, self.to_browser = _high_pipe()
        self.from_browser, from_browser_write = _high_pipe()
        # The flags keep Chromium off the network it would otherwise call home on.
        flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                 "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--disable-extensions",
                 "--hide-scrollbars", "--remote-debugging-pipe",
                 f"--user-data-dir={self.profile.name}", f"--window-size={WIDTH},{HEIGHT}",
                 "about:blank"]
        self.process = subprocess.Popen(
            ["/bin/bash", "-c", f'exec "$@" 3<&{to_browser_read} 4>&{from_browser_write}',
             "chromium", chromium, *flags],
            pass_fds=(to_browser_read, from_browser_write),
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_browser_read)
        os.close(from_browser_write)
        self.buffer = b""
        self.next_id = 0
        self.events = []
        self.session = None
        target = self.call("Target.createTarget", url="about:blank")["targetId"]
        self.session = self.call("Target.attachToTarget", targetId=target,
                                 flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self.call(f"{domain}.enable")
        self.call("Emulation.setDeviceMetricsOverride", width=WIDTH, height=HEIGHT,
                  deviceScaleFactor=1, mobile=False)

    def _read_message(self, deadline: float) -> dict:
        while b"\0" not in self.buffer:
            if time.monotonic() > deadline:
                raise TimeoutError("Chromium did not answer in time")
            if self.process.poll() is not None:
                raise RuntimeError(f"Chromium exited with {self.process.returncode}")
            chunk = os.read(self.from_browser, 1 << 16)
            if not chunk:
                raise RuntimeError("Chromium closed its pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method: str, timeout: float = PAGE_TIMEOUT, **params) -> dict:
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params}
        if self.session and not method.startswith("Target."):
            message["sessionId"] = self.session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read_message(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error'].get('message')}")
                return reply.get("result", {})
            if "method" in reply:
                self.events.append(reply)

    def wait_for(self, method: str, timeout: float = PAGE_TIMEOUT) -> None:
        deadline = time.monotonic() + timeout
        while not any(e["method"] == method for e in self.events):
            event = self._read_message(deadline)
            if "method" in event:
                self.events.append(event)

    def evaluate(self, expression: str):
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True,
                           awaitPromise=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"the check's own script failed: {result['exceptionDetails']}")
        return result["result"].get("value")

    def close(self) -> None:
        try:
            self.call("Browser.close", timeout=5)
        except (RuntimeError, TimeoutError, OSError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self.to_browser)
        os.close(self.from_browser)
        self.profile.cleanup()


def _high_pipe() -> tuple:
    """A pipe whose two ends are numbered 10 or more."""
    ends = []
    for end in os.pipe():
        ends.append(fcntl.fcntl(end, fcntl.F_DUPFD_CLOEXEC, 10))
        os.close(end)
    return tuple(ends)


def console_errors(events: list) -> list:
    """The errors among the DevTools events a page load produced."""
    errors = []
    for event in events:
        params = event.get("params", {})
        if event["method"] == "Runtime.consoleAPICalled" and params.get("type") == "error":
            errors.append(" ".join(str(a.get("value", a.get("description", "")))
                                   for a in params.get("args", [])))
        elif event["method"] == "Runtime.exceptionThrown":
            details = params.get("exceptionDetails", {})
            errors.append(details.get("exception", {}).get("description", details.get("text")))
        elif event["method"] == "Log.entryAdded" and params["entry"].get("level") == "error":
            entry = params["entry"]
            errors.append(f"{entry.get('text')} {entry.get('url', '')}".strip())
    return errors


# What a page reports of itself, once loaded.
PAGE_FACTS = r"""
(() => {
  const skipped = "code, pre, script, style, .katex, .md-search, .md-nav";
  const raw = [], tables = [], leftovers = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    if (node.parentElement.closest(skipped)) continue;
    const text = node.textContent;
    if (text.includes("$") || text.includes("\\(") || text.includes("\\["))
      raw.push(text.trim().slice(0, 80));
    if (/\|\s*-{3}/.test(text)) tables.push(text.trim().slice(0, 80));
    // An HTML comment or a value marker shown as text (a "|" inside one split
    // a table's cell, and the rest of the marker became the cell's text).
    if (/<!--|-->|\bvalue: \S+\.md\b/.test(text)) leftovers.push(text.trim().slice(0, 80));
  }
  const visible = e => e.closest(skipped) === null;
  // A list that ran into the paragraph above it (a line directly under a
  // caption): its items are lines of the paragraph's text starting "- ".
  const runOn = [...document.querySelectorAll("article p")].filter(visible)
      .map(p => p.textContent).filter(t => /\n\s*[-*+] \S/.test(t))
      .map(t => t.trim().slice(0, 80));
  // Table rows cut off from their table by a blank line: a paragraph of "| a | b |" lines.
  const rowsAsText = [...document.querySelectorAll("article p")].filter(visible)
      .map(p => p.textContent).filter(t => /^\s*\|.*\|\s*$/m.test(t))
      .map(t => t.trim().slice(0, 80));
  // Markdown syntax left in a table cell as text: the cell was not parsed.
  const cells = [...document.querySelectorAll("article td, article th")].filter(visible)
      .filter(c => [...c.childNodes].some(n => n.nodeType === Node.TEXT_NODE &&
                                                /\*\*|`|\]\(|<!--|-->/.test(n.textContent)))
      .map(c => c.textContent.trim().slice(0, 80));
  // A figure shown smaller than its own pixels, where the column had room
  // for it two to a row (a failure beside its fix): three or four to a row, a
  // 2x crop shrank back to under 1x. A figure wider than half the column may
  // shrink to that half. The models' textures (obj/) are thumbnails of whole
  // maps, not figures.
  const column = (document.querySelector("article") || document.body).getBoundingClientRect().width;
  const narrow = [...document.querySelectorAll("article img")].filter(
      i => i.naturalWidth > 0 && !/\/obj\//.test(i.currentSrc || i.src) &&
           i.getBoundingClientRect().width + 2 < Math.min(i.naturalWidth, 0.45 * column)).map(
      i => `${(i.currentSrc || i.src).split("/").pop()} at ${Math.round(i.getBoundingClientRect().width)} px of ${i.naturalWidth}`);
  // A code block whose lines run past the column: their ends are hidden
  // until the reader scrolls it sideways.
  const cut = [...document.querySelectorAll("article pre > code")].filter(
      c => c.scrollWidth > c.clientWidth + 1).map(c => c.textContent.split("\n")[0].slice(0, 60));
  return {
    images: [...document.images].map(i => ({src: i.currentSrc || i.src, width: i.naturalWidth})),
    links: [...document.querySelectorAll("a[href]")].map(a => a.href),
    formulas: document.querySelectorAll(".katex").length,
    // KaTeX's stylesheet hides the MathML copy of each formula; without it
    // every formula shows twice.
    unstyled: [...document.querySelectorAll(".katex-mathml")].filter(
        e => getComputedStyle(e).position !== "absolute").length,
    marked: document.querySelectorAll(".arithmatex").length,
    raw: raw,
    tables: tables,
    leftovers: leftovers,
    run_on: runOn,
    rows_as_text: rowsAsText,
    cells: cells,
    narrow: narrow,
    cut: cut,
    // A display formula grows to its width; the block around it scrolls.
    wide: [...document.querySelectorAll("div.arithmatex")].filter(
        e => e.scrollWidth > e.clientWidth + 1).map(e => e.textContent.slice(0, 60)),
    previous: !!document.querySelector("a.md-footer__link--prev"),
    next: !!document.querySelector("a.md-footer__link--next"),
  };
})()
"""


# What a page's figures and inline code show, measured as displayed.
FIGURE_FACTS = r"""
// What a page's figures and code spans show a reader, once loaded (async:
// each SVG figure is fetched and laid out again, at the size it is shown, so
// that its text can be measured).
(async () => {
  const article = document.querySelector("article") || document.body;
  // Inline code broken inside a word: a line ends at a character that is not
  // a space (a hyphen, a slash, a dot), so the reader sees, and copies, a
  // word in two pieces. In a table's cell a word wider than the whole cell
  // has to break somewhere (or the table would scroll): that break is allowed.
  const splitCode = [];
  for (const code of article.querySelectorAll("code")) {
    if (code.closest("pre") || code.getClientRects().length < 2) continue;
    const cell = code.closest("td, th");
    const room = cell ? cell.clientWidth - parseFloat(getComputedStyle(cell).paddingLeft)
                        - parseFloat(getComputedStyle(cell).paddingRight) : Infinity;
    const walker = document.createTreeWalker(code, NodeFilter.SHOW_TEXT);
    // The top of the word's last character, whether the word broke, its width.
    let previous = null, broken = false, wordBroken = false, width = 0;
    const endWord = () => {
      if (wordBroken && width <= room + 1) broken = true;
      previous = null, wordBroken = false, width = 0;
    };
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      for (let i = 0; i < node.data.length; ++i) {
        const character = node.data[i];
        if (/\s/.test(character)) {  // a line may end at a space
          endWord();
          continue;
        }
        const range = document.createRange();
        range.setStart(node, i);
        range.setEnd(node, i + 1);
        const rects = range.getClientRects();
        if (!rects.length) continue;
        const top = rects[0].top;
        wordBroken ||= previous !== null && top > previous + 2;
        width += rects[0].width;
        previous = top;
      }
    }
    endWord();
    if (broken) splitCode.push(code.textContent.slice(0, 60));
  }

  // The SVG figures (charts and diagrams, drawn by matplotlib with text as
  // glyph paths in groups id="text_N", each opened by a comment holding the
  // text): measured as shown. Text in a diagram must be 8 px or more as
  // shown; in any figure no two texts overlap and none is cut at the
  // figure's edge; in a chart no note runs over the edge of its axes, and
  // no series lies exactly under another (the legend would list a line the
  // reader cannot see).
  const MIN_TEXT_PX = 8;
  const smallText = [], overlaps = [], outside = [], hidden = [];
  const label = g => {
    for (const node of g.childNodes)
      if (node.nodeType === Node.COMMENT_NODE) return node.data.trim().slice(0, 40);
    return g.id;
  };
  const box = e => e.getBoundingClientRect();
  const intersect = (a, b) => Math.min(a.right, b.right) - Math.max(a.left, b.left) > 1 &&
                              Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top) > 1;
  const inside = (a, b) => a.left >= b.left - 1 && a.right <= b.right + 1 &&
                           a.top >= b.top - 1 && a.bottom <= b.bottom + 1;
  const holder = document.createElement("div");
  holder.style.cssText = "position: absolute; left: 0; top: 0; visibility: hidden";
  document.body.append(holder);
  const figures = [...article.querySelectorAll("img")].filter(
      i => /\.svg$/.test(i.currentSrc || i.src) && i.naturalWidth > 0);
  const seen = new Set();
  for (const image of figures) {
    const name = (image.currentSrc || image.src).split("/").slice(-2).join("/");
    // A chart has axes that frame its data and a legend naming each series;
    // a diagram (docs/diagrams/) draws freely, its axes hidden.
    const chart = name.startsWith("charts/");
    const shown = image.getBoundingClientRect().width;
    const key = `${name}@${Math.round(shown)}`;
    if (seen.has(key) || shown === 0) continue;
    seen.add(key);
    const text = await (await fetch(image.currentSrc || image.src)).text();
    holder.innerHTML = text.replace(/^[\s\S]*?(<svg)/, "$1");
    const svg = holder.querySelector("svg");
    if (!svg || !svg.viewBox.baseVal || !svg.viewBox.baseVal.width) continue;
    const view = svg.viewBox.baseVal;
    svg.setAttribute("width", shown);
    svg.setAttribute("height", shown * view.height / view.width);
    const scale = shown / view.width;  // displayed pixels per unit of the figure
    const whole = box(svg);
    const texts = [...svg.querySelectorAll('g[id^="text_"]')].filter(g => box(g).width > 0);
    const boxes = texts.map(box);
    for (const g of texts) {
      const glyphs = g.querySelector('g[transform*="scale("]');
      const size = glyphs && /scale\(\s*([\d.]+)/.exec(glyphs.getAttribute("transform"));
      // matplotlib's glyphs are drawn at 100 units to the point of the font.
      const px = size ? parseFloat(size[1]) * 100 * scale : box(g).height;
      if (!chart && px < MIN_TEXT_PX) smallText.push(`${name}: "${label(g)}" at ${px.toFixed(1)} px`);
      if (!inside(box(g), whole)) outside.push(`${name}: "${label(g)}" cut at the figure's edge`);
    }
    for (let i = 0; i < texts.length; ++i)
      for (let j = i + 1; j < texts.length; ++j)
        if (texts[i].contains(texts[j]) || texts[j].contains(texts[i])) continue;
        else if (intersect(boxes[i], boxes[j]))
          overlaps.push(`${name}: "${label(texts[i])}" and "${label(texts[j])}"`);
    for (const axes of chart ? svg.querySelectorAll('g[id^="axes_"]') : []) {
      const patch = axes.querySelector(':scope > g[id^="patch_"] > path');
      if (!patch) continue;
      const frame = box(patch);
      // A note written inside the axes that runs over their edge (a title,
      // wholly above them, is not one).
      for (const g of axes.querySelectorAll(':scope > g[id^="text_"]')) {
        const b = box(g);
        if (b.width > 0 && intersect(b, frame) && !inside(b, frame))
          outside.push(`${name}: "${label(g)}" runs over the edge of its axes`);
      }
      // A series drawn exactly over another: the same line (path) or the same
      // markers (their positions), in another style. The first is hidden,
      // though the legend lists it.
      const drawn = new Map();
      for (const g of axes.querySelectorAll(':scope > g[id^="line2d_"]')) {
        const path = g.querySelector(":scope > path");
        const marks = [...g.querySelectorAll("use")].map(
            u => `${u.getAttribute("x")},${u.getAttribute("y")}`);
        const shape = path ? path.getAttribute("d").replace(/\s+/g, " ").trim()
                           : marks.length > 1 ? marks.join(" ") : "";
        if (!shape || /#b0b0b0/.test(path ? path.getAttribute("style") : "")) continue;
        const style = (path || g.querySelector("use") || g).getAttribute("style") || "";
        // A dashed line over another lets the one under it show between its dashes.
        if (/stroke-dasharray/.test(style)) {
          drawn.set(shape, drawn.get(shape) || "dashed");
          continue;
        }
        const colour = (/stroke: ?(#\w+)/.exec(style) || /fill: ?(#\w+)/.exec(style) || ["", "?"])[1];
        if (drawn.has(shape) && drawn.get(shape) !== colour)
          hidden.push(`${name}: a series in ${drawn.get(shape)} lies exactly under one in ${colour}`);
        drawn.set(shape, colour);
      }
    }
  }
  holder.remove();

  // The opening picture (the first raster figure of a lesson's page) must
  // show its point at a glance: not too dark, not flat.
  let opening = null;
  const first = [...article.querySelectorAll("img")].find(
      i => /\.(png|jpe?g)$/.test(i.currentSrc || i.src) && i.naturalWidth > 0 &&
           !/\/obj\//.test(i.currentSrc || i.src));
  if (first) {
    const canvas = document.createElement("canvas");
    canvas.width = first.naturalWidth;
    canvas.height = first.naturalHeight;
    const context = canvas.getContext("2d");
    context.drawImage(first, 0, 0);
    const pixels = context.getImageData(0, 0, canvas.width, canvas.height).data;
    let sum = 0, squares = 0;
    const count = pixels.length / 4;
    for (let i = 0; i < pixels.length; i += 4) {
      const luma = 0.2126 * pixels[i] + 0.7152 * pixels[i + 1] + 0.0722 * pixels[i + 2];
      sum += luma;
      squares += luma * luma;
    }
    const mean = sum / count;
    opening = {name: (first.currentSrc || first.src).split("/").pop(), mean: mean,
               spread: Math.sqrt(Math.max(0, squares / count - mean * mean))};
  }
  return {split_code: splitCode, small_text: smallText, overlaps: overlaps, outside: outside,
          hidden: hidden, opening: opening};
})()
"""

class Anchors(html.parser.HTMLParser):
    """The ids and names a page's HTML declares (what a #fragment can name)."""

    def __init__(self):
        super().__init__()
        self.found = set()

    def handle_starttag(self, tag, attributes):
        for key, value in attributes:
            if key in ("id", "name") and value:
                self.found.add(value)


FENCE = re.compile(r"^( {0,3})(`{3,}|~{3,}).*?^\1\2[ \t]*$", re.S | re.M)
COMMENT = re.compile(r"<!--.*?-->", re.S)
CODE_SPAN = re.compile(r"(`+)(?!`).+?(?<!`)\1(?!`)", re.S)
DISPLAY = re.compile(r"\$\$.+?\$\$", re.S)
INLINE = re.compile(r"(?<![\\$])\$(?![\s$])(?:\\.|[^\\$\n])+?(?<!\s)\$")


def markdown_formulas(text: str) -> int:
    """How many formulas a page's Markdown holds: $$...$$ blocks and $...$ in
    prose, code blocks, code spans and HTML comments left out."""
    text = COMMENT.sub("", FENCE.sub("", text))
    text = CODE_SPAN.sub("", text)
    display = len(DISPLAY.findall(text))
    return display + len(INLINE.findall(DISPLAY.sub("", text)))


def page_words(text: str) -> int:
    """A page's length as a reader meets it: its Markdown's words, the HTML
    comments (value markers, snippet markers) left out."""
    return len(COMMENT.sub("", text).split())


def serve(folder: pathlib.Path) -> tuple:
    handler = functools.partial(_QuietHandler, directory=str(folder))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/"


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def fetch(url: str) -> tuple:
    """(status, body) of a URL of the local server."""
    try:
        with urllib.request.urlopen(url, timeout=10) as answer:
            return answer.status, answer.read()
    except urllib.error.HTTPError as error:
        return error.code, b""


def check_links(links: list, base: str, cache: dict) -> list:
    problems = []
    for link in sorted(set(links)):
        if not link.startswith(base):
            continue  # outside the site: there is none, and a test must not leave this machine
        address, _, anchor = link.partition("#")
        if address not in cache:
            status, body = fetch(address)
            anchors = Anchors()
            if status == 200 and address.endswith((".html", "/")):
                anchors.feed(body.decode("utf-8", "replace"))
            cache[address] = (status, anchors.found)
        status, found = cache[address]
        if status != 200:
            problems.append(f"link to {link[len(base):]} answers {status}")
        elif anchor and urllib.parse.unquote(anchor) not in found:
            problems.append(f"link to {link[len(base):]}: no element #{anchor} there")
    return problems


def check_search(browser: Browser, base: str) -> list:
    """Type a word into the search box; a result must come back."""
    browser.events.clear()
    browser.call("Page.navigate", url=base + "index.html")
    browser.wait_for("Page.loadEventFired")
    # The theme's search worker reads the index after the page loads, and
    # ignores what is typed before it is ready.
    deadline = time.monotonic() + PAGE_TIMEOUT
    while "Initializing" in (browser.evaluate(
            "document.querySelector('.md-search-result__meta').innerText") or ""):
        if time.monotonic() > deadline:
            return ["search: the search index never finished loading"]
        time.sleep(0.2)
    browser.evaluate("document.querySelector('.md-search__input').focus()")
    for key in "Bresenham":  # typed key by key: the theme searches on key-up
        browser.call("Input.dispatchKeyEvent", type="keyDown", key=key, text=key)
        browser.call("Input.dispatchKeyEvent", type="keyUp", key=key)
    # The box reports the search's end in its meta line ("7 matching
    # documents", "No matching documents").
    meta = "Type to start searching"
    deadline = time.monotonic() + PAGE_TIMEOUT
    while "matching" not in meta.lower() and time.monotonic() < deadline:
        time.sleep(0.2)
        meta = browser.evaluate("document.querySelector('.md-search-result__meta').innerText")
    results = browser.evaluate(
        "[...document.querySelectorAll('.md-search-result__item')].map(e => e.innerText)")
    if not results:
        return [f"search: no result for 'Bresenham' (the box says: {meta.strip()!r})"]
    if not any("Bresenham" in r for r in results):
        return [f"search: 'Bresenham' found only {results[:3]}"]
    return []


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("site", type=pathlib.Path, help="the built site (build/site)")
    parser.add_argument("--docs", type=pathlib.Path,
                        default=pathlib.Path(__file__).resolve().parent.parent / "docs",
                        help="the Markdown the site was built from (for the formula counts)")
    parser.add_argument("--screenshots", type=pathlib.Path,
                        help="write a PNG of each page here")
    parser.add_argument("--pages", nargs="+", metavar="PAGE",
                        help="check only these pages (paths in the site), and search")
    options = parser.parse_args()

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("check_site: skipped, Chromium is not installed (scripts/setup.sh site installs it)")
        return SKIP
    if not (options.site / "index.html").is_file():
        print(f"check_site: error: {options.site} holds no built site (index.html); "
              "build it with: cmake --build build --target docs_site", file=sys.stderr)
        return 1
    if options.screenshots:
        options.screenshots.mkdir(parents=True, exist_ok=True)

    pages = options.pages or sorted(p.relative_to(options.site).as_posix()
                                    for p in options.site.rglob("*.html"))
    absent = [page for page in pages if not (options.site / page).is_file()]
    if absent:
        print(f"check_site: error: no page {', '.join(absent)} in {options.site}", file=sys.stderr)
        return 1
    server, base = serve(options.site)
    try:
        return check_pages(options, pages, chromium, base)
    except (RuntimeError, TimeoutError, OSError) as error:
        print(f"check_site: error: {error}", file=sys.stderr)
        return 1
    finally:
        server.shutdown()


def check_page(browser: Browser, page: str, options, base: str, cache: dict) -> tuple:
    """One page: (the line that reports it, its problems, its formula count)."""
    browser.events.clear()
    browser.call("Page.navigate", url=base + page)
    browser.wait_for("Page.loadEventFired")
    facts = browser.evaluate(PAGE_FACTS)
    problems = [f"console: {e}" for e in console_errors(browser.events)]
    problems += [f"image {i['src'][len(base):]} did not load" for i in facts["images"]
                 if i["width"] == 0]
    problems += check_links(facts["links"], base, cache)
    problems += [f"formula not typeset: ...{text}..." for text in facts["raw"]]
    problems += [f"a Markdown table left as text: {text}..." for text in facts["tables"]]
    problems += [f"markup left in the text: {text}..." for text in facts["leftovers"]]
    problems += [f"a list run into a paragraph: {text}..." for text in facts["run_on"]]
    problems += [f"table rows shown as a paragraph: {text}..." for text in facts["rows_as_text"]]
    problems += [f"a table cell holding markup: {text}..." for text in facts["cells"]]
    problems += [f"an image shown smaller than its own width: {text}" for text in facts["narrow"]]
    problems += [f"a code block cut at the right: {text}..." for text in facts["cut"]]
    problems += [f"a display formula wider than the page's column ({WIDTH} px "
                 f"window): {text}..." for text in facts["wide"]]
    figures = browser.evaluate(FIGURE_FACTS)
    problems += [f"inline code broken inside a word: {text}..." for text in figures["split_code"]]
    problems += [f"figure text smaller than 8 px as shown: {text}" for text in figures["small_text"]]
    problems += [f"figure text overlapping: {text}" for text in figures["overlaps"]]
    problems += [f"figure text out of place: {text}" for text in figures["outside"]]
    problems += [f"a chart's series hidden: {text}" for text in figures["hidden"]]
    lesson = re.fullmatch(r"\d\d_\w+?(?<!_lab)\.html", page)
    opening = figures["opening"]
    if lesson and opening and (opening["mean"] < OPENING_MIN_MEAN
                               or opening["spread"] < OPENING_MIN_SPREAD):
        problems.append(f"the opening picture {opening['name']} is too dark or too flat to show "
                        f"its point: mean {opening['mean']:.0f}, spread {opening['spread']:.0f} "
                        f"(at least {OPENING_MIN_MEAN:.0f} and {OPENING_MIN_SPREAD:.0f} of 255)")
    if re.match(r"\d\d_", page) and not (facts["previous"] and facts["next"]):
        problems.append("a lesson without its previous and next links")
    if facts["unstyled"]:
        problems.append(f"{facts['unstyled']} formulas without KaTeX's stylesheet")
    source = options.docs / page.replace(".html", ".md")
    words = page_words(source.read_text()) if source.is_file() else 0
    if lesson and words > WORD_BUDGET:
        problems.append(f"{words} words, over a lesson page's budget of {WORD_BUDGET} (move the "
                        "lab's tables and method to its lab page)")
    expected = markdown_formulas(source.read_text()) if source.is_file() else 0
    if facts["formulas"] != expected or facts["marked"] != expected:
        problems.append(f"{facts['formulas']} formulas typeset ({facts['marked']} marked "
                        f"by arithmatex) where {source.name} holds {expected}")
    if options.screenshots:
        shot = browser.call("Page.captureScreenshot", format="png")["data"]
        name = page.replace("/", "_").replace(".html", ".png")
        (options.screenshots / name).write_bytes(base64.b64decode(shot))
    line = (f"{page}: {len(facts['images'])} images, {len(facts['links'])} links, "
            f"{facts['formulas']} formulas" + (f", {len(problems)} problems" if problems else ""))
    return line, problems, facts["formulas"]


def check_share(pages: list, chromium: str, options, base: str, cache: dict,
                search: bool) -> dict:
    """Some of the pages in a browser of their own (and the search, if asked):
    {page: check_page's answer}, plus "search": its problems."""
    answers = {}
    browser = Browser(chromium)
    try:
        for page in pages:
            answers[page] = check_page(browser, page, options, base, cache)
        if search:
            answers["search"] = check_search(browser, base)
    finally:
        browser.close()
    return answers


def check_pages(options, pages: list, chromium: str, base: str) -> int:
    """Every page, then search; prints the problems, returns the exit code.
    The pages are shared between two browsers (one where the machine has a
    single core), each in a thread of its own: a page's load waits mostly on
    Chromium, so two at once take about half the time on two cores. The
    report lists the pages in their order whatever order they finished in."""
    browsers = max(1, min(2, os.cpu_count() or 1, len(pages)))
    shares = [pages[i::browsers] for i in range(browsers)]
    cache, answers, errors = {}, {}, []

    def run(index: int) -> None:
        try:
            answers.update(check_share(shares[index], chromium, options, base, cache,
                                       search=index == 0))
        except Exception as error:  # raised again below, in the main thread
            errors.append(error)

    threads = [threading.Thread(target=run, args=(i,)) for i in range(browsers)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    if errors:
        raise errors[0]

    failures, formulas = [], 0
    for page in pages:
        line, problems, count = answers[page]
        print(line)
        failures += [f"{page}: {p}" for p in problems]
        formulas += count
    failures += answers["search"]
    for failure in failures:
        print(failure, file=sys.stderr)
    print(f"check_site: {len(pages)} pages, {formulas} formulas, {len(cache)} link targets; "
          f"{len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
