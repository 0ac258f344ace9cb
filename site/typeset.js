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

if (document.readyState === "loading") {
  document.addEventListener("DOMContentLoaded", typesetFormulas);
} else {
  typesetFormulas();
}
