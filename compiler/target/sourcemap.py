"""Map the lines of a composed shader back to the snippet files they came from.

The emitter writes a marker comment `// source: FILE:LINE` in front of each block it copies, meaning
"the next line is line LINE of FILE". Diagnostics on the composed text are then reported where the
user can fix them: in the snippet. `FILE` may be `<generated>` for code the emitter wrote itself;
those lines, the markers and anything before the first marker belong to the composed file.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from glint.compiler.glsl.includes import expand_includes, has_includes

MARKER = re.compile(r"^// source: (\S+):(\d+)\s*$")
GENERATED = "<generated>"


def source_marker(origin: str, line: int) -> str:
    """The comment saying that the next line is line `line` of `origin` (MARKER reads it)."""
    return f"// source: {origin}:{line}"


@dataclass(frozen=True)
class Origin:
    """Where one line of a composed shader came from (1-based line)."""

    file: str
    line: int


def split_lines(text: str) -> list[str]:
    """Split on newlines the way a GLSL compiler counts them (a final newline ends a line)."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return [line.removesuffix("\r") for line in lines]


def build_line_map(text: str, own_name: str) -> list[Origin]:
    """Return the origin of every line of `text`: index i describes line i + 1."""
    origins: list[Origin] = []
    # The snippet file and line that the next line corresponds to; None means "our own line".
    current: tuple[str, int] | None = None
    for index, line in enumerate(split_lines(text)):
        own = Origin(own_name, index + 1)
        marker = MARKER.match(line)
        if marker:
            origins.append(own)
            file, first = marker.group(1), int(marker.group(2))
            current = None if file == GENERATED else (file, first)
            continue
        if current is None:
            origins.append(own)
        else:
            origins.append(Origin(*current))
            current = (current[0], current[1] + 1)
    return origins


def marker_path(path: str) -> str:
    """A file path as a `// source: PATH:LINE` marker holds it: one word on one line, each
    whitespace or control character percent-encoded (a space as %20)."""
    return "".join(
        char if char.isprintable() and not char.isspace() else _percent(char) for char in path
    )


def _percent(char: str) -> str:
    return "".join(f"%{byte:02X}" for byte in char.encode("utf-8", "surrogatepass"))


def with_includes(text: str, name: str) -> str:
    """The file's text with its `#include`s in place (glsl/includes.py) and a source marker
    wherever it moves to another file or place, so that validate and render report an
    included file's own line; the text as it is where it includes nothing."""
    if not has_includes(text):
        return text
    expanded = expand_includes(text, name)
    out: list[str] = []
    expected = (expanded.origins[0][0], 1) if expanded.origins else None
    for line, (file, number) in zip(expanded.text.split("\n"), expanded.origins, strict=True):
        if (file, number) != expected:
            out.append(source_marker(marker_path(file), number))
        out.append(line)
        expected = (file, number + 1)
    return "\n".join(out)
