"""PF002 loop-invariant-work."""

from __future__ import annotations

import math
from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import (
    ConditionDeclaration,
    Declarator,
    ForStatement,
    VariableDeclaration,
    binary_parts,
    declarator_initializer,
    for_parts,
    loop_parts,
    operator,
    variable_name,
)

from ...analysis.constants import const_value, global_constants
from ...analysis.functions import Function, functions, out_param_map, writes_of
from ...analysis.syntax import call_args, call_name, names_in
from ...context import LintContext, Node, walk, walk_kind
from ...finding import Finding
from .. import Rule, register
from ..lighting._common import macros_used, short_text
from ._common import BUILTINS, WRITERS

# Builtins worth hoisting: transcendental, square roots, normalisation. Texture fetches are
# PF004's (invariant-expensive-call-in-loop), which follows them through calls too.
_EXPENSIVE = {
    "normalize",
    "length",
    "distance",
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "sinh",
    "cosh",
    "tanh",
    "pow",
    "exp",
    "exp2",
    "log",
    "log2",
    "sqrt",
    "inversesqrt",
    "inverse",
    "determinant",
    "reflect",
    "refract",
}


# Expression nodes a hoisted value can be (statements and declarations are not).
_EXPRESSIONS = {"call", "binary", "unary", "constructor", "field", "index", "ternary"}


_LOOPS = {"for_statement", "while_statement", "do_statement"}


def _global_names(ctx: LintContext) -> tuple[set[str], set[str]]:
    """Names of global constants (and uniforms), and of other globals."""
    constant: set[str] = set()
    other: set[str] = set()
    assert ctx.tree is not None
    for node in ctx.tree.children:
        if not (isinstance(node, Tree) and node.data == "variable_declaration"):
            continue
        declaration = VariableDeclaration(node)
        qualifiers = declaration.type.qualifiers
        fixed = "const" in qualifiers or "uniform" in qualifiers
        for declarator in declaration.declarators:
            (constant if fixed else other).add(declarator.name)
    return constant, other


def _local_consts(fn: Function) -> set[str]:
    found = set()
    for node in walk_kind(fn.body, "variable_declaration"):
        declaration = VariableDeclaration(node)
        if declaration.type.is_const:
            found |= {d.name for d in declaration.declarators}
    return found


def _from_macro(ctx: LintContext, expr: Tree) -> str:
    """` (in the expansion of R)` when the expression is not in the user's text as shown."""
    if not ctx.has_macros(expr):
        return ""
    line = ctx.span(expr)[0]
    source = "".join(ctx.lines[line - 1].split()) if 0 < line <= len(ctx.lines) else ""
    if "".join(ctx.node_text(expr).split()) in source:
        return ""
    names = sorted(macros_used(ctx, expr))
    return f" (in the expansion of {', '.join(names)})" if names else " (in a macro expansion)"


# Executions per pixel below which hoisting saves nothing worth a finding: drivers unroll short
# constant loops (an AA grid of 3x3, a few bounces) and merge the repeated calls.
HOT = 64

# A loop whose trip count the code does not say (a while, a bound that is not a constant) is
# taken as a march: hot.
_UNKNOWN_TRIPS = HOT


def trip_count(ctx: LintContext, loop: Tree, fn: Function, unknown: int = _UNKNOWN_TRIPS) -> int:
    """The number of passes of `for (i = A; i < B; i += k)` with constant A, B and k (macros
    expanded, const names and locals with one value included); `unknown` otherwise."""
    if loop.data != "for_statement":
        return unknown
    init, cond, step, _ = for_parts(loop)
    if cond is None or step is None:
        return unknown
    start = None
    for node in walk(init):
        if node.data == "declarator" and (value := declarator_initializer(node)) is not None:
            start = _number(ctx, value, fn)
        elif node.data == "assignment":
            start = _number(ctx, binary_parts(node)[2], fn)
    op = operator(cond) if isinstance(cond, Tree) and cond.data == "binary" else ""
    if start is None or op not in ("<", "<=", ">", ">="):
        return unknown
    end = _number(ctx, binary_parts(cond)[2], fn)  # type: ignore[arg-type]
    delta = _step(ctx, step, fn)
    if end is None or not delta:
        return unknown
    span = (end - start) if delta > 0 else (start - end)
    span += 1 if op in ("<=", ">=") else 0
    return max(0, math.ceil(span / abs(delta)))


def _number(ctx: LintContext, node: Node, fn: Function) -> float | None:
    if isinstance(node, Tree) and node.data == "call" and call_name(node) in ("int", "float"):
        args = call_args(node)
        node = args[0] if len(args) == 1 else node
    value = const_value(node, global_constants(ctx))
    if value is None and fn is not None:
        name = variable_name(node)
        init = fn.value_of(name) if name is not None else None
        value = const_value(init, global_constants(ctx)) if init is not None else None
    return value


def _step(ctx: LintContext, node: Node, fn: Function) -> float | None:
    if not isinstance(node, Tree):
        return None
    if node.data in ("postfix", "prefix"):
        return 1.0 if operator(node) == "++" else -1.0
    if node.data == "assignment" and (parts := binary_parts(node))[1] in ("+=", "-="):
        value = _number(ctx, parts[2], fn)
        return None if value is None else (value if parts[1] == "+=" else -value)
    return None


def _enclosing_trips(ctx: LintContext, node: Tree, fn: Function, up: dict[int, Tree]) -> int:
    """The product of the trip counts of the loops around the node in its function (for a
    loop's for-init, its own loop does not repeat it)."""
    total = 1
    current: Node = node
    while (parent := up.get(id(current))) is not None and parent is not fn.node:
        if parent.data in _LOOPS and not (
            parent.data == "for_statement" and ForStatement(parent).init is current
        ):
            total *= trip_count(ctx, parent, fn)
        current = parent
    return total


def calls_per_pixel(ctx: LintContext, up: dict[int, Tree]) -> dict[str, int]:
    """How many times each function runs per pixel, at most: mainImage once, another function
    the largest over its call sites of (runs of the caller x loops around the call)."""
    defined = {f.name: f for f in functions(ctx)}
    sites: dict[str, list[tuple[Function, Tree]]] = {}
    for fn in defined.values():
        for node in walk_kind(fn.body, "call"):
            if call_name(node) in defined:
                sites.setdefault(call_name(node) or "", []).append((fn, node))
    runs: dict[str, int] = {}

    def count(name: str, depth: int) -> int:
        if name in runs:
            return runs[name]
        if name == "mainImage" or name not in sites or depth > 16:
            runs[name] = 1
            return 1
        best = 1
        for caller, call in sites[name]:
            if caller.name == name:
                continue
            best = max(best, count(caller.name, depth + 1)
                       * _enclosing_trips(ctx, call, caller, up))  # fmt: skip
        runs[name] = min(best, 1 << 30)
        return runs[name]

    for name in defined:
        count(name, 0)
    return runs


@register
class LoopInvariant(Rule):
    """Finds expensive work inside a loop that gives the same value on every iteration: a call to
    normalize, length, a trigonometric or exponential function whose inputs are not changed by the
    loop (a texture fetch is PF004's).

    What counts as invariant: every variable the expression reads is neither written in the loop
    (assignment, ++/--, an out argument), nor declared inside it, nor a global that any function
    writes. Calls of the shader's own functions are never counted (they may be expensive, but
    proving them pure is out of scope), and expressions of constants only are left to the compiler,
    which folds them. Only hot code is reported: the estimated executions per pixel (the trip
    counts of the loops around it, times how often its function runs from the loops of its
    callers, as map() from a march) must reach 64; a loop whose count the code does not state
    counts as hot. Short constant loops (an AA grid, a few bounces) are unrolled and their
    repeated calls merged by the driver.

    Opt-in: desktop compilers hoist pure arithmetic themselves (even across a break); the value
    is on targets that do not hoist reliably (ANGLE/FXC, mobile) and in hot march or fold loops.

    Why is this bad?
        A raymarch or shadow loop runs up to hundreds of times per pixel; a normalize or a sin
        of loop-invariant inputs is paid on every step where the compiler does not hoist
        it (ANGLE's HLSL path and many mobile drivers do not reliably).

    Example:
        for (int i = 0; i < 64; i++) {
            float h = map(ro + rd * t);
            res = min(res, h / t * length(lightPos - ro));
            t += h;
        }

    Use instead:
        float dist = length(lightPos - ro);
        for (int i = 0; i < 64; i++) { ... res = min(res, h / t * dist); ... }

    Fix safety:
        No fix: the hoisted value needs a name and a type, and the loop may be inside an expression
        the fix cannot move code out of.

    References:
        - Muchnick, Advanced Compiler Design and Implementation, 1997, §13.2 (Loop-Invariant Code
          Motion)
    """

    code = "PF002"
    name = "loop-invariant-work"
    category = "performance"
    severity = "info"
    default = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        constants, other_globals = _global_names(ctx)
        outs = out_param_map(ctx)
        global_writes = set().union(*(f.written for f in functions(ctx))) & other_globals
        reported: list[tuple[int, int]] = []
        assert ctx.tree is not None
        up = ctx.parents()
        runs = calls_per_pixel(ctx, up)
        for fn in functions(ctx):
            fixed = constants | _local_consts(fn)
            for loop in walk_kind(fn.body, *_LOOPS):
                varying = set(global_writes)
                for node in walk_kind(loop, *WRITERS, "declarator", "condition_declaration"):
                    varying |= writes_of(node, outs)
                    if node.data == "declarator":
                        varying.add(Declarator(node).name)
                    elif node.data == "condition_declaration":
                        varying.add(ConditionDeclaration(node).name)
                for expr in self._candidates(loop, varying, fixed, fn):
                    if runs.get(fn.name, 1) * _enclosing_trips(ctx, expr, fn, up) < HOT:
                        continue  # a short loop: unrolled and merged by the driver
                    span = (expr.meta.start_pos, expr.meta.end_pos)
                    if any(a <= span[0] and span[1] <= b for a, b in reported):
                        continue
                    reported.append(span)
                    text = short_text(ctx, expr, 60)
                    yield self.report(
                        ctx,
                        expr,
                        f"`{text}`{_from_macro(ctx, expr)} gives the same value on every "
                        "iteration of the loop; compute it once before the loop",
                    )

    def _candidates(
        self, loop: Tree, varying: set[str], fixed: set[str], fn: Function
    ) -> Iterator[Tree]:
        # The for-init runs once: only the condition, the increment and the body repeat.
        stack: list[Node] = list(reversed(loop_parts(loop)))
        while stack:
            node = stack.pop()
            if not isinstance(node, Tree):
                continue
            if node.data == "assignment":
                stack.append(binary_parts(node)[2])  # the target is written, never hoisted
                continue
            if node.data in _EXPRESSIONS and self._invariant(node, varying, fixed, fn):
                yield node
                continue
            stack.extend(reversed(node.children))

    def _invariant(self, node: Tree, varying: set[str], fixed: set[str], fn: Function) -> bool:
        names = names_in(node)
        if not names or names & varying:
            return False
        if names <= fixed:  # constants only: the compiler folds it
            return False
        costly = False
        for sub in walk(node):
            if sub.data in ("assignment", "prefix", "postfix"):
                return False
            if sub.data == "call":
                name = call_name(sub)
                if name is None or name not in BUILTINS:
                    return False  # the shader's own function, or a call through an expression
                costly = costly or name in _EXPENSIVE
        return costly
