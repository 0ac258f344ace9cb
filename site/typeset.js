// Typesets every formula of the page with KaTeX, which the site serves itself
// (site/hooks.py copies Debian's libjs-katex). pymdownx.arithmatex, in its
// generic mode, leaves each formula as the TeX between \( \) in a span, or
// between \[ \] in a div, of class "arithmatex". A formula KaTeX cannot read
// becomes a console error that names it: the browser test
// (site/check_site.py) fails on any console error.
function typesetFormulas() {
  for (const element of document.querySelectorAll(".arithmatex")) {
    const display = element.tagName === "DIV";
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
