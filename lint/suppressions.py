"""Inline suppressions: `// glint: ignore[CODE, ...]` silences those codes on its own line (or,
written alone on a line, on the next line); `// glint: file-ignore[CODE, ...]` in the whole file.
Without a bracket every code is silenced. A suppression that silences nothing is itself a
finding (S001), so stale ones do not pile up."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from .finding import Finding

_COMMENT = re.compile(r"//\s*glint\s*:\s*(ignore|file-ignore)\b\s*(?:\[([^\]]*)\])?")


@dataclass
class Suppression:
    line: int  # where the comment is
    column: int
    end_column: int
    codes: frozenset[str] | None  # None: every code
    file_wide: bool
    targets: tuple[int, ...]  # the lines it covers (empty for file-wide)
    used: set[str] = field(default_factory=set)

    def covers(self, finding: Finding) -> bool:
        if not self.file_wide and finding.line not in self.targets:
            return False
        return self.codes is None or finding.code in self.codes


def parse_suppressions(text: str) -> list[Suppression]:
    found = []
    lines = text.split("\n")
    for number, line in enumerate(lines, start=1):
        match = _COMMENT.search(line)
        if not match:
            continue
        codes = None
        if match.group(2) is not None:
            codes = frozenset(c.strip().upper() for c in match.group(2).split(",") if c.strip())
        file_wide = match.group(1) == "file-ignore"
        alone = not line[: match.start()].strip()
        targets = () if file_wide else ((number, number + 1) if alone else (number,))
        found.append(
            Suppression(number, match.start() + 1, match.end() + 1, codes, file_wide, targets)
        )
    return found


def apply_suppressions(findings: list[Finding], suppressions: list[Suppression]) -> list[Finding]:
    """The findings no suppression covers; marks which suppressions were used."""
    kept = []
    for finding in findings:
        covering = [s for s in suppressions if s.covers(finding)]
        for suppression in covering:
            suppression.used.add(finding.code)
        if not covering:
            kept.append(finding)
    return kept
