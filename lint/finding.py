"""What a rule reports: a finding at a span of the user's file, and the fix it offers."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal

Severity = Literal["error", "warning", "info"]
# How sure a finding is. certain: the code is wrong for every input, or for a named reachable
# one (the first frame, the first iteration, a constant); likely: the evidence is real but rests
# on reading the author's intent (names, a twin, a path the analysis cannot rule out); possible:
# a range that merely reaches the bad value (opt-in rules only).
Certainty = Literal["certain", "likely", "possible"]
CERTAINTIES: tuple[Certainty, ...] = ("certain", "likely", "possible")
Applicability = Literal["safe", "unsafe"]


@dataclass(frozen=True)
class Edit:
    """Replace the text from (line, column) up to, not including, (end_line, end_column) by
    `content`. Positions are 1-based, in the file as the user wrote it."""

    line: int
    column: int
    end_line: int
    end_column: int
    content: str

    def as_json(self) -> dict[str, Any]:
        return {
            "line": self.line,
            "column": self.column,
            "end_line": self.end_line,
            "end_column": self.end_column,
            "content": self.content,
        }


@dataclass(frozen=True)
class Fix:
    """Edits that remove the finding. Safe fixes keep the program's meaning and `--fix` applies
    them; unsafe ones (an inserted clamp or epsilon) change values and need `--unsafe-fixes`."""

    message: str
    edits: tuple[Edit, ...]
    applicability: Applicability = "safe"

    def as_json(self) -> dict[str, Any]:
        return {
            "message": self.message,
            "applicability": self.applicability,
            "edits": [e.as_json() for e in self.edits],
        }


@dataclass(frozen=True)
class Finding:
    """One problem at a span (1-based lines and columns, the end exclusive)."""

    file: str
    line: int
    column: int
    end_line: int
    end_column: int
    code: str
    severity: Severity
    message: str
    fix: Fix | None = field(default=None, compare=False)
    certainty: Certainty = field(default="likely", compare=False)

    def as_json(self) -> dict[str, Any]:
        return {
            "file": self.file,
            "line": self.line,
            "column": self.column,
            "end_line": self.end_line,
            "end_column": self.end_column,
            "code": self.code,
            "severity": self.severity,
            "message": self.message,
            "certainty": self.certainty,
            "fix": None if self.fix is None else self.fix.as_json(),
        }

    @property
    def sort_key(self) -> tuple[str, int, int, str]:
        return (self.file, self.line, self.column, self.code)
