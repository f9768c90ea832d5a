"""Map the lines of a composed shader back to the snippet files they came from.

The emitter writes a marker comment `// source: FILE:LINE` in front of each block it copies, meaning
"the next line is line LINE of FILE". Diagnostics on the composed text are then reported where the
user can fix them: in the snippet. `FILE` may be `<generated>` for code the emitter wrote itself;
those lines, the markers and anything before the first marker belong to the composed file.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

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
