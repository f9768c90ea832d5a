// Typesets the math that pymdownx.arithmatex (generic mode) leaves in the page as \( \) and
// \[ \], with the KaTeX this site serves itself (no CDN). Material's document$ emits on every
// page load, instant navigation included.
document$.subscribe(function () {
  renderMathInElement(document.body, {
    delimiters: [
      { left: "\\[", right: "\\]", display: true },
      { left: "\\(", right: "\\)", display: false },
    ],
    throwOnError: false,
  });
});
