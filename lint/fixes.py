"""Applying fixes: non-overlapping edits of the user's text, repeated until nothing applicable
is left (a fix may reveal another), so that fixing is idempotent."""

from __future__ import annotations

from collections.abc import Callable

from .finding import Edit, Finding

MAX_ROUNDS = 10


def apply_edits(text: str, edits: list[Edit]) -> str:
    """Apply edits that do not overlap (later ones first, so earlier positions stay valid)."""
    lines = text.split("\n")
    starts = [0]
    for line in lines:
        starts.append(starts[-1] + len(line) + 1)

    def offset(line: int, column: int) -> int:
        line = min(max(line, 1), len(lines))
        return min(starts[line - 1] + column - 1, starts[line] - 1)

    spans = sorted(
        ((offset(e.line, e.column), offset(e.end_line, e.end_column), e.content) for e in edits),
        reverse=True,
    )
    out = text
    for start, end, content in spans:
        out = out[:start] + content + out[end:]
    return out


def _choose(findings: list[Finding], allowed: set[str]) -> list[Edit]:
    """Edits of the applicable fixes, skipping any fix that overlaps one already taken."""
    taken: list[tuple[tuple[int, int], tuple[int, int]]] = []
    edits: list[Edit] = []
    for finding in findings:
        fix = finding.fix
        if fix is None or fix.applicability not in allowed or not fix.edits:
            continue
        spans = [((e.line, e.column), (e.end_line, e.end_column)) for e in fix.edits]
        if any(a < d and c < b for a, b in spans for c, d in taken):
            continue
        taken += spans
        edits += fix.edits
    return edits


def apply_fixes(
    text: str,
    findings: list[Finding],
    allowed: set[str],
    relint: Callable[[str], list[Finding]],
) -> tuple[str, int]:
    """The text with every applicable fix applied, and how many were."""
    count = 0
    for _ in range(MAX_ROUNDS):
        edits = _choose(findings, allowed)
        if not edits:
            break
        new_text = apply_edits(text, edits)
        if new_text == text:
            break
        count += sum(1 for f in findings if f.fix is not None and f.fix.edits
                     and all(e in edits for e in f.fix.edits))  # fmt: skip
        text = new_text
        findings = relint(text)
    return text, count
