// Typesets every formula of the page with KaTeX, which the site serves itself
// (site/hooks.py copies Debian's libjs-katex). pymdownx.arithmatex, in its
// generic mode, leaves each formula as the TeX between \( \) in a span, or
// between \[ \] in a div, of class "arithmatex". A formula KaTeX cannot read
// becomes a console error that names it: the browser test
// (site/check_site.py) fails on any console error.

// A short inline formula is kept on one line with the bracket that opens
// before it and the punctuation that follows it: "far plane (" must not end a
// line whose next one starts with the formula. A long one keeps the breaks
// KaTeX allows inside it, which a no-wrap group would take away.
const SHORT_FORMULA = 30;  // characters of TeX

function keepWithNeighbours(element) {
  if (element.textContent.length > SHORT_FORMULA) return;
  const before = element.previousSibling, after = element.nextSibling;
  const opening = before && before.nodeType === Node.TEXT_NODE && /[(\[]$/.test(before.data);
  const closing = after && after.nodeType === Node.TEXT_NODE && /^[)\],.;:]+/.exec(after.data);
  if (!opening && !closing) return;
  const group = document.createElement("span");
  group.style.whiteSpace = "nowrap";
  element.replaceWith(group);
  if (opening) {
    group.append(before.data.slice(-1));
    before.data = before.data.slice(0, -1);
  }
  group.append(element);
  if (closing) {
    group.append(closing[0]);
    after.data = after.data.slice(closing[0].length);
  }
}

function typesetFormulas() {
  for (const element of document.querySelectorAll(".arithmatex")) {
    const display = element.tagName === "DIV";
    if (!display) keepWithNeighbours(element);
    const tex = element.textContent.trim().replace(/^\\[([]/, "").replace(/\\[)\]]$/, "");
    try {
      katex.render(tex, element, {displayMode: display, throwOnError: true, strict: "error"});
    } catch (error) {
      console.error(`KaTeX cannot typeset "${tex}": ${error.message}`);
    }
  }
}

// Inline code breaks only at its spaces. A browser may end a line after any
// hyphen, so `--tangents` could show as "-" at a line's end and "-tangents"
// on the next, and a reader copying it gets neither. Each run of non-space
// characters becomes a span that does not wrap (site.css: .code-word); the
// spaces between them stay text, where a long span may still break. The
// text, and so what a reader copies, is unchanged.
function keepCodeWordsWhole() {
  for (const code of document.querySelectorAll(".md-typeset code")) {
    if (code.closest("pre")) continue;
    for (const node of [...code.childNodes]) {
      if (node.nodeType !== Node.TEXT_NODE) continue;
      const pieces = node.data.split(/(\s+)/);
      const fragment = document.createDocumentFragment();
      for (const piece of pieces) {
        if (piece === "") continue;
        if (/^\s+$/.test(piece)) {
          fragment.append(piece);
        } else {
          const word = document.createElement("span");
          word.className = "code-word";
          word.textContent = piece;
          fragment.append(word);
        }
      }
      node.replaceWith(fragment);
    }
  }
}

function typesetPage() {
  keepCodeWordsWhole();
  typesetFormulas();
}

if (document.readyState === "loading") {
  document.addEventListener("DOMContentLoaded", typesetPage);
} else {
  typesetPage();
}
