"""Which rules run and how: select and ignore by code or prefix, per-file ignores, the target;
and the checks that a selection names known codes and leaves some rule to run."""

from __future__ import annotations

import fnmatch
from dataclasses import dataclass, field
from functools import cache
from pathlib import PurePath

from glint.compiler.target.shadertoy import CHANNELS, Tab


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
    # what iChannel0..3 are bound to: "2d", "cube" or "3d" (shadertoy.CHANNEL_KINDS)
    channels: tuple[str, ...] = ("2d",) * CHANNELS

    def tab(self) -> Tab:
        """The ShaderToy tab a file is linted in when it has no Common tab."""
        return Tab(channels=self.channels)

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
    return not rest or rest[0].isdigit() or pattern[-1:].isdigit()


def _matches(file: str, glob: str) -> bool:
    path = PurePath(file)
    return fnmatch.fnmatch(str(path), glob) or fnmatch.fnmatch(path.name, glob)


def unknown_code(codes: list[str]) -> str | None:
    """The first of `codes` that is neither ALL, DEFAULT, a category prefix nor a prefix of a
    rule's code (N, N0, N001), or None when all are known. An empty code is unknown."""
    from .rules import CATEGORY_PREFIX, rule_codes  # no rule module is imported

    prefixes = set(CATEGORY_PREFIX.values())
    for raw in codes:
        code = raw.strip().upper()
        if code in ("ALL", "DEFAULT") or code in prefixes:
            continue
        if not code or not any(c.startswith(code) and _prefix_ok(c, code) for c in rule_codes()):
            return raw
    return None


def enables_some_rule(options: Options) -> bool:
    """Whether the selection, after ignore, runs at least one rule (per-file ignores aside: a
    file may be ignored whole). Imports the rules only to tell which are in DEFAULT when an
    ignore list could remove them all."""
    from .rules import rule_codes

    select = [c.strip().upper() for c in options.select]
    explicit = Options(select=[c for c in select if c != "DEFAULT"], ignore=options.ignore)
    if any(explicit.enabled(code) for code in rule_codes()):
        return True
    if "DEFAULT" not in select:
        return False
    if not options.ignore:
        return True  # DEFAULT holds rules (a test checks)
    plain = Options(select=select, ignore=options.ignore)
    return any(plain.enabled(code) for code in rule_codes())
