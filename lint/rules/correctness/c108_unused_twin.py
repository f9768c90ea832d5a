"""C108 unused-twin."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import (
    Assignment,
    Call,
    CompoundStatement,
    Declarator,
    Variable,
    first_child,
)

from ...analysis.functions import Function, functions
from ...analysis.syntax import call_args, var_name
from ...context import LintContext, Node, walk_kind
from ...finding import Finding
from .. import Rule, register
from ._twins import copy_suffix, shape, twin_kind

_STATEMENTS = ("expression_statement", "declaration_statement", "jump_statement")


@register
class UnusedTwin(Rule):
    """Finds a local variable that is computed and never read while its twin, a variable of the
    same name but for one digit or axis letter (`t`/`t2`, `ddx_uvw`/`ddy_uvw`) or a saved copy
    (`glow2`/`glow2Save`), computed the same way, is read: the code was copied and one use of
    the twin was meant to be the unused one.

    Where the slip shows it is reported there: a call that passes the used twin twice
    (`f(p, ddy, ddy)` with `ddx` unused), or a statement that reads the live value where the
    statements beside it read saved copies (`glowSave`, `glow2`, `glow3Save` with `glow2Save`
    unused); otherwise at the unused variable. A plain unused variable is not reported: the
    compiler drops it. Only twins computed by expressions of the same shape (or a copy saved of
    its twin) count.

    Why is this bad?
        The value the author computed for one purpose is thrown away and its twin is used in
        its place: the result uses the wrong axis, the wrong sample or a value that changed
        since it was saved. No compiler warns, since each line is valid on its own.

    Example:
        vec2 ddx_uvw = dFdx(uv);
        vec2 ddy_uvw = dFdy(uv);
        float c = checkersGrad(uv, ddy_uvw, ddy_uvw);

    Use instead:
        vec2 ddx_uvw = dFdx(uv);
        vec2 ddy_uvw = dFdy(uv);
        float c = checkersGrad(uv, ddx_uvw, ddy_uvw);

    Fix safety:
        No fix: which use of the twin was meant is the author's choice (or the unused value is
        leftover work to delete).

    References:
        - CWE-563, Assignment to Variable without Use
        - Beller et al., "Analyzing the last line effect" (copy-paste slips in parallel code)
    """

    code = "C108"
    name = "unused-twin"
    default = False  # opt-in: fewer than 15 findings on the corpus to judge it by
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        parents = ctx.parents()
        for fn in functions(ctx):
            reads = _reads(fn, parents)
            names = set(reads) | set(fn.locals) | set(fn.params)
            for name, init in fn.init.items():
                if reads[name] or name in fn.declared_twice:
                    continue
                # One twin of a kind only: an unused member of a family (f0, f1, f2, ...) says
                # nothing about which of the others took its place. A saved copy's own twin
                # (what it saves) comes first.
                for kind in ("copy", "digit", "axis"):
                    twins = [n for n in names if twin_kind(name, n) == kind]
                    if len(twins) == 1 and reads[twins[0]]:
                        if _parallel(fn, name, twins[0], kind, init):
                            yield self._finding(ctx, fn, name, twins[0], kind, init, parents)
                        break

    def _finding(self, ctx: LintContext, fn: Function, name: str, twin: str, kind: str,
                 init: Node, parents: dict[int, Tree]) -> Finding:  # fmt: skip
        line = ctx.span(init)[0]
        if kind != "copy":
            call = _passed_twice(fn, twin)
            if call is not None:
                message = (
                    f"`{twin}` is passed twice here while its twin `{name}`, computed the same "
                    f"way at line {line}, is never read: one of these arguments was meant to "
                    f"be `{name}`"
                )
                return self.report(ctx, call, message)
        else:
            suffix = copy_suffix(name, twin) or ""
            found = _live_beside_saved(fn, twin, suffix, init, parents)
            if found is not None:
                statement, sibling = found
                message = (
                    f"reads `{twin}` where `{name}` (saved at line {line}, never read) was "
                    f"evidently meant: the statement beside it reads `{sibling}`; `{twin}` may "
                    "have changed since it was saved"
                )
                return self.report(ctx, statement, message)
        if kind == "copy":
            message = (
                f"`{name}` saves `{twin}` here but is never read, while `{twin}` is: a read of "
                f"`{twin}` after this line was probably meant to be `{name}`; use it or delete it"
            )
        else:
            message = (
                f"`{name}` is computed like its twin `{twin}` but never read, while `{twin}` is: "
                f"one use of `{twin}` was probably meant to be `{name}`; use it or delete it"
            )
        return self.report(ctx, _declarator(init, parents), message)


def _reads(fn: Function, parents: dict[int, Tree]) -> Counter[str]:
    """How often each name is read in the function: every variable but call heads and the
    variable an assignment writes (`x = ...`, `x.y += ...`)."""
    counts: Counter[str] = Counter()
    for node in walk_kind(fn.body, "variable"):
        parent = parents.get(id(node))
        if parent is not None and parent.data == "call" and Call(parent).callee is node:
            continue
        if _assigned(node, parents):
            continue
        counts[Variable(node).name] += 1
    return counts


def _assigned(node: Tree, parents: dict[int, Tree]) -> bool:
    current: Tree = node
    while (parent := parents.get(id(current))) is not None:
        if parent.data == "assignment":
            return Assignment(parent).target is current
        if parent.data not in ("field", "index") or first_child(parent) is not current:
            return False  # not the base of a field or index
        current = parent
    return False


def _parallel(fn: Function, name: str, twin: str, kind: str, init: Node) -> bool:
    """Whether the unused value is computed as its twin's is: a saved copy of the twin itself,
    or an initialiser of the twin's shape that differs in a few names or numbers."""
    if kind == "copy":
        return len(name) > len(twin) and var_name(init) == twin
    other = fn.init.get(twin)
    if other is None:
        return False
    a, b = shape(init), shape(other)
    if len(a) != len(b) or any(x[0] != y[0] for x, y in zip(a, b, strict=True)):
        return False
    differ = sum(x != y for x, y in zip(a, b, strict=True))
    return 0 < differ <= max(2, len(a) // 8)


def _passed_twice(fn: Function, twin: str) -> Tree | None:
    """A call that passes the twin, alone, as two of its arguments."""
    for call in walk_kind(fn.body, "call"):
        if sum(var_name(a) == twin for a in call_args(call)) >= 2:
            return call
    return None


def _live_beside_saved(fn: Function, twin: str, suffix: str, init: Node,
                       parents: dict[int, Tree]) -> tuple[Tree, str] | None:  # fmt: skip
    """A statement after the save that reads the twin while a statement next to it reads
    another value's saved copy (same suffix)."""
    start = init.meta.end_pos if isinstance(init, Tree) and not init.meta.empty else 0
    for node in walk_kind(fn.body, "variable"):
        if Variable(node).name != twin or node.meta.empty or node.meta.start_pos < start:
            continue
        statement = _statement_of(node, parents)
        block = parents.get(id(statement)) if statement is not None else None
        if statement is None or block is None:
            continue
        siblings = CompoundStatement(block).statements
        i = next(k for k, c in enumerate(siblings) if c is statement)
        for j in (i - 1, i + 1):
            if 0 <= j < len(siblings) and isinstance(siblings[j], Tree):
                for other in walk_kind(siblings[j], "variable"):
                    seen = Variable(other).name
                    base = seen[: len(seen) - len(suffix)] if seen.endswith(suffix) else ""
                    if base and base != twin and copy_suffix(seen, base) == suffix:
                        return statement, seen
    return None


def _statement_of(node: Tree, parents: dict[int, Tree]) -> Tree | None:
    current: Tree = node
    while (parent := parents.get(id(current))) is not None:
        if current.data in _STATEMENTS and parent.data == "compound_statement":
            return current
        current = parent
    return None


def _declarator(init: Node, parents: dict[int, Tree]) -> Node:
    parent = parents.get(id(init))
    declarator = Declarator.cast(parent)
    return declarator.name_token if declarator is not None else init
