"""`#include "file"` of local files, as lygia-style projects write it: each directive replaced by
the file it names (relative to the including file), recursively, with a line map from every
line of the result back to its file and line, so that a finding in an included file is
reported there.

Include guards (`#ifndef X` / `#define X` ... `#endif`) are left to the preprocessor, which
skips a guarded file's second copy; `#pragma once` is honoured here. A file that includes
itself, directly or through others, is a cycle: an error naming the chain. ShaderToy and the
GLSL compilers have no `#include`: the result is what they must be given instead.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from glint.compiler.errors import InputError
from glint.compiler.files import MiB, read_user_text

# `#include "path"` or `#include <path>`, alone on its line (a trailing comment allowed).
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*(?:"([^"\n]+)"|<([^>\n]+)>)[ \t]*(?://.*)?$')
_ONCE = re.compile(r"^[ \t]*#[ \t]*pragma[ \t]+once\b", re.M)
MAX_DEPTH = 64
INCLUDE_FILE_LIMIT = 4 * MiB


class IncludeError(InputError):
    """An #include that cannot be followed: where it stands, and why."""

    def __init__(self, file: str, line: int, reason: str) -> None:
        self.file, self.line, self.reason = file, line, reason
        super().__init__(f"{file}:{line}: {reason}")


@dataclass(frozen=True)
class Expanded:
    text: str
    origins: tuple[tuple[str, int], ...]  # per line of `text`: (file, line in that file)
    sources: dict[str, str]  # every file read (the first too), by name: its text

    def origin(self, line: int) -> tuple[str, int]:
        """The file and line that line `line` (1-based) of the text came from."""
        return self.origins[min(max(line, 1), len(self.origins)) - 1]


def has_includes(text: str) -> bool:
    return any(INCLUDE.match(line) for line in text.split("\n"))


def expand_includes(text: str, name: str) -> Expanded:
    """`text` (the file `name`) with its includes replaced, and where each line came from."""
    lines: list[str] = []
    origins: list[tuple[str, int]] = []
    sources = {name: text}
    once: set[Path] = set()

    def expand(body: str, file: str, chain: list[Path]) -> None:
        if _ONCE.search(body):
            once.add(chain[-1])
        for number, line in enumerate(body.split("\n"), 1):
            match = INCLUDE.match(line)
            if match is None:
                lines.append(line)
                origins.append((file, number))
                continue
            target = (chain[-1].parent / (match[1] or match[2])).resolve()
            directive = f"#include {match[1] or match[2]!r}"
            if target in chain:
                cycle = " -> ".join(p.name for p in [*chain[chain.index(target) :], target])
                raise IncludeError(
                    file, number, f"{directive}: a cycle ({cycle}); include each file once"
                )
            if len(chain) >= MAX_DEPTH:
                raise IncludeError(
                    file, number, f"{directive}: includes nested over {MAX_DEPTH} deep"
                )
            lines.append("")  # the directive's own line, kept so that lines stay in step
            origins.append((file, number))
            if target in once:
                continue
            if not target.is_file():
                raise IncludeError(
                    file, number,
                    f"{directive}: no such file (looked for {target}; the path is relative to "
                    f"{Path(file).name})",
                )  # fmt: skip
            try:
                included = read_user_text(target, INCLUDE_FILE_LIMIT, "included GLSL file")
            except InputError as exc:
                raise IncludeError(file, number, f"{directive}: {exc.message}") from None
            shown = _shown(target)
            sources[shown] = included
            expand(included, shown, [*chain, target])

    expand(text, name, [Path(name).resolve()])
    return Expanded("\n".join(lines), tuple(origins), sources)


def _shown(path: Path) -> str:
    """The path relative to the working folder where it is under it, else absolute."""
    try:
        return str(path.relative_to(Path.cwd().resolve()))
    except ValueError:
        return str(path)
