"""Markdown building blocks for the generated pages.

Shader text only ever reaches a page inside a fenced code block: Pygments highlights it and
escapes every `<` and `&`, so a comment such as `// </script>` stays text. A fence is made one
backtick longer than the longest run of backticks in the code, so no code can close it early.
Prose from the catalog (summaries, sources) is escaped for HTML and for table cells, because
Markdown passes raw HTML through untouched.
"""

from __future__ import annotations

import html
import re

_BACKTICKS = re.compile(r"`+")


def fenced(code: str, language: str = "", indent: str = "") -> str:
    """`code` as a fenced block (ending with a newline), every line prefixed with `indent`
    (four spaces put it inside a tab of pymdownx.tabbed)."""
    longest = max((len(run) for run in _BACKTICKS.findall(code)), default=0)
    fence = "`" * max(3, longest + 1)
    lines = [f"{fence}{language}", *code.rstrip("\n").split("\n"), fence]
    return "".join(f"{indent}{line}\n" if line else "\n" for line in lines)


def text(value: str) -> str:
    """Plain text from the catalog as Markdown prose: no raw HTML gets through."""
    return html.escape(value, quote=False)


def cell(value: str) -> str:
    """Plain text as one cell of a Markdown table."""
    return text(value).replace("|", "\\|").replace("\n", " ")


def code(value: str) -> str:
    """An inline code span holding `value` exactly."""
    longest = max((len(run) for run in _BACKTICKS.findall(value)), default=0)
    ticks = "`" * (longest + 1)
    pad = " " if value.startswith("`") or value.endswith("`") else ""
    return f"{ticks}{pad}{value}{pad}{ticks}"


def table(header: list[str], rows: list[list[str]]) -> str:
    """A Markdown table; the cells are Markdown already (use `cell` for plain text)."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def math_block(latex: str) -> str:
    """Display math for pymdownx.arithmatex (generic mode, rendered by the local KaTeX)."""
    return f"$$\n{latex.strip()}\n$$\n"
