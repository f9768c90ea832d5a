"""Markdown building blocks for the generated pages (the site's, and the bench report that the
site shows), and the one place where a value from a file (a scene's name, a file name, a
snippet's front matter, a bench label) becomes page text.

Markdown passes raw HTML through untouched and turns brackets, backticks, braces (attr_list)
and dollars (arithmatex) into markup, so every such value goes through one of these:

- `md_text`: plain text that reads exactly as written: HTML and every character that is
  markup here become entities, newlines become spaces;
- `md_prose`: prose from the catalog (summaries, sources, descriptions): `md_text`, except that
  its `code` spans stay code spans (`md_code`); no links, HTML, emphasis or math;
- `md_code`: an inline code span holding a value exactly, whatever backticks it holds;
- `html_text`, `html_attr`: for the raw HTML of a page (the live canvases);
- `safe_link`, `safe_image` (with `url_part`, `path_url`): a link or an image only to an
  http(s) or relative target, its path segments percent-encoded; any other scheme
  (`javascript:`, `data:`, `vbscript:`, ...) leaves the text alone, unlinked.

Shader text only ever reaches a page inside a fenced code block: Pygments highlights it and
escapes every `<` and `&`, so a comment such as `// </script>` stays text. A fence is made one
backtick longer than the longest run of backticks in the code, so no code can close it early.
"""

from __future__ import annotations

import html
import re
from pathlib import PurePosixPath
from urllib.parse import quote

_BACKTICKS = re.compile(r"`+")
# Line breaks and other control characters: a value is one line of text on a page.
_BREAKS = re.compile(r"[\x00-\x1f\x7f\x85\u2028\u2029]+")
# Markup wherever it stands: code (`), links and images ([ ]), attr_list ({ }), arithmatex ($ and
# \( \[), emphasis (*), headings and their closing hashes (#), table cells (|).
_MARKUP = re.compile(r"[`\[\]{}$\\*#|]")
# `_` is emphasis only at a word's edge (python-markdown's smart emphasis), so one between two
# letters or digits stays as it is (snake_case); any other becomes an entity.
_UNDERSCORE = re.compile(r"(?<![^\W_])_|_(?![^\W_])")
# What starts a block at the start of a line: a list (- + 1.), a heading (#), a quote (>),
# a tab (===), an admonition (!!!), a definition (:).
_LEADING = re.compile(r"^( *)(?:([-+=!:])|(\d+)([.)]))")
_SCHEME = re.compile(r"^([A-Za-z][A-Za-z0-9+.-]*):")
SAFE_SCHEMES = ("http", "https")


def _entity(match: re.Match[str]) -> str:
    return "".join(f"&#{ord(char)};" for char in match.group(0))


def md_text(value: str) -> str:
    """`value` as inline Markdown that shows exactly its text: no HTML, link, code, emphasis,
    math or attribute list gets through, and it stays on one line (safe in a table cell, a
    heading, a list item, link text or an image's alt text)."""
    return _text(value, line_start=True)


def _text(value: str, line_start: bool) -> str:
    value = _BREAKS.sub(" ", value)
    value = html.escape(value, quote=False)
    value = _MARKUP.sub(_entity, value)
    value = _UNDERSCORE.sub(_entity, value)
    lead = _LEADING.match(value) if line_start else None
    if lead:
        spaces, mark, digits, dot = lead.groups()
        escaped = f"&#{ord(mark)};" if mark else f"{digits}&#{ord(dot)};"
        value = spaces + escaped + value[lead.end() :]
    return value


def md_code(value: str) -> str:
    """An inline code span holding `value` exactly (line breaks and other control characters
    become a space, as newlines do in any code span): its fence is longer than any run of
    backticks in it, and it is padded with spaces where it starts or ends with a backtick, or
    starts as pymdownx.inlinehilite's language prefix (`#!lang`, `:::lang`)."""
    value = _BREAKS.sub(" ", value)
    if not value.strip():
        return "` `"
    longest = max((len(run) for run in _BACKTICKS.findall(value)), default=0)
    ticks = "`" * (longest + 1)
    pad = " " if value[0] == "`" or value[-1] == "`" or value.startswith(("#!", ":::")) else ""
    return f"{ticks}{pad}{value}{pad}{ticks}"


def md_prose(value: str) -> str:
    """Prose from the catalog or the scene model as Markdown: plain text (`md_text`), except
    that a `code` span (backticks, closed by a run of the same length) stays a code span."""
    parts = []
    at = 0
    for match in _BACKTICKS.finditer(value):
        if match.start() < at:  # inside a code span already taken
            continue
        fence = match.group(0)
        close = re.compile(rf"(?<!`){fence}(?!`)").search(value, match.end())
        if close is None:
            continue  # an unmatched run is text
        code = value[match.end() : close.start()]
        if code.strip() and code.startswith(" ") and code.endswith(" "):
            code = code[1:-1]  # CommonMark's padding, as md_code adds it
        parts += [_text(value[at : match.start()], at == 0), md_code(code)]
        at = close.end()
    parts.append(_text(value[at:], at == 0))
    return "".join(parts)


def html_text(value: str) -> str:
    """`value` as text in raw HTML. Line breaks become entities too, so that no value can cut
    a raw HTML block of a Markdown page with a blank line."""
    return _lines(html.escape(value, quote=False))


def html_attr(value: str) -> str:
    """`value` inside a double-quoted HTML attribute (line breaks as entities, as above)."""
    return _lines(html.escape(value, quote=True))


def _lines(value: str) -> str:
    return value.replace("\r", "&#13;").replace("\n", "&#10;")


def url_part(value: str) -> str:
    """`value` as one percent-encoded path segment of a relative link (`:` and `/` included,
    so it can neither name a scheme nor leave its folder)."""
    return quote(value, safe="")


def is_safe_url(url: str) -> bool:
    """Whether `url` is relative or http(s), as a browser reads it: before and after its HTML
    entities are decoded, with the spaces and control characters it ignores taken out."""
    for form in (url, html.unescape(url)):
        match = _SCHEME.match(re.sub(r"[\x00-\x20\x7f]", "", form))
        if match and match.group(1).lower() not in SAFE_SCHEMES:
            return False
    return True


def safe_link(label: str, url: str) -> str:
    """`label` (Markdown, made with the functions above) linked to `url` if it is http(s) or
    relative; any other scheme gives the label alone, as text. Characters that would end the
    link's target (spaces, parentheses, brackets, quotes, ...) are percent-encoded."""
    if not is_safe_url(url):
        return label
    target = quote(re.sub(r"[\x00-\x1f\x7f]", "", url), safe="/?#&=%:+,;@!$*~.-_")
    return f"[{label}]({target})"


def safe_image(alt: str, url: str) -> str:
    """An image with `alt` (Markdown) as its text, where `url` is http(s) or relative; else the
    alt text alone."""
    link = safe_link(alt, url)
    return f"!{link}" if link != alt else alt


def path_url(path: PurePosixPath, up: str = "") -> str:
    """A relative link to a file under the docs folder from `up` ("", "../", ...) below it,
    each segment of `path` percent-encoded."""
    return up + "/".join(url_part(part) for part in path.parts)


def fenced(code: str, language: str = "", indent: str = "", searchable: bool = True) -> str:
    """`code` as a fenced block (ending with a newline), every line prefixed with `indent`
    (four spaces put it inside a tab of pymdownx.tabbed). `searchable=False` keeps it out of
    the site's search index (Material skips a block marked data-search-exclude): a composed
    shader holds the code of every snippet it uses and would match every search."""
    longest = max((len(run) for run in _BACKTICKS.findall(code)), default=0)
    fence = "`" * max(3, longest + 1)
    opening = f"{fence}{language}" if searchable else (
        f'{fence} {{ .{language or "text"} data-search-exclude="" }}')  # fmt: skip
    lines = [opening, *code.rstrip("\n").split("\n"), fence]
    return "".join(f"{indent}{line}\n" if line else "\n" for line in lines)


def table(header: list[str], rows: list[list[str]]) -> str:
    """A Markdown table; the cells are Markdown already (`md_text` and `md_prose` keep a value
    in its cell)."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def _one_definition_a_line(latex: str) -> str:
    """A formula that states several things side by side, `a = ..., \\quad b = ...` (the
    catalog's way of giving a term and then its parts), as one line each, centred: KaTeX never
    breaks a display formula, and one line of three definitions runs past a page's width (the
    env BRDF approximation was 1,544 px in a 688 px column). The separators are taken only at
    the formula's top level, outside every brace group, \\left...\\right pair and environment."""
    parts, depth, start, i = [], 0, 0, 0
    while i < len(latex):
        char = latex[i]
        if char == "{" or latex.startswith(("\\left", "\\begin"), i):
            depth += 1
        elif char == "}" or latex.startswith(("\\right", "\\end"), i):
            depth -= 1
        elif depth == 0 and latex.startswith("\\quad", i) and not latex[i + 5 : i + 6].isalpha():
            parts.append(latex[start:i])
            start = i + 5
            i = start
            continue
        i += 1
    parts.append(latex[start:])
    parts = [part.strip().rstrip(",").rstrip("\\,").strip() for part in parts]
    parts = [part for part in parts if part]
    if len(parts) < 2:
        return latex
    return "\\begin{gathered}\n" + " \\\\\n".join(parts) + "\n\\end{gathered}"


def math_block(latex: str) -> str:
    """Display math as pymdownx.arithmatex's generic mode writes it, for the local KaTeX: the
    same div, written here as raw HTML with the LaTeX escaped, so that no formula can leave it
    (through `$$`, a line of HTML or a blank line in a formula would end up on the page)."""
    body = "\n".join(line for line in latex.strip().splitlines() if line.strip())
    body = _one_definition_a_line(body)
    escaped = html.escape(body, quote=False).replace('"', "&quot;")  # as arithmatex escapes
    return f'<div class="arithmatex">\\[\n{escaped}\n\\]</div>\n'
