"""Lint one source: read, preprocess, parse, run the enabled rules, apply suppressions, and
apply fixes when asked. Nothing here raises on bad input: every problem is a finding."""

from __future__ import annotations

import codecs
import re
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

from glint.compiler.collector import paused
from glint.compiler.errors import InputError
from glint.compiler.glsl import parse, preprocess
from glint.compiler.target.shadertoy import Tab, predefined_macros

from .context import LintContext, indexed
from .finding import Finding
from .fixes import apply_fixes
from .nesting import Nesting, bracket_nesting, tree_nesting
from .options import Options
from .rules import all_rules
from .rules.style.s001_unused_suppression import UNUSED_SUPPRESSION, unused_suppressions
from .suppressions import apply_suppressions, parse_suppressions

# Files larger than this are reported (C006) rather than analysed: glslang still sees them, but
# parsing megabytes of GLSL in Python would take minutes and no real shader is that large.
MAX_BYTES = 1_000_000
RECURSION_LIMIT = 20_000


@dataclass
class LintResult:
    file: str
    findings: list[Finding]
    text: str  # the source after fixes (the original when nothing was fixed)
    fixed: int = 0  # how many fixes were applied
    notes: list[str] = field(default_factory=list)
    bom: bool = False  # the file opened with a UTF-8 byte-order mark
    failed: bool = False  # glint itself failed on this file (a bug): see notes, nothing cached

    def encoded(self) -> bytes:
        """The bytes to write back after fixes: UTF-8, the file's byte-order mark kept."""
        # surrogateescape gives back, byte for byte, what a comment held that was not UTF-8
        body = self.text.encode("utf-8", "surrogateescape")
        return (codecs.BOM_UTF8 if self.bom else b"") + body


# A comment, which may hold bytes of an older encoding (a Latin-1 `°` in a 2013 shader): GLSL
# and glslang ignore what a comment holds, so only a byte outside comments makes a file unreadable.
_COMMENT = re.compile(r"//[^\n]*|/\*.*?(?:\*/|\Z)", re.S)
_ESCAPED = re.compile("[\udc80-\udcff]")


def decode(data: bytes, file: str) -> tuple[str, str | None]:
    """The text of a file's bytes, or "" and why it cannot be linted."""
    if len(data) > MAX_BYTES:
        return "", f"too large to analyse ({len(data) / 1e6:.1f} MB; the limit is 1 MB)"
    if b"\0" in data:
        return "", "binary data (a NUL byte), not GLSL source"
    try:
        # utf-8-sig drops a byte-order mark, which editors on Windows write and GLSL rejects.
        return data.decode("utf-8-sig"), None
    except UnicodeDecodeError:
        text = data.decode("utf-8-sig", "surrogateescape")
    stray = _ESCAPED.search(_COMMENT.sub(lambda m: " " * len(m.group()), text))
    if stray is None:
        return text, None
    line = text[: stray.start()].count("\n") + 1
    byte = ord(stray.group()) - 0xDC00
    return "", f"not UTF-8 text (invalid byte 0x{byte:02x} on line {line})"


def build_context(text: str, file: str, options: Options, tab: Tab | None = None) -> LintContext:
    """The file preprocessed and parsed with the Common tab's code in front, as ShaderToy
    compiles it: its functions, macros and globals are known to the file's analysis."""
    tab = tab or options.tab()
    common = "" if tab.is_common or not tab.common else tab.common.rstrip("\n") + "\n"
    ctx = LintContext(file=file, text=text, target=options.target, tab=tab,
                      line_offset=common.count("\n"), use_glslang=options.glslang)  # fmt: skip
    ctx.reports_glslang_errors = options.glslang and options.enabled("C001", file)
    try:
        # lenient: C004 reports an undefined macro in #if, the rest of the file is still linted
        ctx.pre = preprocess(
            common + text, file, predefined_macros(options.target, common + text), lenient=True
        )
    except InputError as exc:
        ctx.front_end_error = exc
        return ctx
    except RecursionError:  # macro calls nested thousands deep in arguments
        ctx.too_deep = True
        return ctx
    ctx.nesting = Nesting(brackets=bracket_nesting(ctx.pre.text))
    if ctx.nesting.too_deep():
        ctx.too_deep = True
        return ctx
    try:
        ctx.tree = parse(ctx.pre.text, file)
    except InputError as exc:
        ctx.front_end_error = exc
    except RecursionError:
        # Input nested deeper than the parser can follow: C006 alone is reported.
        ctx.tree = None
        ctx.too_deep = True
    if ctx.tree is not None:
        # Statements or loops nested, or chains, deeper than the analyses follow: C006 alone,
        # before any analysis runs into them (lint/nesting.py).
        ctx.nesting = tree_nesting(ctx.tree, ctx.nesting.brackets)
        if ctx.nesting.too_deep():
            ctx.tree = None
            ctx.too_deep = True
    return ctx


def lint_source(
    text: str,
    file: str = "<input>",
    options: Options | None = None,
    read_problem: str = "",
    tab: Tab | None = None,
) -> list[Finding]:
    """Every enabled finding for `text` (within `tab`: the Common tab in front, the channels'
    types), sorted by position. Findings in the Common tab's code are left to that file."""
    # A lint allocates a parse tree and the analyses' tables, hundreds of thousands of objects
    # that live until the file is done: the collector is paused (a cold lint of the corpus:
    # 9.4 s -> 8.3 s) and the file's garbage collected once, after _findings has returned it.
    with paused(collect_after=True):
        return _findings(text, file, options or Options(), read_problem, tab)


def _findings(
    text: str, file: str, options: Options, read_problem: str, tab: Tab | None
) -> list[Finding]:
    with _recursion_limit(RECURSION_LIMIT):
        ctx = build_context(text, file, options, tab)
        ctx.read_problem = read_problem
        findings: list[Finding] = []
        # Rules that report on what the others found out (C006: too deep) run last.
        rules = sorted(all_rules().items(), key=lambda item: item[1].runs_last)
        with indexed(ctx.tree):  # the rules and analyses walk the tree many times
            for code, rule in rules:
                if code == UNUSED_SUPPRESSION or not options.enabled(code, file):
                    continue
                if rule.needs_tree and ctx.tree is None:
                    continue
                try:
                    findings.extend(rule().check(ctx))
                except RecursionError:
                    ctx.too_deep = True
    findings = [f for f in findings if f.line >= 1]  # not on the Common tab's lines
    findings = _without_explained_glslang_errors(findings)
    suppressions = parse_suppressions(text)
    kept = apply_suppressions(findings, suppressions)
    if options.enabled(UNUSED_SUPPRESSION, file):
        ran = {c for c in all_rules() if options.enabled(c, file)}
        kept += unused_suppressions(ctx, suppressions, ran)
    return sorted(set(kept), key=lambda f: f.sort_key)


def _without_explained_glslang_errors(findings: list[Finding]) -> list[Finding]:
    """glslang's error (C001) on a line where a glint rule reports an error says the same thing
    less clearly (`float x = 1;` is P005 with a fix, and glslang's "cannot convert"): keep
    glint's."""
    explained = {(f.file, f.line) for f in findings if f.severity == "error" and f.code != "C001"}
    return [f for f in findings if f.code != "C001" or (f.file, f.line) not in explained]


@contextmanager
def _recursion_limit(limit: int) -> Iterator[None]:
    """Expressions are analysed recursively, and generated shaders have long operator chains
    (hundreds of `+` terms); Python's default limit of 1000 frames is too low for them. Python
    3.11 runs Python-to-Python calls without C stack, so a higher limit is safe."""
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, limit))
    try:
        yield
    finally:
        sys.setrecursionlimit(old)


def lint_text(
    text: str,
    file: str = "<input>",
    options: Options | None = None,
    fix: bool = False,
    unsafe_fixes: bool = False,
    read_problem: str = "",
    tab: Tab | None = None,
) -> LintResult:
    """Lint, and with `fix` apply the fixes (safe ones; unsafe too with `unsafe_fixes`)."""
    options = options or Options()
    findings = lint_source(text, file, options, read_problem, tab)
    if not fix or read_problem:
        return LintResult(file, findings, text)
    allowed = {"safe", "unsafe"} if unsafe_fixes else {"safe"}
    fixed_text, count = apply_fixes(
        text, findings, allowed, lambda t: lint_source(t, file, options, tab=tab)
    )
    if count == 0:
        return LintResult(file, findings, text)
    after = lint_source(fixed_text, file, options, tab=tab)
    if _errors(after) > _errors(findings):
        # A fix must never break a shader; if one did, keep the user's text and say so.
        note = f"{file}: fixes not applied: they would add compile errors (a glint bug; report it)"
        return LintResult(file, findings, text, 0, [note])
    return LintResult(file, after, fixed_text, count)


def _errors(findings: list[Finding]) -> int:
    return sum(1 for f in findings if f.severity == "error")


def lint_bytes(data: bytes, file: str, options: Options | None = None, fix: bool = False,
               unsafe_fixes: bool = False, tab: Tab | None = None) -> LintResult:  # fmt: skip
    text, problem = decode(data, file)
    result = lint_text(text, file, options, fix, unsafe_fixes, problem or "", tab)
    result.bom = data.startswith(codecs.BOM_UTF8)
    return result
