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
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace

from lark import Token, Tree

from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS
from glint.compiler.glsl.keywords import words

from ..context import LintContext, walk
from . import types as T
from .ranges import (
    BOOL,
    HALF_PI,
    INF,
    NONNEG,
    UNIT,
    UNKNOWN,
    ZERO_ONE,
    Interval,
    atan_range,
    cos_range,
    exp_range,
    floor_like,
    fract_range,
    hull_all,
    inversesqrt_range,
    length_bound,
    log_range,
    mix_range,
    mod_range,
    poly_range,
    pow_range,
    sign_range,
    sin_range,
    sqrt_range,
    step_range,
    tan_range,
)
from .scopes import Scopes, join_scopes, widen
from .syntax import (
    array_text,
    call_args,
    callee_name,
    int_value,
    is_tree,
    root_variable,
    same_expression,
    spec_text,
    swizzle_index,
    var_key,
)
from .values import Comps, Env, Value

Node = Tree | Token


# The largest framebuffer or texture side a GPU offers: a resolution is finite, so a positive
# constant over it (2.0 / iResolution.y, a pixel's width) is strictly positive.
MAX_RESOLUTION = 16384.0


# ShaderToy's uniforms: times and counts never go below zero, a resolution is at least a pixel.
SHADERTOY_RANGES: dict[str, Interval] = {
    "iResolution": Interval(1.0, MAX_RESOLUTION),
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
_NEGATE = {"<": ">=", "<=": ">", ">": "<=", ">=": "<"}
_FLIP = {"<": ">", "<=": ">=", ">": "<", ">=": "<="}
_ASSIGN_OPS = {"+=": "+", "-=": "-", "*=": "*", "/=": "/"}


# --- builtin ranges: a table of interval functions, by name and arity ------------------------

_RANGE_1: dict[str, Callable[[Interval], Interval]] = {
    "sin": sin_range,
    "cos": cos_range,
    "tan": tan_range,
    "asin": lambda x: Interval(-HALF_PI, HALF_PI),
    "acos": lambda x: Interval(0.0, 2 * HALF_PI),
    "atan": lambda x: atan_range(x, None),
    "radians": lambda x: x.scale(HALF_PI / 90),
    "degrees": lambda x: x.scale(90 / HALF_PI),
    "sinh": lambda x: x.monotone(math.sinh),
    "cosh": lambda x: x.abs().monotone(math.cosh),
    "tanh": lambda x: UNIT,
    "acosh": lambda x: NONNEG,
    "exp": exp_range,
    "exp2": lambda x: exp_range(x, math.exp2),
    "log": log_range,
    "log2": lambda x: log_range(x, math.log2),
    "sqrt": sqrt_range,
    "inversesqrt": inversesqrt_range,
    "abs": Interval.abs,
    "sign": sign_range,
    "floor": floor_like(math.floor),
    "ceil": floor_like(math.ceil),
    "trunc": floor_like(math.trunc),
    "round": lambda x: floor_like(math.floor)(x).hull(floor_like(math.ceil)(x)),
    "roundEven": lambda x: floor_like(math.floor)(x).hull(floor_like(math.ceil)(x)),
    "fract": fract_range,
    "fwidth": lambda x: NONNEG,
}
_RANGE_2: dict[str, Callable[[Interval, Interval], Interval]] = {
    "pow": pow_range,
    "mod": mod_range,
    "min": Interval.min,
    "max": Interval.max,
    "step": step_range,
    "atan": atan_range,
}
_RANGE_3: dict[str, Callable[[Interval, Interval, Interval], Interval]] = {
    "clamp": Interval.clamp,
    "mix": mix_range,
    "smoothstep": lambda a, b, x: ZERO_ONE,
}


# --- the model ----------------------------------------------------------------------------


@dataclass
class Function:
    name: str
    node: Tree
    return_type: str
    params: list[tuple[str, str, str]]  # (qualifier, type, name)
    result: Value | None = None  # the join of what its return statements give


@dataclass
class _Loop:
    switch: bool = False  # a switch takes `break` but not `continue`
    breaks: list[Scopes] = field(default_factory=list)
    continues: list[Scopes] = field(default_factory=list)


class Model:
    """Types, ranges and unit-length facts for the expressions of one parsed file."""

    def __init__(self, tree: Tree) -> None:
        self.tree = tree
        self.structs: dict[str, dict[str, str]] = {}
        self.functions: dict[str, list[Function]] = {}
        self._env_of: dict[int, Env] = {}
        self._memo: dict[int, Value] = {}
        self._globals = Scopes([dict(_shadertoy_values())])
        self._params: dict[tuple[str, int], list[Value]] = {}  # call-site facts
        self._collect_structs()
        self._written = self._written_names()
        self._analyse()

    # --- the API rules use -----------------------------------------------------------------

    def value_of(self, expr: Node) -> Value:
        key = id(expr)
        if key not in self._memo:
            env = self._env_of.get(key, self._global_env)
            self._memo[key] = Evaluator(self, env, self._memo).eval(expr)
        return self._memo[key]

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
        called = {callee_name(c) for c in walk(self.tree) if c.data == "call"}
        deep = sum(1 for n in self.tree.children if is_tree(n, "function_definition")
                   and str(n.children[0].children[1]) in called) > 1  # type: ignore  # fmt: skip
        rounds = _ROUNDS if deep else 2
        for rnd in range(rounds):
            self._globals = Scopes([dict(_shadertoy_values())])
            self.functions = {}
            self._collecting = rnd < rounds - 1
            self._reading = rnd > 0
            self._new_params: dict[tuple[str, int], list[Value]] = {}
            for node in self.tree.children:
                if is_tree(node, "function_definition"):
                    self._function(node)  # type: ignore[arg-type]
                elif is_tree(node, "variable_declaration"):
                    self._declaration(node, self._globals, is_global=True)  # type: ignore[arg-type]
            self._global_env = self._globals.flat()
            if not self._collecting:
                break
            # A round that found the arguments it was given (round 0 was given none) is a
            # fixpoint: the next would see the same and find the same, so this one is final.
            if self._new_params == (self._params if self._reading else {}):
                break
            self._params = self._new_params
        self._memo.clear()

    def _collect_structs(self) -> None:
        for node in walk(self.tree):
            if node.data != "struct_specifier":
                continue
            name = next((str(c) for c in node.children if isinstance(c, Token)), None)
            members: dict[str, str] = {}
            for member in node.children:
                if not is_tree(member, "struct_member"):
                    continue
                spec = next(c for c in member.children if is_tree(c, "type_specifier"))
                for decl in member.children:
                    if is_tree(decl, "struct_declarator"):
                        arrays = [array_text(a) for a in decl.children[1:]]
                        members[str(decl.children[0])] = spec_text(spec) + "".join(arrays)
            if name:
                self.structs[name] = members

    def _written_names(self) -> set[str]:
        """Names assigned anywhere in a function: such globals are unknown in every function."""
        names: set[str] = set()
        for node in walk(self.tree):
            for target in _written_targets(node, self):
                if (name := root_variable(target)) is not None:
                    names.add(name)
        return names

    # --- declarations ----------------------------------------------------------------------

    def _function(self, node: Tree) -> None:
        proto, body = node.children
        full_type = proto.children[0]
        name = str(proto.children[1])
        plist = proto.children[2] if len(proto.children) > 2 else None
        params = [_param(p) for p in plist.children] if is_tree(plist, "parameter_list") else []
        params = [p for p in params if p[1] != "void" or p[2]]
        spec = next(c for c in full_type.children if is_tree(c, "type_specifier"))
        fn = Function(name, node, spec_text(spec), params)
        scopes = Scopes([self._globals.flat()])
        facts = self._params.get((name, len(params))) if self._reading else None
        scopes.push()
        for i, (qualifier, ptype, pname) in enumerate(params):
            if not pname:
                continue
            value = Value(ptype)
            if name == "mainImage" and pname == "fragCoord":
                value = Value(ptype, NONNEG)
            elif facts is not None and "out" not in qualifier.split():
                value = replace(facts[i], type=ptype, rel=(), ortho=())
            scopes.declare(pname, value)
        # visible to the body's own (illegal) recursion and to later functions
        self.functions.setdefault(name, []).append(fn)
        flow = _Flow(self, fn)
        flow.statement(body, scopes)
        fn.result = flow.result()

    def _declaration(self, node: Tree, scopes: Scopes, is_global: bool = False) -> None:
        full_type = node.children[0]
        spec = next(c for c in full_type.children if is_tree(c, "type_specifier"))
        base = spec_text(spec)  # type: ignore[arg-type]
        const = any(
            is_tree(q, "type_qualifier") and "const" in (str(t) for t in q.children)
            for q in full_type.children
        )
        for decl in node.children[1:]:
            if not is_tree(decl, "declarator"):
                continue
            name = str(decl.children[0])
            arrays = [array_text(c) for c in decl.children[1:] if is_tree(c, "array_specifier")]
            dtype = base + "".join(arrays)
            init = next((c for c in decl.children[1:] if not is_tree(c, "array_specifier")), None)
            value = Value(dtype)
            if init is not None:
                env = scopes.env_for(init)
                self.record(init, env)
                got = Evaluator(self, env).eval(init)
                value = replace(got, type=dtype)
                if is_global and not const and name in self._written:
                    value = Value(dtype)  # some function assigns it
            scopes.declare(name, value)

    # --- remembering where each expression is evaluated ------------------------------------

    def record(self, expr: Node, env: Env) -> None:
        """Remember the environment of every node of `expr`; branches of `?:`, `&&` and `||`
        get the environment narrowed by the condition. Also gathers call-site facts."""
        stack: list[tuple[Node, Env]] = [(expr, env)]
        while stack:
            node, here = stack.pop()
            if not isinstance(node, Tree):
                continue
            self._env_of[id(node)] = here
            kids = node.children
            if node.data == "ternary":
                stack += [(kids[0], here), (kids[1], self.refine(here, kids[0], True)),
                          (kids[2], self.refine(here, kids[0], False))]  # fmt: skip
                continue
            if node.data == "binary" and str(kids[1]) in ("&&", "||"):
                stack += self._short_circuit_operands(node, here)
                continue
            if node.data == "call" and self._collecting:
                self._call_site(node, here)
            stack.extend((child, here) for child in kids)

    def _short_circuit_operands(self, node: Tree, env: Env) -> list[tuple[Node, Env]]:
        """The operands of `a && b && c ...` (or of `||`), each with the environment where it
        is evaluated: narrowed by every operand before it being true (false for `||`).

        The chain parses left-nested, `((a && b) && c)`, so narrowing each right operand by its
        whole left side would refine the chain's prefix again at every level: quadratic in the
        chain's length. Walking the left spine once and threading the environment gives the
        same environments (refining by `x && y` is refining by x, then by y) in linear time."""
        op = str(node.children[1])
        truth = op == "&&"
        spine = [node]  # the `&&` nodes of the chain, outermost first
        first = node.children[0]
        while is_tree(first, "binary") and str(first.children[1]) == op:  # type: ignore
            spine.append(first)  # type: ignore[arg-type]
            self._env_of[id(first)] = env
            first = first.children[0]  # type: ignore[union-attr]
        out: list[tuple[Node, Env]] = [(first, env)]
        before = first
        for link in reversed(spine):
            env = self.refine(env, before, truth)
            before = link.children[2]
            out.append((before, env))
        return out

    def _call_site(self, call: Tree, env: Env) -> None:
        name = callee_name(call)
        args = call_args(call)
        if name is None or name in BUILTIN_FUNCTIONS or self.function(name, len(args)) is None:
            return
        ev = Evaluator(self, env)
        values = [_passed(ev.eval(a), a) for a in args]
        key = (name, len(args))
        old = self._new_params.get(key)
        self._new_params[key] = (
            values if old is None else [a.join(b) for a, b in zip(old, values, strict=True)]
        )

    def refine(self, env: Env, cond: Node, truth: bool) -> Env:
        """The environment where `cond` is `truth`: comparisons of a scalar variable with
        anything narrow that variable."""
        if is_tree(cond, "unary") and str(cond.children[0]) == "!":  # type: ignore[union-attr]
            return self.refine(env, cond.children[1], not truth)  # type: ignore[union-attr]
        if not is_tree(cond, "binary"):
            return env
        left, op_token, right = cond.children  # type: ignore[union-attr]
        op = str(op_token)
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
        if is_tree(target, "field") and is_tree(target.children[0], "variable"):  # type: ignore
            letter = str(target.children[1])  # type: ignore[union-attr]
            if len(letter) != 1:
                return env
            component, target = swizzle_index(letter), target.children[0]  # type: ignore
            target_field = letter
        if not is_tree(target, "variable"):
            return env
        name = str(target.children[0])  # type: ignore[union-attr]
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
        if component is None:
            narrowed = replace(old, range=old.range.meet(bound))
        else:
            n = T.size(old.type)
            if component >= n:
                return env
            parts = old.parts(n)
            parts[component] = parts[component].meet(bound)
            narrowed = replace(old, comps=tuple(parts))
        key = var_key(other)
        if key is not None and key[1] in env and key[1] != name:
            # x < y: y - x > 0 however y varies (while y keeps this value)
            narrowed = replace(narrowed, rel=(*narrowed.rel, (part, op, key[0], env[key[1]])))
        return {**env, name: narrowed} if narrowed != old else env


def _square_root_node(node: Node) -> Node | None:
    """x for `x * x`."""
    if is_tree(node, "binary") and str(node.children[1]) == "*":  # type: ignore[union-attr]
        left, _, right = node.children  # type: ignore[union-attr]
        if same_expression(left, right):
            return left
    return None


_ROUNDS = 3


def _passed(value: Value, arg: Node) -> Value:
    """An argument as its parameter sees it: an unclamped dot product keeps the evidence of
    its 0, and says where it came from."""
    if value.why is None and value.zero and value.origin in ("dot", "length", "distance"):
        first = next(arg.scan_values(lambda t: isinstance(t, Token)), None) \
            if isinstance(arg, Tree) else arg  # fmt: skip
        line = getattr(first, "line", None)
        where = f" at line {line}" if line else ""
        what = {"dot": "dot product"}.get(value.origin, value.origin)
        return replace(value, why=f"an unclamped {what} passed as an argument{where}")
    return value


def _related(env: Env, a: Node, op: str, b: Node) -> bool:
    """Whether the environment records `a op b` (op "<" or "<="; "<" implies "<="), from
    a relation on either side, while both still hold the values the relation was made with."""
    ka, kb = var_key(a), var_key(b)
    if ka is None or kb is None:
        return False
    ops = ("<",) if op == "<" else ("<", "<=")
    flipped = {"<": ">", "<=": ">="}
    for mine, other, wanted in ((ka, kb, ops), (kb, ka, tuple(flipped[o] for o in ops))):
        holder = env.get(mine[1])
        if holder is None:
            continue
        part = mine[0][len(mine[1]) :]
        for rel_part, rel_op, name, target in holder.rel:
            if (rel_part == part and rel_op in wanted and name == other[0]
                    and env.get(other[1]) is target):  # fmt: skip
                return True
    return False


def _shadertoy_values() -> dict[str, Value]:
    return {
        name: Value(ty, SHADERTOY_RANGES.get(name, UNKNOWN))
        for name, ty in T.SHADERTOY_TYPES.items()
    }


def _param(node: Tree) -> tuple[str, str, str]:
    qualifier = " ".join(
        str(t) for q in node.children if is_tree(q, "type_qualifier") for t in q.children
    )
    spec = next(c for c in node.children if is_tree(c, "type_specifier"))
    name = next((str(c) for c in node.children if isinstance(c, Token)), "")
    arrays = [array_text(c) for c in node.children if is_tree(c, "array_specifier")]
    return qualifier, spec_text(spec) + "".join(arrays), name  # type: ignore[arg-type]


def _written_targets(node: Tree, model: Model | None) -> Iterable[Node]:
    """Lvalues one node writes: an assignment's target, `x++`, out arguments of a call."""
    if node.data == "assignment" or node.data == "postfix":
        yield node.children[0]
    elif node.data == "prefix":
        yield node.children[1]
    elif node.data == "call":
        yield from _out_arguments(node, model)


def _out_arguments(call: Tree, model: Model | None) -> Iterable[Node]:
    name = callee_name(call)
    args = call_args(call)
    if name == "modf" and len(args) == 2:
        yield args[1]
        return
    if name is None or name in BUILTIN_FUNCTIONS:
        return
    fns = model.functions.get(name, []) if model is not None else []
    if model is not None and not fns:
        fns = []
    if not fns:  # not analysed yet (or unknown): any argument may be written
        yield from (a for a in args if root_variable(a) is not None)
        return
    for fn in fns:
        if len(fn.params) != len(args):
            continue
        for (qualifier, _, _), arg in zip(fn.params, args, strict=True):
            if "out" in qualifier.split() or "inout" in qualifier.split():
                yield arg


class _Flow:
    """The forward pass over one function's statements."""

    def __init__(self, model: Model, fn: Function) -> None:
        self.model = model
        self.fn = fn
        self.loops: list[_Loop] = []
        self.returns: list[Value] = []

    # --- statements ------------------------------------------------------------------------

    def block(self, statements: Iterable[Node], scopes: Scopes) -> None:
        # iterative over the list: long functions must not deepen the stack
        for stmt in statements:
            self.statement(stmt, scopes)

    def result(self) -> Value | None:
        """What the function returns: the join of its return statements."""
        if not self.returns:
            return None
        result = self.returns[0]
        for r in self.returns[1:]:
            result = result.join(r)
        return replace(result, type=self.fn.return_type)

    def statement(self, stmt: Node, scopes: Scopes) -> None:
        if not isinstance(stmt, Tree):
            return
        handler = getattr(self, "_" + stmt.data, None)
        if handler is not None:
            handler(stmt, scopes)

    def _compound_statement(self, node: Tree, scopes: Scopes) -> None:
        scopes.push()
        self.block(node.children, scopes)
        scopes.pop()

    def _declaration_statement(self, node: Tree, scopes: Scopes) -> None:
        decl = node.children[0]
        if is_tree(decl, "variable_declaration"):
            self.model._declaration(decl, scopes)  # type: ignore[arg-type]
            for d in decl.children[1:]:  # type: ignore[union-attr]
                for init in d.children[1:] if is_tree(d, "declarator") else ():  # type: ignore
                    self.effects(init, scopes, nested_only=True)

    def _expression_statement(self, node: Tree, scopes: Scopes) -> None:
        self.expression(node.children[0], scopes)

    def _jump_statement(self, node: Tree, scopes: Scopes) -> None:
        kind = str(node.children[0])
        if kind == "return" and len(node.children) > 1:
            expr = node.children[1]
            self.expression(expr, scopes)
            if not scopes.dead:
                self.returns.append(Evaluator(self.model, scopes.env_for(expr)).eval(expr))
        elif kind == "break" and self.loops:
            self.loops[-1].breaks.append(scopes.copy())
        elif kind == "continue":
            loop = next((lp for lp in reversed(self.loops) if not lp.switch), None)
            if loop is not None:
                loop.continues.append(scopes.copy())
        scopes.dead = True

    def _if_statement(self, node: Tree, scopes: Scopes) -> None:
        # `else if` is an if nested in the else branch. Following the chain here and joining
        # all its branches once gives the same state as joining level by level (the join is a
        # hull: associative and idempotent), without joining a variable assigned deep in a long
        # chain again at every level on the way out (quadratic in the chain's length).
        branches = []
        current = scopes
        while True:
            cond, then = node.children[0], node.children[1]
            other = node.children[2] if len(node.children) > 2 else None
            self.expression(cond, current)
            state = self.narrowed(current, cond, True)
            self.statement(then, state)
            branches.append(state)
            state = self.narrowed(current, cond, False)
            if is_tree(other, "if_statement"):
                current, node = state, other  # type: ignore[assignment]
                continue
            if other is not None:
                self.statement(other, state)
            branches.append(state)
            break
        scopes.become(join_scopes(branches))

    def _for_statement(self, node: Tree, scopes: Scopes) -> None:
        init, *middle, body = node.children
        cond = update = None
        if len(middle) == 2:
            cond, update = middle
        elif len(middle) == 1:  # `for (;; i++)` or `for (; c;)`: positions do not say which
            is_cond = is_tree(middle[0], "binary", "unary", "variable", "bool_literal", "call")
            cond, update = (middle[0], None) if is_cond else (None, middle[0])
        scopes.push()
        self.statement(init, scopes)
        self.loop(scopes, cond, update, body)
        scopes.pop()

    def _while_statement(self, node: Tree, scopes: Scopes) -> None:
        cond, body = node.children
        scopes.push()
        if is_tree(cond, "condition_declaration"):
            spec = next(c for c in cond.children[0].children if is_tree(c, "type_specifier"))
            scopes.declare(str(cond.children[1]), Value(spec_text(spec)))
            cond = None
        self.loop(scopes, cond, None, body)
        scopes.pop()

    def _do_statement(self, node: Tree, scopes: Scopes) -> None:
        body, cond = node.children
        self.loop(scopes, cond, None, body, test_first=False)

    def _switch_statement(self, node: Tree, scopes: Scopes) -> None:
        selector, *body = node.children
        self.expression(selector, scopes)
        entry = scopes.copy()
        entry.push()
        current = entry.copy()
        current.dead = True  # nothing before the first label runs
        self.loops.append(_Loop(switch=True))
        has_default = False
        for stmt in body:
            if is_tree(stmt, "case_label", "default_label"):
                has_default |= stmt.data == "default_label"  # type: ignore[union-attr]
                current = join_scopes([current, entry])  # jumped to, or fallen into
                continue
            self.statement(stmt, current)
        exits = self.loops.pop()
        out = join_scopes([current, *exits.breaks] + ([] if has_default else [entry]))
        out.frames = out.frames[: len(scopes.frames)]
        scopes.become(out)

    def loop(self, scopes: Scopes, cond: Node | None, update: Node | None, body: Node,
             test_first: bool = True) -> None:  # fmt: skip
        """Widen what the loop assigns, run the body until its facts stop changing, then
        leave with the condition false (or through a break)."""
        assigned = {
            name
            for part in (cond, update, body)
            if isinstance(part, Tree)
            for n in walk(part)
            for t in _written_targets(n, self.model)
            if (name := root_variable(t)) is not None
        }
        # Nested loops would multiply the passes: deep inside, one pass that knows nothing of
        # what the loop assigns (sound at once, no fixpoint needed). Elsewhere the passes stop
        # when the loop-head state is stable, and fall back to that one pass if it is not.
        deep = sum(not lp.switch for lp in self.loops) >= 3
        entry = widen(scopes, assigned)
        state, converged = entry, False
        for _ in range(0 if deep else 4):
            inner, exits = self._pass(state, cond, update, body, test_first)
            new_state = widen(join_scopes([entry, inner]), assigned)
            converged = new_state.flat() == state.flat()
            if converged:
                break
            state = new_state
        if not converged:
            state = widen(scopes, assigned, keep_flags=False)
            _, exits = self._pass(state, cond, update, body, test_first)
        leave = self.narrowed(state, cond, False) if cond is not None else state.copy()
        if cond is None:
            leave.dead = True  # `for (;;)` ends only through a break
        scopes.become(join_scopes([leave, *exits.breaks]))

    def _pass(self, state: Scopes, cond: Node | None, update: Node | None, body: Node,
              test_first: bool) -> tuple[Scopes, _Loop]:  # fmt: skip
        """One run of the loop from `state`: the state after it, and its breaks/continues."""
        self.loops.append(_Loop())
        inner = state.copy()
        if cond is not None and test_first:
            self.expression(cond, inner)
            inner = self.narrowed(inner, cond, True)
        self.statement(body, inner)
        exits = self.loops.pop()
        inner = join_scopes([inner, *exits.continues])
        if update is not None:
            self.expression(update, inner)
        if cond is not None and not test_first:
            self.expression(cond, inner)
        return inner, exits

    def narrowed(self, scopes: Scopes, cond: Node | None, truth: bool) -> Scopes:
        out = scopes.copy()
        if cond is None or out.dead:
            return out
        env = out.env_for(cond)
        refined = self.model.refine(env, cond, truth)
        if refined is not env:
            for name, value in refined.items():
                if env.get(name) is not value:
                    out.assign(name, value)
        return out

    # --- expressions -----------------------------------------------------------------------

    def expression(self, expr: Node, scopes: Scopes) -> None:
        self.model.record(expr, scopes.env_for(expr))
        self.effects(expr, scopes)

    def effects(self, expr: Node, scopes: Scopes, nested_only: bool = False) -> None:
        """Apply what an expression writes: top-level assignments exactly (`x = e`, `x += e`,
        a sequence of them), any other write makes its variable unknown."""
        if not isinstance(expr, Tree):
            return
        if not nested_only and expr.data == "sequence":
            for part in expr.children:
                self.effects(part, scopes)
            return
        if not nested_only and expr.data == "assignment":
            target, op, rhs = expr.children
            self.effects(rhs, scopes)
            self._assign(target, str(op), expr, scopes)
            return
        for node in walk(expr):
            for target in _written_targets(node, self.model):
                name = root_variable(target)
                old = scopes.lookup(name) if name else None
                if name and old is not None:
                    scopes.assign(name, old.unknown())

    def _assign(self, target: Node, op: str, expr: Tree, scopes: Scopes) -> None:
        name = root_variable(target)
        old = scopes.lookup(name) if name else None
        if name is None or old is None:
            return
        got = Evaluator(self.model, scopes.env_for(expr)).eval(expr)
        if op not in ("=", *_ASSIGN_OPS):
            scopes.assign(name, old.unknown())
        elif is_tree(target, "variable"):
            scopes.assign(name, replace(got, type=old.type))
        else:  # one component or element: each is now the old value or the new one
            scopes.assign(name, Value(old.type, old.range.hull(got.range)))


class Evaluator:
    """Evaluates an expression in an environment (plain recursion on expressions: the runner
    turns a RecursionError on absurdly deep input into finding C006)."""

    def __init__(self, model: Model, env: Env, memo: dict[int, Value] | None = None) -> None:
        self.model = model
        self.env = env
        self.memo = memo

    def eval(self, node: Node) -> Value:
        if not isinstance(node, Tree):
            return Value()
        if self.memo is not None:
            key = id(node)
            if key in self.memo:
                return self.memo[key]
        handler = getattr(self, "_" + node.data, None)
        value = handler(node) if handler is not None else Value()
        if self.memo is not None:
            self.memo[id(node)] = value
        return value

    def _sub(self, node: Node) -> Value:
        """A child evaluated where the model recorded it (narrowed branches), if it did."""
        if self.memo is not None and isinstance(node, Tree):
            return self.model.value_of(node)
        return self.eval(node)

    # --- leaves ----------------------------------------------------------------------------

    def _float_literal(self, node: Tree) -> Value:
        text = str(node.children[0]).rstrip("fF")
        x = float(text)
        return Value("float", Interval.point(x), zero=x == 0)

    def _int_literal(self, node: Tree) -> Value:
        text = str(node.children[0])
        n = int_value(text)
        ty = "uint" if text[-1] in "uU" else "int"
        return Value(ty, Interval.point(float(n)) if n is not None else UNKNOWN, zero=n == 0)

    def _bool_literal(self, node: Tree) -> Value:
        return Value("bool", Interval.point(1.0 if str(node.children[0]) == "true" else 0.0))

    def _variable(self, node: Tree) -> Value:
        return self.env.get(str(node.children[0])) or Value()

    # --- operators -------------------------------------------------------------------------

    def _unary(self, node: Tree) -> Value:
        op, operand = str(node.children[0]), self._sub(node.children[1])
        if op == "-":
            comps = tuple(-c for c in operand.comps) if operand.comps is not None else None
            return replace(operand, range=-operand.range, comps=comps)
        if op == "+":
            return operand
        if op == "!":
            return Value("bool", BOOL)
        return Value(operand.type)

    def _prefix(self, node: Tree) -> Value:
        return Value(self._sub(node.children[1]).type)

    def _postfix(self, node: Tree) -> Value:
        return Value(self._sub(node.children[0]).type)

    def _binary(self, node: Tree) -> Value:
        left, op_token, right = node.children
        op = str(op_token)
        a, b = self._sub(left), self._sub(right)
        ty = T.binary(op, a.type, b.type)
        if ty == "bool":
            return Value("bool", BOOL)
        both_units = a.unit and b.unit and T.is_vector(a.type)
        if op in _ARITH:
            rng, comps = self._arith(op, a, b, ty, same_expression(left, right))
            if op != "/":
                rng, comps = self._polynomial(node, ty, rng, comps)
            if comps is None:
                rng = rng.meet(self._relation(op, left, right, a, b))
            zero = _zero_of(op, a, b) and rng.may_be_zero
            origin = {"+": "sum", "-": "difference"}.get(op) if both_units else None
            why = ((a.zero and a.why) or (b.zero and b.why) or None) if zero else None
            return Value(ty, rng, origin=origin, zero=zero, comps=comps, why=why)
        if op == "%" and a.range.lo >= 0 and b.range.lo > 0:
            return Value(ty, Interval(0.0, b.range.hi))
        return Value(ty)

    @staticmethod
    def _arith(
        op: str, a: Value, b: Value, ty: str | None, same: bool
    ) -> tuple[Interval, tuple[Interval, ...] | None]:
        """The range of a + - * / b, per component for vectors."""
        lm, rm = T.matrix_shape(a.type), T.matrix_shape(b.type)
        if op == "*" and (lm or rm) and not (T.is_scalar(a.type) or T.is_scalar(b.type)):
            inner = lm[0] if lm else (rm[1] if rm else 0)  # type: ignore[index]
            return _sum_of(a.range * b.range, inner), None  # a row times a column
        combine = _ARITH[op]
        if op == "*" and same:
            combine = _square_of
        n = T.size(ty)
        if n > 1 and not (lm or rm):
            return UNKNOWN, tuple(map(combine, a.parts(n), b.parts(n)))
        return combine(a.range, b.range), None

    def _relation(self, op: str, left: Node, right: Node, a: Value, b: Value) -> Interval:
        """What a guard `x < y` (or `<=`) on the path says of y - x, y*y - x*x and x / y."""
        env = self.env
        if op == "-":
            if _related(env, right, "<", left):
                return Interval(5e-324, INF)  # y > x: y - x is a positive float (no underflow)
            if _related(env, right, "<=", left):
                return NONNEG
            squares = [_square_root_node(n) for n in (left, right)]
            if None not in squares:
                y, x = squares
                lower = self._sub(x).range  # type: ignore[arg-type]
                if lower.is_nonnegative and _related(env, x, "<=", y):  # type: ignore[arg-type]
                    return NONNEG  # 0 <= x <= y: y*y - x*x >= 0
        if op == "/" and a.range.is_nonnegative and _related(env, left, "<=", right):
            return ZERO_ONE  # 0 <= x <= y (so y > 0 where x > 0): x / y in [0, 1]
        return UNKNOWN

    def _polynomial(
        self, node: Tree, ty: str | None, rng: Interval, comps: Comps
    ) -> tuple[Interval, Comps]:
        """Tighter bounds for a polynomial in one variable (written more than once): interval
        arithmetic treats each occurrence as independent, so t*t*(3.0 - 2.0*t), the Hermite
        weight of value noise, comes out [0, 3] for t in [0, 1] instead of [0, 1]."""
        found = _as_polynomial(node)
        if found is None:
            return rng, comps
        atom, coeffs = found
        x = self._sub(atom)
        n = T.size(ty)
        if n > 1 and comps is not None and T.size(x.type) == n:
            tight = tuple(
                c.meet(poly_range(coeffs, p)) for c, p in zip(comps, x.parts(n), strict=True)
            )
            return hull_all(tight), tight
        if n == 1 and T.size(x.type) == 1:
            return rng.meet(poly_range(coeffs, x.range)), comps
        return rng, comps

    def _ternary(self, node: Tree) -> Value:
        cond, then, other = node.children
        if self.memo is not None:
            a, b = self._sub(then), self._sub(other)
        else:
            a = Evaluator(self.model, self.model.refine(self.env, cond, True)).eval(then)
            b = Evaluator(self.model, self.model.refine(self.env, cond, False)).eval(other)
        value = a.join(b)
        return value if value.type else replace(value, type=a.type or b.type)

    def _assignment(self, node: Tree) -> Value:
        target, op_token, rhs = node.children
        op = str(op_token)
        old, new = self._sub(target), self._sub(rhs)
        if op == "=":
            return replace(new, type=old.type or new.type)
        if op in _ASSIGN_OPS:
            arith = _ASSIGN_OPS[op]
            rng, comps = self._arith(arith, old, new, old.type, False)
            return Value(old.type, rng, zero=_zero_of(arith, old, new), comps=comps)
        return Value(old.type)

    def _sequence(self, node: Tree) -> Value:
        for child in node.children[:-1]:
            self._sub(child)
        return self._sub(node.children[-1])

    # --- access ----------------------------------------------------------------------------

    def _field(self, node: Tree) -> Value:
        base, name = self._sub(node.children[0]), str(node.children[1])
        swizzled = T.swizzle(base.type, name)
        if swizzled is not None:
            unit = base.unit and len(name) == T.size(base.type) and len(set(name)) == len(name)
            parts = base.parts(T.size(base.type))
            indices = [swizzle_index(c) for c in name]
            if max(indices) >= len(parts):  # `v2.z`: invalid, glslang reports it
                return Value(swizzled)
            picked = tuple(parts[i] for i in indices)
            if len(picked) == 1:  # the vector's evidence of a 0 may be another component's:
                # eps.x of vec2(4.0 / iResolution.y, 0.0) is not 0 because eps.y is
                zero = base.zero and picked[0].may_be_zero and not picked[0].is_unknown
                origin = base.origin if base.origin in ("sin", "cos") else None
                return Value(swizzled, picked[0], origin=origin, zero=zero, why=base.why)
            return Value(swizzled, unit=unit, zero=base.zero, comps=picked)
        member = self.model.structs.get(base.type or "", {}).get(name)
        return Value(member)

    def _index(self, node: Tree) -> Value:
        base = self._sub(node.children[0])
        index = self._sub(node.children[1]).range
        element = T.element(base.type)
        # a struct array element's range says nothing; a vector's component is in its hull
        known = bool(T.components(element) or T.matrix_shape(element))
        rng = base.range if known else UNKNOWN
        n = T.size(base.type)
        if n > 1 and index.is_point and 0 <= index.lo < n:
            rng = base.parts(n)[int(index.lo)]
        return Value(element, rng, zero=known and base.zero)

    # --- calls and constructors ------------------------------------------------------------

    def _constructor(self, node: Tree) -> Value:
        ty = spec_text(node.children[0])  # type: ignore[arg-type]
        args = [self._sub(a) for a in call_args(node)]
        if not args:
            return Value(ty)
        if ty in self.model.structs:
            return Value(ty)
        ranges = [_converted(a, ty) for a in args]
        rng = hull_all(ranges)
        shape = T.matrix_shape(ty)
        if shape and len(args) == 1 and T.is_scalar(args[0].type):
            rng = rng.hull(Interval.point(0.0))  # mat3(s): s on the diagonal, 0 elsewhere
        zero = any(a.zero or a.range == Interval.point(0.0) for a in args)
        unit = self._unit_constructor(ty, args)
        comps = _constructor_parts(ty, args)
        origin = None
        if not unit and _trig_axis(ty, call_args(node)):
            unit, origin = True, "axis"  # sin² + cos² = 1: a chosen (rolled) axis
        return Value(ty, rng, unit, origin, zero=zero, comps=comps)

    @staticmethod
    def _unit_constructor(ty: str, args: list[Value]) -> bool:
        n = T.size(ty)
        if n < 2 or T.components(ty)[0] != "float":  # type: ignore[index]
            return False
        if len(args) == 1 and args[0].type == ty:
            return args[0].unit
        if len(args) == n and all(a.range.is_point for a in args):
            return abs(sum(a.range.lo**2 for a in args) - 1.0) < 1e-6
        return False

    def _call(self, node: Tree) -> Value:
        head = node.children[0]
        args = call_args(node)
        values = [self._sub(a) for a in args]
        if is_tree(head, "field") and str(head.children[1]) == "length":  # type: ignore
            base = self._sub(head.children[0])  # type: ignore[union-attr]
            n = T.size(base.type)
            return Value("int", Interval.point(float(n)) if n > 1 else NONNEG)
        name = callee_name(node)
        if name is None:
            return Value()
        fn = self.model.function(name, len(args))
        if fn is not None:
            result = fn.result or Value(fn.return_type)
            return replace(result, type=fn.return_type)
        if name not in BUILTIN_FUNCTIONS:
            return Value()
        ty = T.builtin_return(name, [v.type for v in values])
        rng, unit, comps = _builtin(name, values, args, T.size(ty))
        if comps is not None:
            rng = hull_all(comps)
        zero = rng.may_be_zero and (name in _REACH_ZERO or _keeps_zero(name, values))
        why = next((v.why for v in values if v.zero and v.why), None) if zero else None
        origin = name
        ortho: tuple[tuple[str, Value], ...] = ()
        if name == "cross" and len(values) == 2:
            origin, unit, ortho = _cross_facts(args, values, unit)
        elif name == "normalize" and values:
            ortho = values[0].ortho  # the same direction
        return Value(ty, rng, unit, origin, zero, comps, why=why, ortho=ortho)


# Builtins with f(0) = 0 (or that pass an argument through): evidence of a 0 in an argument is
# evidence of a 0 in the result. pow(2.0, floor(b)) is 1 where b is 0; exp, cos, inversesqrt
# never give 0 for a 0.
_KEEP_ZERO = words(
    """abs sqrt sign min max clamp mix radians degrees sinh tanh asin atan normalize reflect
    faceforward dFdx dFdy fwidth"""
)


def _keeps_zero(name: str, values: list[Value]) -> bool:
    if name == "pow":
        return bool(values) and values[0].zero
    return name in _KEEP_ZERO and any(v.zero for v in values)


def _cross_facts(
    nodes: list[Node], values: list[Value], unit: bool
) -> tuple[str, bool, tuple[tuple[str, Value], ...]]:
    """Origin, unit-length and orthogonality of cross(a, b). With a fixed axis (a constant, or
    (sin r, cos r, 0), a camera's rolled up) it degenerates only along that axis; the cross of
    two unit vectors known orthogonal (the look-at basis: uu = normalize(cross(ww, up)), then
    cross(uu, ww)) is a unit vector; the cross of a vector already from a fixed-axis cross and
    a vector it is orthogonal to is still zero only along that axis."""
    origin = "cross"
    if any(all(c.is_point for c in v.parts(3)) or v.origin == "axis" for v in values):
        origin = "cross-axis"
    keys = [str(n.children[0]) if is_tree(n, "variable") else None for n in nodes]  # type: ignore
    ortho = tuple((k, v) for k, v in zip(keys, values, strict=True) if k is not None)
    for (x, _kx), (y, ky) in (((values[0], keys[0]), (values[1], keys[1])),
                             ((values[1], keys[1]), (values[0], keys[0]))):  # fmt: skip
        if ky is None or not any(name == ky and v is y for name, v in x.ortho):
            continue
        if x.unit and y.unit:
            return "cross-orthonormal", True, ortho
        if x.origin == "cross-axis":
            origin = "cross-axis"
    return origin, unit, ortho


def _trig_axis(ty: str, nodes: list[Node]) -> bool:
    """vec2/vec3(sin(x), cos(x)) with zeros elsewhere, in any order: a unit vector."""
    if ty not in ("vec2", "vec3") or len(nodes) != T.size(ty):
        return False
    trig = {}
    for n in nodes:
        if is_tree(n, "float_literal", "int_literal"):
            text = str(n.children[0]).rstrip("fF")  # type: ignore[union-attr]
            try:
                if float(text) != 0:
                    return False
            except ValueError:
                return False
            continue
        name = callee_name(n) if is_tree(n, "call") else None  # type: ignore[arg-type]
        inner = call_args(n) if name in ("sin", "cos") else []  # type: ignore[arg-type]
        if len(inner) != 1 or name in trig:
            return False
        trig[name] = inner[0]
    return len(trig) == 2 and same_expression(trig["sin"], trig["cos"])


def _converted(value: Value, ty: str) -> Interval:
    """An argument's range once a constructor converts it to `ty`'s component type."""
    comps = T.components(ty)
    base = comps[0] if comps else "float"
    r = value.range
    if base == "bool":
        return BOOL
    if base in ("int", "uint") and T.components(value.type or "") and \
            T.components(value.type or "")[0] == "float":  # type: ignore[index]  # fmt: skip
        r = floor_like(math.trunc)(r)
    if base == "uint" and r.may_be_negative:
        return UNKNOWN  # negative values wrap around
    return r


# Builtins whose result really passes through 0 when its range contains it (a length at the
# origin, sin at kπ, fract at integers), as opposed to a range widened by interval arithmetic.
_REACH_ZERO = words(
    """length distance dot cross sin cos tan asin atan sinh tanh fract mod floor ceil trunc
    round roundEven sign step smoothstep"""
)

_ARITH: dict[str, Callable[[Interval, Interval], Interval]] = {
    "+": Interval.__add__,
    "-": Interval.__sub__,
    "*": Interval.__mul__,
    "/": Interval.__truediv__,
}


def _square_of(a: Interval, b: Interval) -> Interval:
    return a.square()


def _zero_of(op: str, a: Value, b: Value) -> bool:
    """Whether a op b reaches 0 on evidence (see Value.zero)."""
    if op == "+":  # a sum is 0 on evidence where both terms are
        # (N·L·X + N·V·Y, Smith's denominator, with N·V unclamped: it also changes sign)
        if a.zero and b.zero:
            return True
        # or where a term that reaches 0 and changes sign (an unclamped N·V) can cancel the
        # other: N·V·(1 - k) + k in Schlick-GGX's G1, N·L·X + N·V·Y in Smith's
        total = a.range + b.range
        return total.lo < 0 < total.hi and any(
            x.zero and x.range.lo < 0 < x.range.hi and y.range.is_bounded
            for x, y in ((a, b), (b, a))
        )
    if op in "+-" and b.range.is_point:  # x - c crosses 0 where x passes the constant c
        c = b.range.lo if op == "-" else -b.range.lo
        known = not a.range.is_unknown  # an unknown x passing c is no evidence
        return (a.zero and c == 0) or (known and a.range.lo < c < a.range.hi)
    if op == "-":
        return a.zero and b.range == Interval.point(0.0)
    if op == "*":
        return a.zero or b.zero
    return op == "/" and a.zero


_POLY_SIZE = 64  # nodes: longer expressions are left to interval arithmetic
_POLY_DEGREE = 8


def _as_polynomial(node: Tree) -> tuple[Node, list[float]] | None:
    """(x, coefficients) when `node` is a polynomial with constant coefficients in one
    expression x that occurs at least twice (+, -, *, unary minus, division by a constant);
    None otherwise."""
    atoms: list[Node] = []
    budget = [_POLY_SIZE]

    def poly(n: Node) -> list[float] | None:
        budget[0] -= 1
        if budget[0] < 0 or not isinstance(n, Tree):
            return None
        if n.data in ("float_literal", "int_literal"):
            text = str(n.children[0]).rstrip("fFuU")
            try:
                return [float(text) if n.data == "float_literal" else float(int_value(text) or 0)]
            except ValueError:
                return None
        if n.data == "unary" and str(n.children[0]) in "+-":
            inner = poly(n.children[1])
            if inner is None:
                return None
            return inner if str(n.children[0]) == "+" else [-c for c in inner]
        if n.data == "binary" and str(n.children[1]) in ("+", "-", "*", "/"):
            op = str(n.children[1])
            a, b = poly(n.children[0]), poly(n.children[2])
            if a is None or b is None:
                return None
            if op == "/":
                if len(b) != 1 or b[0] == 0:
                    return None
                return [c / b[0] for c in a]
            if op == "*":
                if len(a) + len(b) - 1 > _POLY_DEGREE + 1:
                    return None
                out = [0.0] * (len(a) + len(b) - 1)
                for i, x in enumerate(a):
                    for j, y in enumerate(b):
                        out[i + j] += x * y
                return out
            sign = 1.0 if op == "+" else -1.0
            out = [0.0] * max(len(a), len(b))
            for i, x in enumerate(a):
                out[i] += x
            for i, y in enumerate(b):
                out[i] += sign * y
            return out
        if n.data in ("variable", "field", "index", "call"):
            if atoms and not same_expression(atoms[0], n):
                return None
            if not atoms and not same_expression(n, n):
                return None  # a call with side effects is not one value
            atoms.append(n)
            return [0.0, 1.0]
        return None

    coeffs = poly(node)
    if coeffs is None or len(atoms) < 2:
        return None
    return atoms[0], coeffs


def _constructor_parts(ty: str, args: list[Value]) -> tuple[Interval, ...] | None:
    """Component ranges of vecN(...): the arguments' components in order, a scalar broadcast."""
    n = T.size(ty)
    if n < 2:
        return None
    parts: list[Interval] = []
    for a in args:
        k = T.size(a.type)
        if k == 0:  # a matrix, or an argument of unknown type: sizes cannot be lined up
            return None
        parts += [_converted(Value(a.type, c), ty) for c in a.parts(k)]
    if len(parts) == 1:
        parts *= n
    return tuple(parts[:n]) if len(parts) >= n else None


def _sum_of(term: Interval, n: int) -> Interval:
    """The sum of n terms each in `term`; any count from 1 to 4 when n is unknown."""
    if n:
        return term.scale(float(n))
    return hull_all([term.scale(float(k)) for k in range(1, 5)])


def _builtin(
    name: str, values: list[Value], nodes: list[Node], n: int
) -> tuple[Interval, bool, Comps]:
    """Range, unit-length and component ranges of a builtin's result (`n` components)."""
    special = _SPECIAL.get(name)
    if special is not None:
        return special(values, nodes)
    table = {1: _RANGE_1, 2: _RANGE_2, 3: _RANGE_3}.get(len(values), {})
    rule = table.get(name)
    if rule is None:
        return UNKNOWN, False, None
    if n > 1:  # genType functions work per component; a scalar argument broadcasts
        columns = zip(*(v.parts(n) for v in values), strict=True)
        comps = tuple(rule(*column) for column in columns)  # type: ignore[operator]
        return hull_all(comps), False, comps
    return rule(*(v.range for v in values)), False, None  # type: ignore[operator]


def _n(value: Value) -> int:
    return T.size(value.type)


def _total(terms: Iterable[Interval]) -> Interval:
    out = Interval.point(0.0)
    for term in terms:
        out = out + term
    return out


def _dot(values: list[Value], nodes: list[Node]) -> tuple[Interval, bool, Comps]:
    if len(values) != 2:
        return UNKNOWN, False, None
    a, b = values
    n = _n(a) or _n(b)
    if same_expression(nodes[0], nodes[1]):
        if a.unit:
            return Interval.point(1.0), False, None
        if n:
            return _total(c.square() for c in a.parts(n)), False, None
        return _sum_of(a.range.square(), n), False, None
    if n:
        rng = _total(x * y for x, y in zip(a.parts(n), b.parts(n), strict=True))
    else:
        rng = _sum_of(a.range * b.range, n)
    if a.unit and b.unit:
        return rng.meet(UNIT), False, None
    for u, other in ((a, b), (b, a)):
        if u.unit:  # |dot(u, v)| <= |v|
            reach = _length(other, n).hi
            rng = rng.meet(Interval(-reach, reach))
    return rng, False, None


def _length(v: Value, n: int) -> Interval:
    if v.unit:
        return Interval.point(1.0)
    if n and v.comps is not None:
        out = sqrt_range(_total(c.square() for c in v.parts(n)))
        # |v| >= |v.x|: also where the squares underflow (a component > 0 from `x > 0.0`)
        near = max(0.0 if c.may_be_zero else min(abs(c.lo), abs(c.hi)) for c in v.parts(n))
        return Interval(max(out.lo, near), max(out.hi, near))
    return length_bound(v.range, n or 4)


def _length_rule(values: list[Value], nodes: list[Node]) -> tuple[Interval, bool, Comps]:
    return (_length(values[0], _n(values[0])) if values else NONNEG), False, None


def _distance(values: list[Value], nodes: list[Node]) -> tuple[Interval, bool, Comps]:
    if len(values) != 2:
        return NONNEG, False, None
    a, b = values
    if a.unit and b.unit:
        return Interval(0.0, 2.0), False, None
    n = _n(a) or _n(b)
    if n:
        diff = tuple(x - y for x, y in zip(a.parts(n), b.parts(n), strict=True))
        return _length(Value(a.type, comps=diff), n), False, None
    return length_bound(a.range - b.range, 4), False, None


def _normalize(values: list[Value], nodes: list[Node]) -> tuple[Interval, bool, Comps]:
    v = values[0] if values else Value()
    n = _n(v)
    if n < 2:
        return Interval(-1.0, 1.0), True, None
    parts = v.parts(n)
    longest = _length(Value(v.type, comps=tuple(parts)), n).hi
    # each component keeps its sign, and one bounded away from 0 stays away after dividing
    comps = tuple(
        Interval(
            c.lo / longest if c.lo > 0 else (-1.0 if c.lo < 0 else 0.0),
            c.hi / longest if c.hi < 0 else (1.0 if c.hi > 0 else 0.0),
        )
        for c in parts
    )
    return hull_all(comps), True, comps


def _cross(values: list[Value], nodes: list[Node]) -> tuple[Interval, bool, Comps]:
    if len(values) != 2:
        return UNKNOWN, False, None
    a, b = values
    x, y = a.parts(3), b.parts(3)
    comps = tuple(x[(i + 1) % 3] * y[(i + 2) % 3] - x[(i + 2) % 3] * y[(i + 1) % 3]
                  for i in range(3))  # fmt: skip
    if a.unit and b.unit:
        comps = tuple(c.meet(UNIT) for c in comps)
    return hull_all(comps), False, comps


def _reflect(values: list[Value], nodes: list[Node]) -> tuple[Interval, bool, Comps]:
    unit = len(values) >= 2 and values[0].unit and values[1].unit
    return (UNIT if unit else UNKNOWN), unit, None


def _faceforward(values: list[Value], nodes: list[Node]) -> tuple[Interval, bool, Comps]:
    n = values[0] if values else Value()
    return n.range.hull(-n.range), n.unit, None


_SPECIAL: dict[str, Callable[[list[Value], list[Node]], tuple[Interval, bool, Comps]]] = {
    "dot": _dot,
    "length": _length_rule,
    "distance": _distance,
    "normalize": _normalize,
    "cross": _cross,
    "reflect": _reflect,
    "refract": _reflect,  # unit, or the zero vector at total internal reflection
    "faceforward": _faceforward,
}


def semantic_model(ctx: LintContext) -> Model:
    """The file's semantic model, built on first use and cached in `ctx.cache["model"]`.
    Only for a parsed file (rules with `needs_tree`)."""
    model = ctx.cache.get("model")
    if model is None:
        if ctx.tree is None:
            raise ValueError("semantic_model needs a parsed file")
        model = ctx.cache["model"] = Model(ctx.tree)
    return model


def condition_truth(model: Model, cond: Node) -> bool | None:
    """Whether a comparison is true (True) or false (False) every time it is evaluated, from
    the ranges of its scalar operands where the model evaluates them (`abs(uv.x) < 1.0` with
    `uv` in [0, 1]); None when it may be either. The data-flow analysis (flow.py) follows only
    the side of a branch that can be taken."""
    if is_tree(cond, "bool_literal"):
        return str(cond.children[0]) == "true"  # type: ignore[union-attr]
    if not is_tree(cond, "binary"):
        return None
    left, op_token, right = cond.children  # type: ignore[union-attr]
    op = str(op_token)
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
