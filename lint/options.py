"""Which rules run and how: select and ignore by code or prefix, per-file ignores, the target."""

from __future__ import annotations

import fnmatch
from dataclasses import dataclass, field
from functools import cache
from pathlib import PurePath


@dataclass
class Options:
    # codes, prefixes, ALL, or DEFAULT: the rules whose findings on real shaders are worth
    # acting on (lint/precision.py measures them); the others run when selected by code,
    # prefix or ALL, like ruff's non-default rules
    select: list[str] = field(default_factory=lambda: ["DEFAULT"])
    ignore: list[str] = field(default_factory=list)
    per_file_ignores: dict[str, list[str]] = field(default_factory=dict)  # glob -> codes
    target: str = "shadertoy"  # shadertoy, webgl2 or desktop
    glslang: bool = True  # run glslangValidator (C001, C002)

    def enabled(self, code: str, file: str = "") -> bool:
        """Selected, not ignored, and not ignored for this file. The longest matching code
        prefix wins, so `--select N --ignore N005` and `--ignore N --select N005` both work."""
        extra = [c for glob, codes in self.per_file_ignores.items() if _matches(file, glob)
                 for c in codes]  # fmt: skip
        select = _best(code, self.select)
        ignore = _best(code, self.ignore + extra)
        return select > ignore if select or ignore else False


def _best(code: str, patterns: list[str]) -> int:
    """Length of the longest pattern that matches the code (ALL and DEFAULT count as 0.5); 0 if
    none."""
    best = 0.0
    for pattern in patterns:
        pattern = pattern.strip().upper()
        if pattern == "ALL" or (pattern == "DEFAULT" and code in default_codes()):
            best = max(best, 0.5)
        elif code.startswith(pattern) and _prefix_ok(code, pattern):
            best = max(best, float(len(pattern)))
    return int(best * 2)


@cache
def default_codes() -> frozenset[str]:
    """The codes of the rules that run when nothing is selected."""
    from .rules import all_rules  # the rules import the lint context, which needs no options

    return frozenset(code for code, rule in all_rules().items() if rule.default)


def _prefix_ok(code: str, pattern: str) -> bool:
    # "P" must not select "PF001": a letter prefix matches only codes of that category.
    rest = code[len(pattern) :]
    return not rest or rest[0].isdigit() or pattern[-1].isdigit()


def _matches(file: str, glob: str) -> bool:
    path = PurePath(file)
    return fnmatch.fnmatch(str(path), glob) or fnmatch.fnmatch(path.name, glob)
