"""N013 condition-always-same."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import (
    CompoundStatement,
    Declarator,
    ForStatement,
    binary_parts,
    if_parts,
    leaf_text,
    operand,
    operator,
    ternary_parts,
)
from glint.compiler.target.shadertoy import SHADERTOY_TYPES

from ...analysis.constants import is_compile_time
from ...analysis.functions import Function, function_at, functions
from ...analysis.model import Model, condition_truth, semantic_model
from ...analysis.ranges import Interval
from ...analysis.syntax import binary_op, call_args, callee_name, is_tree
from ...context import LintContext, Node, walk_kind
from ...finding import Finding
from .. import register
from ._common import NumericalRule, text

_COMPARISONS = ("<", "<=", ">", ">=", "==", "!=")


@register
class ConditionAlwaysSame(NumericalRule):
    """Finds a comparison in an `if` or `?:` condition whose outcome is the same every time it
    runs, by the ranges of its operands: `abs(x) < 0.0` is never true, `t < 0.0` is never true
    after `if (t < 0.0) t = 600.0;`. A guard that no longer guards: its branch is dead or
    always taken.

    Only comparisons that are always false are reported (a branch that never runs); an
    always-true test is a defensive check that costs nothing. Left alone as constant on
    purpose: both sides constant (`#define SHADOWS 0` ... `if (SHADOWS == 1)`, `if (false)`, a
    local set once to a constant), loop conditions and tests that follow a for loop's counter
    (constant-bounded loops), tests of ShaderToy's inputs (`iTime != -1.0`), a helper's test of
    its own parameters (constant only for today's callers), a comparison already tested by an
    earlier `if` that leaves the function or loop, and comparisons from a macro's body.

    Why is this bad?
        The test was written to catch a case that the code before it already ruled out (or a
        threshold was mistyped, `< 0.00` for `< 0.001`), so the branch it guards never runs, or
        always runs: an early exit that never exits, a fallback never taken. The author believes
        the case is handled.

    Example:
        if (t < 0.0) t = 600.0;
        ...
        if (t < 0.0) col = sky(rd);

    Use instead:
        if (t < 0.0) t = 600.0;
        ...
        if (t >= 600.0) col = sky(rd);

    Fix safety:
        No fix: what the test should have been is the author's choice.

    References:
        - CWE-570, Expression is Always False; CWE-571, Expression is Always True
    """

    code = "N013"
    name = "condition-always-same"
    default = False  # opt-in: fewer than 15 findings on the corpus to judge it by
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        fns = functions(ctx)
        tests = [(n, if_parts(n)[0]) for n in ctx.nodes("if_statement")]
        tests += [(n, ternary_parts(n)[0]) for n in ctx.nodes("ternary")]
        if not tests:
            return
        model = semantic_model(ctx)
        defined = {fn.name for fn in fns}
        exits = _tested_before_exit(ctx)
        dead_chains: set[int] = set()  # the else branches of if statements already reported
        for statement, cond in tests:
            if id(statement) in dead_chains:
                continue  # one finding for an else-if chain that one earlier test makes dead
            for comparison in _comparisons(cond):
                if not _written_here(ctx, comparison):
                    continue  # from a macro's body: generic code, not the user's text here
                fn = function_at(fns, comparison)
                if fn is None or _retested(ctx, comparison, exits):
                    continue
                found = _always_false(ctx, model, fn, defined, comparison)
                if found is not None:
                    yield self.emit(ctx, comparison, found)
                    other = if_parts(statement)[2] if statement.data == "if_statement" else None
                    if other is not None:
                        dead_chains.add(id(other))
                    break


def _comparisons(cond: Node) -> Iterator[Tree]:
    """The comparisons a condition is made of, through &&, ||, ^^ and !."""
    stack = [cond]
    while stack:
        node = stack.pop()
        if not isinstance(node, Tree):
            continue
        op = binary_op(node)
        if op in ("&&", "||", "^^"):
            left, _, right = binary_parts(node)
            stack += [right, left]
        elif op in _COMPARISONS:
            yield node
        elif node.data == "unary" and operator(node) == "!":
            stack.append(operand(node))


def _always_false(ctx: LintContext, model: Model, fn: Function, defined: set[str],
                  cmp: Tree) -> str | None:  # fmt: skip
    """The message when the comparison is false every time it runs and one side of it is a
    value computed in this function. Always-true tests are left alone: they are defensive
    checks that cost nothing (`x >= 0.0` on a value that is), not dead code."""
    if condition_truth(model, cmp) is not False:
        return None
    sides = []
    left, _, right = binary_parts(cmp)
    for side in (left, right):
        r = model.range_of(side)
        sides.append((side, r, r.is_point or is_compile_time(ctx, side, fn)))
    varying = [(s, r) for s, r, constant in sides if not constant]
    if len(varying) != 1:
        return None  # both constant: written so (a switch); both varying: a relation
    side, r = varying[0]
    sources = _sources(fn, cmp, defined)
    if _read_names(cmp, defined) & set(SHADERTOY_TYPES):
        return None  # a test of the host's inputs (`iTime != -1.0`, a bound channel)
    other = model.range_of(right if side is left else left)
    intrinsic = _never_negative(side, r) and other.hi <= 0.0  # `abs(h) < 0.0` for any h
    if fn.name != "mainImage" and sources & set(fn.params) and not intrinsic:
        return None  # a helper's check of its parameter: constant only for today's callers
    if sources & _loop_counters(ctx):
        return None  # follows a constant-bounded loop's counter: constant by configuration
    shown = text(ctx, cmp, 40)
    return (
        f"`{shown}` is always false: {text(ctx, side, 32)} is in {r.describe()} wherever this "
        "runs, so the branch it guards never runs; the guard no longer guards (fix the "
        "threshold, or the code before it that already rules the case out)"
    )


def _never_negative(side: Node, r: Interval) -> bool:
    """Whether the side is never below 0 whatever its arguments (`abs(h)`, `length(p)`)."""
    return r.lo == 0.0 and callee_name(side) in _NON_NEGATIVE if is_tree(side, "call") else False


_NON_NEGATIVE = {"abs", "length", "distance", "sqrt", "exp", "exp2", "inversesqrt"}


def _sources(fn: Function, node: Node, defined: set[str]) -> set[str]:
    """The names a value is computed from, through the initialisers of the locals it reads,
    stopping at calls of the file's own functions: what such a call returns does not follow
    from its arguments' ranges."""
    seen: set[str] = set()
    todo = list(_read_names(node, defined))
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        value = fn.init.get(name) if name not in fn.declared_twice else None
        if value is not None:
            todo += _read_names(value, defined)
    return seen


def _loop_counters(ctx: LintContext) -> set[str]:
    """The variables for loops declare in their first clause (once per file: ctx.memo)."""
    return ctx.memo(_declared_loop_counters)


def _declared_loop_counters(ctx: LintContext) -> set[str]:
    return {
        Declarator(d).name
        for loop in ctx.nodes("for_statement")
        for d in walk_kind(ForStatement(loop).init, "declarator")
    }


def _read_names(node: Node, defined: set[str]) -> set[str]:
    """Variables an expression reads, not looking into the arguments of calls of the file's
    own functions."""
    found: set[str] = set()
    stack = [node]
    while stack:
        item = stack.pop()
        if not isinstance(item, Tree):
            continue
        if item.data == "variable":
            found.add(leaf_text(item))
        elif item.data == "call":
            if callee_name(item) not in defined:
                stack += call_args(item)
        else:
            stack += item.children
    return found


def _tested_before_exit(ctx: LintContext) -> dict[str, list[int]]:
    """The comparisons of `if` conditions whose branch leaves (return, break, continue,
    discard), by text, with where they end: a later test of the same comparison is a
    harmless re-check, not a guard that no longer guards."""
    found: dict[str, list[int]] = {}
    for node in ctx.nodes("if_statement"):
        cond, branch, _ = if_parts(node)
        block = CompoundStatement.cast(branch)
        if block is not None and block.statements:
            branch = block.statements[-1]  # a block that ends in the jump
        if not (isinstance(branch, Tree) and branch.data == "jump_statement"):
            continue
        for cmp in _comparisons(cond):
            if not cmp.meta.empty:
                found.setdefault(_key(ctx, cmp), []).append(cmp.meta.end_pos)
    return found


def _retested(ctx: LintContext, cmp: Tree, exits: dict[str, list[int]]) -> bool:
    if cmp.meta.empty:
        return False
    return any(end <= cmp.meta.start_pos for end in exits.get(_key(ctx, cmp), ()))


def _written_here(ctx: LintContext, node: Node) -> bool:
    """Whether the node's text is on its lines as the user wrote it (not a macro's body)."""
    first, _, last, _ = ctx.span(node)
    written = "".join("".join(ctx.lines[first - 1 : last]).split())
    return _key(ctx, node) in written


def _key(ctx: LintContext, node: Node) -> str:
    return "".join(ctx.node_text(node).split())
