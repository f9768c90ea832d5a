"""Helpers shared by the numerical rules: when a value range is evidence of a bad value
(reaches_below, reaches_zero, is_raw_dot), the builtin calls of a file, an expression shortened
for a message, the unsafe wrapping fix, and NumericalRule, the rules' base class."""

from __future__ import annotations

import math
import re
from collections.abc import Iterator

from lark import Token, Tree

from glint.compiler.glsl.ast import SourceFile, binary_parts

from ...analysis.ranges import Interval
from ...analysis.syntax import callee_name
from ...analysis.values import Value
from ...context import LintContext
from ...finding import Certainty, Finding, Fix, Severity
from .. import Rule

Node = Tree | Token


# How far past a limit a bound must be to count: 1 - exp(-x) may come out as -2e-16 from the
# bounds' own rounding, which is not a negative value anyone wrote.
SLACK = 1e-9


def reaches_below(r: Interval, c: float) -> bool:
    """Values below c are reached on evidence: a finite lower bound under c, or a range that
    lies under c entirely. (-inf, 1] from `1.0 - x * x` with x unknown is no such evidence."""
    return r.lo < c - SLACK and (r.lo > -math.inf or r.hi <= c)


def reaches_zero(v: Value) -> bool:
    """Zero is in the range on evidence: a value the model knows reaches 0 (a length, a dot
    product, sin, max(x, 0.0), x - c across c, a product with such a factor). A range that
    merely contains 0 after interval arithmetic is no evidence: GGX's 1 + NoH²(a² - 1) is in
    [0, 1.25] by intervals and never below a²."""
    r = v.range
    if not r.may_be_zero or r.is_unknown:  # nothing known is no evidence of anything
        return False
    return v.zero or v.origin in ("dot", "length", "distance")


def is_raw_dot(v: Value) -> bool:
    return v.origin == "dot"


def _named_builtin_calls(ctx: LintContext) -> list[tuple[Tree, str]]:
    assert ctx.tree is not None
    defined = {definition.name for definition in SourceFile(ctx.tree).functions}
    return [
        (node, name) for node in ctx.nodes("call")
        if (name := callee_name(node)) is not None and name not in defined
    ]  # fmt: skip


def builtin_calls(ctx: LintContext, *names: str) -> Iterator[tuple[Tree, str]]:
    """Calls of these builtins (a function the file defines with the same name is not the
    builtin)."""
    # every numerical rule looks at every call: name them once per file
    for node, name in ctx.memo(_named_builtin_calls):
        if name in names:
            yield node, name


def text(ctx: LintContext, node: Node, limit: int = 48) -> str:
    """The expression as written, on one line, shortened for a message."""
    s = re.sub(r"\s+", " ", ctx.node_text(node)).strip()
    return s if len(s) <= limit else s[: limit - 3] + "..."


def range_note(v: Value, fallback: str) -> str:
    return f"range {v.range.describe()}" if not v.range.is_unknown else fallback


def wrap_fix(ctx: LintContext, node: Node, template: str, message: str) -> Fix | None:
    """An unsafe fix that rewrites `node` as `template` with {} the node's text; None where
    a macro makes the position untrustworthy."""
    edit = ctx.replace(node, template.format(ctx.node_text(node).strip()))
    return Fix(message, (edit,), "unsafe") if edit is not None else None


class NumericalRule(Rule):
    category = "numerical"

    def emit(
        self,
        ctx: LintContext,
        where: Node,
        message: str,
        fix: Fix | None = None,
        severity: Severity | None = None,
        certainty: Certainty | None = None,
    ) -> Finding:
        sure = certainty or self.certainty
        return ctx.finding(self.code, severity or self.severity, where, message, fix, sure)


def divisor_of(node: Tree) -> Node | None:
    """The divisor of `a / b` or `a /= b`, None for any other node."""
    if node.data in ("binary", "assignment"):
        _, op, right = binary_parts(node)
        if op == ("/" if node.data == "binary" else "/="):
            return right
    return None
