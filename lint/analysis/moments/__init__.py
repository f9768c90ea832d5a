"""Exact values at named moments: the first path of execution of a shader, evaluated with the
constants it really holds there.

The semantic model (model.py) gives every expression a range that holds on every run, so a
divisor whose range merely touches 0 is a hint at best. Some values are not a hint but a fact at
a moment everyone reaches: on the first frame iTime, iFrame and iTimeDelta are 0; until the first
click iMouse is vec4(0); on the first iteration of a loop the variables it advances still hold
the values they had before it; a call passes the constants written at its site; and a `uniform`
that ShaderToy does not provide is 0 (false). This package runs the shader once along that path,
from mainImage (or main), with each value either an exact constant or unknown, and records every
division by an exact 0 and every builtin called outside its domain on the way (`Event`).

Values: `MV` holds a type, its components (a float, int or bool where exact, a `Sym` where not;
None for matrices, arrays and structs, which are not followed) and the tags of the moments its
exactness depends on (see values.py). A `Sym` is an unknown with an identity, so that `x + 0.0`
is x and `x - x` is exactly 0 whatever x is. Unknown stays unknown and never yields an event.

Control flow: a branch whose condition is exact is the only one taken (and what it assigns
depends on the condition's moments); otherwise both are run and joined (a component both agree
on stays exact). A loop's body runs once, as its first iteration, with each variable the loop
assigns tagged with its value from before the loop; after the loop those variables are unknown.

Calls: a function of the file is evaluated once per tuple of exact arguments (at most
MAX_VARIANTS tuples per function, then once with unknown arguments), to a depth of MAX_DEPTH.
Inside it, an exact argument carries a `param` tag; an event that depends on one is reported at
the call site, with the call's own tags in its place. So the work stays linear in the size of
the file, times a small constant.

The modules, from the bottom up: values.py (the value model, the moments' tags, ShaderToy's
inputs), state.py (variables in scope, joins of branches), operators.py and builtin_functions.py
(exact semantics of operators and builtins), then the three mixins of `Moments`: calls.py
(calls of the file's functions, memoised per exact arguments, and `emit`), statements.py and
expressions.py (the walk along the first path). This module holds `Moments` and `moments(ctx)`."""

from __future__ import annotations

from collections.abc import Callable

from lark import Tree

from glint.compiler.glsl.ast import FullySpecifiedType, declarators, definition_parts, first_child

from ...context import LintContext, Node
from ..declarations import declared_variables, signature
from ..syntax import is_tree
from .calls import MAX_DEPTH, MAX_VARIANTS, CallEvaluator, Fn, Frame
from .expressions import ExpressionWalker
from .state import State
from .statements import StatementWalker
from .values import MV, SHADERTOY_INPUTS, Event, show, unknown, zero_of

__all__ = ["MAX_DEPTH", "MAX_VARIANTS", "MV", "Event", "Moments", "State", "moments", "show"]


class Moments(CallEvaluator, StatementWalker, ExpressionWalker):
    """The events of one file's first path (see the package's docstring)."""

    def __init__(
        self, tree: Tree, bounds: Callable[[Node], tuple[float, float]] | None = None
    ) -> None:
        self.tree = tree
        # (lo, hi) that an expression holds on every run (the semantic model's range): what
        # decides `r2 < rd1` with rd1 = 0 where r2 = dot(z, z) is not known exactly
        self.bounds = bounds
        self.events: dict[tuple[int, str], Event] = {}
        self.functions: dict[str, list[Fn]] = {}
        self._memo: dict[tuple, tuple[MV, list[Event]]] = {}
        self._stack: list[Frame] = []
        self._active: set[int] = set()
        self._writes: dict[int, frozenset[str]] = {}
        self.globals: dict[str, MV] = {}
        self.mutable_globals: set[str] = set()
        self._fn_globals: dict[int, frozenset[str]] = {}
        self._run()

    # --- setup ----------------------------------------------------------------------------

    def _run(self) -> None:
        for child in self.tree.children:
            if is_tree(child, "function_definition"):
                name, ret, params = signature(child)  # type: ignore[arg-type]
                self.functions.setdefault(name, []).append(Fn(name, child, ret, params))  # type: ignore[arg-type]
        state = State(self.globals)
        self._stack.append(Frame(Fn("", self.tree, "void", [])))
        for child in self.tree.children:
            if is_tree(child, "variable_declaration"):
                self._global_declaration(child, state)  # type: ignore[arg-type]
        self.globals.update(state.frames[0])
        self._stack.pop()
        for fns in self.functions.values():
            for fn in fns:
                body = definition_parts(fn.node)[1]
                self.mutable_globals |= self.writes(body) & self.globals.keys()
        entry = self.functions.get("mainImage") or self.functions.get("main") or []
        for fn in entry[:1]:
            args = [unknown(t) for _, t, _ in fn.params]
            self._evaluate(fn, args, entry=True)

    def _global_declaration(self, node: Tree, state: State) -> None:
        words = set(FullySpecifiedType(first_child(node)).qualifiers)  # type: ignore[arg-type]
        if not declarators(node):  # a bare struct declaration
            return
        _, declared = declared_variables(node)
        for name, type_, init in declared:
            if "uniform" in words:
                if name in SHADERTOY_INPUTS:
                    continue  # the shader declares what the host provides
                line = node.meta.line if not node.meta.empty else 0
                zero = zero_of(type_, frozenset({("uniform", name, line)}))
                state.declare(name, zero)
            elif init is not None and not ("in" in words or "out" in words):
                state.declare(name, self._init_value(type_, init, state))
            else:
                state.declare(name, unknown(type_))


# --- the API ------------------------------------------------------------------------------


def moments(ctx: LintContext) -> Moments | None:
    """The first-path events of the file (computed once per file); None without a tree or
    where the file nests deeper than the evaluation can follow."""
    return ctx.memo(_first_path)


def _first_path(ctx: LintContext) -> Moments | None:
    if ctx.tree is None:
        return None
    try:
        # First without ranges, which need the whole file's semantic model (most of a lint's
        # time): a file with no event there is done. Only a file with one is run again with
        # them, which may decide comparisons and drop a branch that cannot run. On 2,122 real
        # shaders no event needed the ranges to appear; the ranges only removed one.
        plain = Moments(ctx.tree)
        return Moments(ctx.tree, _bounds(ctx)) if plain.events else plain
    except RecursionError:
        return None


def _bounds(ctx: LintContext) -> Callable[[Node], tuple[float, float]]:
    from ..model import semantic_model  # the model is built only where a comparison asks

    def bounds(node: Node) -> tuple[float, float]:
        r = semantic_model(ctx).range_of(node)
        return r.lo, r.hi

    return bounds
