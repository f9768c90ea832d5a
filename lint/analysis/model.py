"""The semantic model of a parsed file: the type, value range and unit-length of expressions.

One forward pass per function, in source order, keeps an environment of the variables in scope
(type, range, whether a unit vector, and which builtin produced the value). Each expression is
remembered with the environment it is evaluated in, so `range_of(node)` later evaluates it
there. Branches are joined by the hull; loops widen the variables they assign to unknown; a
condition narrows the variable it compares (`if (x > 0.0)`, and after `if (x < 0.0) return;`).

Facts about parameters come from the call sites: a second pass gives each parameter the hull
of the arguments passed to it in the first pass (functions never called keep unknown
parameters). Unknown is (-inf, inf) and never yields a finding, so whatever the model cannot
follow makes it quieter, never noisier.

This module holds the Model (the API the rules use, and the rounds of the analysis); its parts
are modules of their own: values.py (what is known of a value, and the join), scopes.py (the
variables in scope, joined and widened), statements.py (the forward pass over a function's
statements), expressions.py (the evaluator) and builtin_rules.py (the builtins' ranges).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

from lark import Tree

from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import (
    FunctionDefinition,
    binary_parts,
    definition_parts,
    field_parts,
    leaf_text,
    operand,
    operator,
    ternary_parts,
    variable_name,
)
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS
from glint.compiler.target.shadertoy import shadertoy_types

from ..context import LintContext, Node, subtree_count, tokens, walk
from .declarations import declared_variables, signature, struct_members
from .expressions import Evaluator, RecordedEvaluator, as_polynomial
from .ranges import INF, NONNEG, UNKNOWN, Interval
from .scopes import Scopes, names_of
from .statements import WRITING, ForwardPass, written_targets
from .syntax import (
    call_args,
    callee_name,
    is_tree,
    root_variable,
    same_expression,
    swizzle_index,
    var_key,
)
from .values import Env, Function, Value
from .witness import CORNER_PIXEL, FIRST_FRAME, FIRST_FRAME_COUNT, NOTHING, Witness

# The largest framebuffer or texture side a GPU offers: a resolution is finite, so a positive
# constant over it (2.0 / iResolution.y, a pixel's width) is strictly positive.
MAX_RESOLUTION = 16384.0


# The smallest canvas a shader is shown on, in pixels a side: a preview or thumbnail is larger.
# It makes the bottom-left pixel's screen coordinate fragCoord / iResolution (0.5 / width) small
# for the witnesses: at most 1/32, so fragCoord / iResolution.xy - 0.5 is negative there.
MIN_CANVAS = 16.0


# ShaderToy's uniforms: times and counts never go below zero, a canvas has some pixels a side.
SHADERTOY_RANGES: dict[str, Interval] = {
    "iResolution": Interval(MIN_CANVAS, MAX_RESOLUTION),
    "iTime": NONNEG,
    "iTimeDelta": NONNEG,
    "iFrame": NONNEG,
    "iFrameRate": NONNEG,
    "iDate": NONNEG,
    "iChannelTime": NONNEG,
    "iChannelResolution": Interval(1.0, MAX_RESOLUTION),  # a channel a shader reads is bound
    "iSampleRate": NONNEG,
    "gl_FragCoord": NONNEG,
}
_COMPARE = {"<", ">", "<=", ">="}
# Subtrees a recursive evaluation may go through at once (Model._value_of_subtrees).
_EVALUATE_IN_ONE_GO = 256
_NEGATE = {"<": ">=", "<=": ">", ">": "<=", ">=": "<"}
_FLIP = {"<": ">", "<=": ">=", ">": "<", ">=": "<="}


# --- the model ----------------------------------------------------------------------------


class Model:
    """Types, ranges and unit-length facts for the expressions of one parsed file."""

    reuse_passes = True  # keep a function's pass when a round gives it what it had before

    def __init__(self, tree: Tree, channels: Sequence[str] = ()) -> None:
        self.tree = tree
        self._channels = tuple(channels)  # what each iChannelN is bound to
        self.structs: dict[str, dict[str, str]] = {}
        self.functions: dict[str, list[Function]] = {}
        self._env_of: dict[int, Env] = {}
        self._memo: dict[int, Value] = {}
        self._globals = Scopes([_shadertoy_values(self._channels)])
        self._params: dict[tuple[str, int], list[Value]] = {}  # call-site facts
        # Facts of the tree's shape, by id of the node: the rounds and a loop's passes ask again.
        self._names: dict[int, frozenset[str]] = {}  # names_of
        self._writers: dict[int, tuple[Tree, ...]] = {}  # the nodes that may write a variable
        self._plans: dict[int, _Region] = {}  # how `record` goes through an expression
        self._polynomials: dict[int, tuple[Node, list[float]] | None] = {}
        self._same_operands: dict[int, bool] = {}
        self._declared: dict[int, tuple[bool, list[tuple[str, str, Node | None]]]] = {}
        self._analysed: dict[int, _Analysed] = {}  # a function's last pass, by id of its node
        self._callees: dict[int, tuple[str, ...]] = {}  # the names a function calls, by id
        self._calls: list[tuple[tuple[str, int], list[Value]]] = []  # this pass's call sites
        # Every subtree (in walk order), for the passes over the whole file; each function's
        # own, for the functions it calls: one walk for both.
        self._nodes: list[Tree] = [tree]
        for child in tree.children:
            if isinstance(child, Tree):
                nodes = list(walk(child))
                self._nodes += nodes
                if child.data == "function_definition":
                    called = {callee_name(c) for c in nodes if c.data == "call"}
                    self._callees[id(child)] = tuple(sorted(n for n in called if n))
        self.structs = struct_members(n for n in self._nodes if n.data == "struct_specifier")
        self._written = self._written_names()
        self._analyse()

    # --- the API rules use -----------------------------------------------------------------

    def value_of(self, expr: Node) -> Value:
        key = id(expr)
        if key not in self._memo:
            if isinstance(expr, Tree):
                self._value_of_subtrees(expr)
            env = self._env_of.get(key, self._global_env)
            self._memo[key] = RecordedEvaluator(self, env, self._memo).eval(expr)
        return self._memo[key]

    def _value_of_subtrees(self, expr: Tree) -> None:
        """Where `expr` is large, the values of its subtrees first, the deepest first: each
        evaluation then finds its children's values and goes one level down, not one level
        per level of a chain (`pow(y * y * ... * y, 2.0)` thousands of terms long, which
        exhausted the frames the runner allows). Every subtree is evaluated as the recursion
        would evaluate it, through `value_of`, in its own recorded environment."""
        if subtree_count(expr, _EVALUATE_IN_ONE_GO) <= _EVALUATE_IN_ONE_GO:
            return
        below = list(walk(expr))
        memo = self._memo
        for node in reversed(below[1:]):
            key = id(node)
            if key not in memo:
                env = self._env_of.get(key, self._global_env)
                memo[key] = RecordedEvaluator(self, env, memo).eval(node)

    def type_of(self, expr: Node) -> str | None:
        """The GLSL type of an expression ("float", "vec3", a struct name), None if unknown."""
        return self.value_of(expr).type

    def range_of(self, expr: Node) -> Interval:
        """A conservative range (the hull of the components for a vector)."""
        return self.value_of(expr).range

    def is_unit(self, expr: Node) -> bool:
        """Whether the expression is known to be a unit-length vector."""
        return self.value_of(expr).unit

    def origin_of(self, expr: Node) -> str | None:
        """The builtin that produced the value ("dot", "length", "cross" ...), following
        variables assigned from it; "sum"/"difference" for two unit vectors added."""
        return self.value_of(expr).origin

    def function(self, name: str, arity: int) -> Function | None:
        for fn in self.functions.get(name, []):
            if len(fn.params) == arity:
                return fn
        return None

    # --- the analysis ----------------------------------------------------------------------

    def _analyse(self) -> None:
        self._global_env: Env = self._globals.flat()
        # Round 0 knows nothing of parameters; each later round knows the arguments the round
        # before passed them, so facts reach one call deeper per round (N·V computed in
        # shade() and passed on to a visibility term needs two). The last round only reads.
        called = {callee_name(c) for c in self._nodes if c.data == "call"}
        deep = sum(1 for n in self.tree.children if is_tree(n, "function_definition")
                   and FunctionDefinition(n).name in called) > 1  # type: ignore  # fmt: skip
        rounds = _ROUNDS if deep else 2
        for rnd in range(rounds):
            self._globals = Scopes([_shadertoy_values(self._channels)])
            self.functions = {}
            self._collecting = rnd < rounds - 1
            self._reading = rnd > 0
            self._new_params: dict[tuple[str, int], list[Value]] = {}
            for node in self.tree.children:
                if is_tree(node, "function_definition"):
                    self._function(node)  # type: ignore[arg-type]
                elif is_tree(node, "variable_declaration"):
                    self._calls = []  # a global's call sites belong to no function's pass
                    self.declaration(node, self._globals, is_global=True)  # type: ignore[arg-type]
            self._global_env = self._globals.flat()
            if not self._collecting:
                break
            # A round that found the arguments it was given (round 0 was given none) is a
            # fixpoint: the next would see the same and find the same, so this one is final.
            if self._new_params == (self._params if self._reading else {}):
                break
            self._params = self._new_params
        self._memo.clear()

    def _written_names(self) -> set[str]:
        """Names assigned anywhere in a function: such globals are unknown in every function."""
        names: set[str] = set()
        for node in self._nodes:
            if node.data not in WRITING:
                continue
            for target in written_targets(node, self):
                if (name := root_variable(target)) is not None:
                    names.add(name)
        return names

    # --- declarations ----------------------------------------------------------------------

    def _function(self, node: Tree) -> None:
        name, return_type, params = signature(node)
        fn = Function(name, node, return_type, params)
        global_env = self._globals.flat()
        facts = self._params.get((name, len(params))) if self._reading else None
        declared: list[tuple[str, Value]] = []
        for i, (qualifier, ptype, pname) in enumerate(params):
            if not pname:
                continue
            value = Value(ptype)
            if name == "mainImage" and i == 1 and ptype == "vec2":  # fragCoord, whatever its name
                value = Value(ptype, NONNEG, wit=_PIXEL)
            elif facts is not None and "out" not in qualifier.split():
                value = facts[i].but(type=ptype, rel=(), ortho=())
            declared.append((pname, value))
        # A pass over the body depends only on what it is given: its parameters, the globals
        # and what the functions it calls return. Given the same as in the round before, it
        # would find the same, so that pass stands (its environments stay recorded) and only
        # its call sites are counted again.
        inputs = (declared, global_env, self._callee_results(node))
        last = self._analysed.get(id(node))
        reuse = last is not None and self.reuse_passes and last.inputs == inputs
        if reuse and (last.collected or not self._collecting):  # type: ignore[union-attr]
            self.functions.setdefault(name, []).append(last.function)  # type: ignore[union-attr]
            for key, values in last.calls:  # type: ignore[union-attr]
                self._count_call(key, values)
            return
        scopes = Scopes([global_env])
        scopes.push()
        for pname, value in declared:
            scopes.declare(pname, value)
        # visible to the body's own (illegal) recursion and to later functions
        self.functions.setdefault(name, []).append(fn)
        self._calls = []
        flow = ForwardPass(self, fn)
        flow.statement(definition_parts(node)[1], scopes)  # the body
        fn.result = flow.result()
        self._analysed[id(node)] = _Analysed(inputs, fn, self._calls, self._collecting)

    def _callee_results(self, node: Tree) -> tuple[tuple[str, tuple[Value | None, ...]], ...]:
        """What the file's functions that `node` calls return, as far as known now."""
        return tuple(
            (n, tuple(f.result for f in self.functions[n]))
            for n in self._callees[id(node)]
            if n in self.functions
        )

    def declaration(self, node: Tree, scopes: Scopes, is_global: bool = False) -> None:
        const, declared = self._declarators(node)
        for name, dtype, init in declared:
            value = Value(dtype)
            if init is not None:
                env = scopes.env_for(init, self.names_of(init))
                seen: dict[int, Value] = {}
                self.record(init, env, seen)
                got = Evaluator(self, env, seen=seen).eval(init)
                value = got.but(type=dtype)
                if is_global and not const and name in self._written:
                    value = Value(dtype)  # some function assigns it
            scopes.declare(name, value)

    def _declarators(self, node: Tree) -> tuple[bool, list[tuple[str, str, Node | None]]]:
        """Whether a variable declaration is const, and its (name, type, initializer)s: read
        from the tree once for all the passes."""
        found = self._declared.get(id(node))
        if found is None:
            found = self._declared[id(node)] = declared_variables(node)
        return found

    def names_of(self, expr: Node) -> frozenset[str]:
        """The names in `expr` (scopes.names_of), once per expression for all the rounds."""
        names = self._names.get(id(expr))
        if names is None:
            names = self._names[id(expr)] = names_of(expr)
        return names

    def writers(self, expr: Tree) -> tuple[Tree, ...]:
        """The nodes of `expr` that may write a variable (statements.WRITING), in walk order."""
        found = self._writers.get(id(expr))
        if found is None:
            found = self._writers[id(expr)] = tuple(n for n in walk(expr) if n.data in WRITING)
        return found

    def polynomial(self, node: Tree) -> tuple[Node, list[float]] | None:
        """expressions.as_polynomial, once per node."""
        key = id(node)
        if key not in self._polynomials:
            self._polynomials[key] = as_polynomial(node)
        return self._polynomials[key]

    def same_operands(self, node: Tree) -> bool:
        """Whether a binary node's operands are the same expression (syntax.same_expression)."""
        same = self._same_operands.get(id(node))
        if same is None:
            left, _, right = binary_parts(node)
            same = self._same_operands[id(node)] = same_expression(left, right)
        return same

    # --- remembering where each expression is evaluated ------------------------------------

    def record(self, expr: Node, env: Env, seen: dict[int, Value] | None = None) -> None:
        """Remember the environment of every node of `expr`; branches of `?:`, `&&` and `||`
        get the environment narrowed by the condition. Also gathers call-site facts; the
        values of arguments evaluated in `env` itself go into `seen` (Evaluator's).

        Goes through the expression's plan (`_plan`): its regions of nodes that share an
        environment, and in between the call sites and the branches, in the order of a
        depth-first walk (the call sites' order is the order their facts are joined in)."""
        work: list[tuple[_Region | Tree, Env]] = [(self._plan(expr), env)]
        while work:
            item, here = work.pop()
            if isinstance(item, Tree):
                if self._collecting:
                    self._call_site(item, here, seen if here is env else None)
                continue
            self._env_of.update(dict.fromkeys(item.ids, here))
            for event in reversed(item.events):
                if isinstance(event, Tree):
                    work.append((event, here))
                elif event.operator == "?:":
                    cond = event.operands[0]
                    work += [(event.regions[0], here),
                             (event.regions[1], self.refine(here, cond, True)),
                             (event.regions[2], self.refine(here, cond, False))]  # fmt: skip
                else:
                    # `a && b && c`: each operand where every one before it is true (false
                    # for `||`); refining by `x && y` is refining by x, then by y.
                    truth, envs = event.operator == "&&", [here]
                    for operand in event.operands[:-1]:
                        envs.append(self.refine(envs[-1], operand, truth))
                    work += zip(event.regions, envs, strict=True)

    def _plan(self, expr: Node) -> _Region:
        plan = self._plans.get(id(expr))
        if plan is None:
            plan = self._plans[id(expr)] = _plan(expr)
        return plan

    def _call_site(self, call: Tree, env: Env, seen: dict[int, Value] | None) -> None:
        name = callee_name(call)
        args = call_args(call)
        if name is None or name in BUILTIN_FUNCTIONS or self.function(name, len(args)) is None:
            return
        ev = Evaluator(self, env, seen=seen)
        values = [_passed(ev.eval(a), a) for a in args]
        key = (name, len(args))
        self._calls.append((key, values))
        self._count_call(key, values)

    def _count_call(self, key: tuple[str, int], values: list[Value]) -> None:
        """Join the arguments of one call site into what its function's parameters get."""
        old = self._new_params.get(key)
        self._new_params[key] = (
            values if old is None else [a.join(b) for a, b in zip(old, values, strict=True)]
        )

    def refine(self, env: Env, cond: Node, truth: bool) -> Env:
        """The environment where `cond` is `truth`: comparisons of a scalar variable with
        anything narrow that variable."""
        if is_tree(cond, "unary") and operator(cond) == "!":  # type: ignore[arg-type]
            return self.refine(env, operand(cond), not truth)  # type: ignore[arg-type]
        if not is_tree(cond, "binary"):
            return env
        left, op, right = binary_parts(cond)  # type: ignore[arg-type]
        if (op == "&&" and truth) or (op == "||" and not truth):
            return self.refine(self.refine(env, left, truth), right, truth)
        if op not in _COMPARE:
            return env
        if not truth:
            op = _NEGATE[op]
        env = self._bound(env, left, op, right)
        return self._bound(env, right, _FLIP[op], left)

    def _bound(self, env: Env, target: Node, op: str, other: Node) -> Env:
        """Narrow a scalar variable `x`, or one component `v.y` of a vector variable."""
        component, target_field = None, ""
        if is_tree(target, "field"):
            base, letter = field_parts(target)  # type: ignore[arg-type]
            if variable_name(base) is not None:
                if len(letter) != 1:
                    return env
                component, target = swizzle_index(letter), base
                target_field = letter
        name = variable_name(target)
        if name is None:
            return env
        old = env.get(name)
        if old is None or (component is None and not T.is_scalar(old.type)):
            return env
        limit = Evaluator(self, env).eval(other).range
        if op == "<":  # strict: x < c excludes c itself (x > 0.0 makes x nonzero)
            bound = Interval(-INF, math.nextafter(limit.hi, -INF))
        elif op == ">":
            bound = Interval(math.nextafter(limit.lo, INF), INF)
        else:
            bound = Interval(-INF, limit.hi) if op == "<=" else Interval(limit.lo, INF)
        part = "" if component is None else "." + str(target_field)
        # A witness may lie where the condition fails: the narrowed value keeps none.
        if component is None:
            met = old.range.meet(bound)
            narrowed = old if met == old.range else old.but(range=met, wit=None)
        else:
            n = T.size(old.type)
            if component >= n:
                return env
            parts = old.parts(n)
            met = parts[component].meet(bound)
            changed = met != parts[component]
            parts[component] = met
            narrowed = old.but(comps=tuple(parts), wit=None) if changed else old
        key = var_key(other)
        if key is not None and key[1] in env and key[1] != name:
            # x < y: y - x > 0 however y varies (while y keeps this value)
            narrowed = narrowed.but(rel=(*narrowed.rel, (part, op, key[0], env[key[1]])))
        return {**env, name: narrowed} if narrowed != old else env


_ROUNDS = 3


@dataclass
class _Region:
    """Nodes of an expression evaluated in one environment (`ids`), and what `record` meets
    among them in depth-first order (`events`): the calls of the file's functions (call sites)
    and the branches (`?:`, `&&` and `||`), whose parts are regions of their own."""

    ids: list[int] = field(default_factory=list)
    events: list[Tree | _Branches] = field(default_factory=list)


@dataclass
class _Branches:
    """A `?:` (condition, then, else) or a chain `a && b && c` (or `||`) and its operands,
    each operand's nodes a region."""

    operator: str  # "?:", "&&" or "||"
    operands: list[Node]
    regions: list[_Region]


def _plan(expr: Node) -> _Region:
    """The regions of `expr` (see _Region). A depth-first walk that takes children last first
    (a stack), the order `record` follows; without recursion, as deep input needs."""
    root = _Region()
    stack: list[tuple[Node, _Region]] = [(expr, root)]
    while stack:
        node, region = stack.pop()
        if not isinstance(node, Tree):
            continue
        region.ids.append(id(node))
        kids = node.children
        if node.data == "ternary":
            parts = list(ternary_parts(node))
            branches = _Branches("?:", parts, [_Region(), _Region(), _Region()])
            stack += zip(parts, branches.regions, strict=True)
            region.events.append(branches)
            continue
        if node.data == "binary" and (op := operator(node)) in ("&&", "||"):
            # The chain parses left-nested, `((a && b) && c)`: its inner links share the
            # environment of the whole; the operands are the right sides and the innermost left.
            first, _, right = binary_parts(node)
            operands = [right]
            while is_tree(first, "binary") and operator(first) == op:  # type: ignore[arg-type]
                region.ids.append(id(first))
                first, _, right = binary_parts(first)  # type: ignore[arg-type]
                operands.append(right)
            operands.append(first)
            operands.reverse()
            branches = _Branches(op, operands, [_Region() for _ in operands])
            stack += zip(operands, branches.regions, strict=True)
            region.events.append(branches)
            continue
        if node.data == "call":
            name = callee_name(node)
            if name is not None and name not in BUILTIN_FUNCTIONS:
                region.events.append(node)  # a call site, if it calls a function of the file
        stack.extend((child, region) for child in kids)
    return root


@dataclass
class _Analysed:
    """One pass over a function's body: what it was given, and what it found."""

    inputs: tuple[object, ...]  # the parameters, the globals, what its callees return
    function: Function
    calls: list[tuple[tuple[str, int], list[Value]]]  # its call sites' arguments, in order
    collected: bool  # whether the pass gathered call sites


def _passed(value: Value, arg: Node) -> Value:
    """An argument as its parameter sees it: an unclamped dot product keeps the evidence of
    its 0, and says where it came from."""
    if value.why is None and value.zero and value.origin in ("dot", "length", "distance"):
        first = next(tokens(arg), None)  # without recursion (lark's scan_values recurses)
        line = getattr(first, "line", None)
        where = f" at line {line}" if line else ""
        what = {"dot": "dot product"}.get(value.origin, value.origin)
        return value.but(why=f"an unclamped {what} passed as an argument{where}")
    return value


# The pixel coordinate at the bottom-left pixel: its centre, (0.5, 0.5).
_PIXEL = Witness(((0.5, -INF), (0.5, -INF)), CORNER_PIXEL)

# The inputs' values at a moment every shader meets (the first frame, the bottom-left pixel):
# evidence of what an expression of them reaches.
_WITNESSES = {
    "iTime": Witness(((0.0, -INF),), FIRST_FRAME),
    "iFrame": Witness(((0.0, -INF),), FIRST_FRAME_COUNT),
    "gl_FragCoord": Witness(((0.5, -INF), (0.5, -INF), NOTHING, NOTHING), CORNER_PIXEL),
}


def _shadertoy_values(channels: Sequence[str] = ()) -> dict[str, Value]:
    return {
        name: Value(ty, SHADERTOY_RANGES.get(name, UNKNOWN), wit=_WITNESSES.get(name))
        for name, ty in shadertoy_types(channels).items()
    }


def semantic_model(ctx: LintContext) -> Model:
    """The file's semantic model, built on first use (ctx.memo). Only for a parsed file (rules
    with `needs_tree`)."""
    if ctx.tree is None:
        raise ValueError("semantic_model needs a parsed file")
    return ctx.memo(_build_model)


def _build_model(ctx: LintContext) -> Model:
    assert ctx.tree is not None
    return Model(ctx.tree, ctx.tab.channels)


def condition_truth(model: Model, cond: Node) -> bool | None:
    """Whether a comparison is true (True) or false (False) every time it is evaluated, from
    the ranges of its scalar operands where the model evaluates them (`abs(uv.x) < 1.0` with
    `uv` in [0, 1]); None when it may be either. The data-flow analysis (flow.py) follows only
    the side of a branch that can be taken."""
    if is_tree(cond, "bool_literal"):
        return leaf_text(cond) == "true"  # type: ignore[arg-type]
    if not is_tree(cond, "binary"):
        return None
    left, op, right = binary_parts(cond)  # type: ignore[arg-type]
    if op not in ("<", "<=", ">", ">=", "==", "!="):
        return None
    a, b = model.value_of(left), model.value_of(right)
    if not (T.is_scalar(a.type) and T.is_scalar(b.type)):
        return None
    x, y = a.range, b.range
    if x.lo > x.hi or y.lo > y.hi:
        return None  # an empty range: a branch the model found unreachable, no fact
    if op in (">", ">="):
        x, y, op = y, x, {">": "<", ">=": "<="}[op]
    if op == "<":
        return True if x.hi < y.lo else False if x.lo >= y.hi else None
    if op == "<=":
        return True if x.hi <= y.lo else False if x.lo > y.hi else None
    equal = None
    if x.hi < y.lo or y.hi < x.lo:
        equal = False
    elif x.is_point and y.is_point:
        equal = True
    return equal if op == "==" or equal is None else not equal


# --- shortcuts for the rules -----------------------------------------------------------------


def is_unit(ctx: LintContext, expr: Node) -> bool:
    """Whether the model proves the expression unit length."""
    return semantic_model(ctx).is_unit(expr)


def may_be_negative(ctx: LintContext, expr: Node) -> bool:
    """Whether the model's range of the value reaches below zero."""
    return semantic_model(ctx).range_of(expr).may_be_negative
