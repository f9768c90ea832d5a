"""Whether the infinity or NaN of a division by an exact 0 (an `Event` of the first path) can
reach something that matters, or is absorbed on the way.

x / 0 is +-infinity where x is not 0, and NaN where it is (0 / 0); mod(x, 0) is NaN. Many such
values go nowhere: a comparison reads an infinity as a sign (`t > 0.0` rejects -inf and NaN),
clamp, smoothstep and step bound it, max(0.0, -inf) is 0, x / inf is 0, and a vector component
no one reads is harmless. NaN is different: GLSL ES 3.00 (§2.1.1, "Floating-Point Computation")
leaves what a builtin does with a NaN argument undefined, and GPUs differ (min(x, NaN) gives x
on some, NaN on others), so a NaN that reaches min, max, clamp, smoothstep or step has escaped:
what the shader computes from there depends on the GPU.

The check follows the quotient forward through the statements of its function, with each
variable's non-finite values per component (a subset of {+inf, -inf, NaN}): sums and products
carry them, the builtins above take the infinities out, and a branch on `q > c` takes -inf and
NaN out of q inside it (+inf in the else branch). The value *escapes* where it is stored to
something not local to the function (an out parameter, fragColor, a global), passed to another
of the file's functions, or returned where the caller is not followed. A return value is
followed into the caller when the division was reported at a call site (the event's chain of
sites), else into every call of the function. One forward walk per function on the way, with a
loop's body walked until its variables stop changing (at most three times): linear in the size
of the code. Where in doubt (a node kind not modelled, a depth bound), the value escapes."""

from __future__ import annotations

import math
from collections.abc import Iterable

from lark import Tree

from glint.compiler.glsl.ast import (
    ConditionDeclaration,
    DoStatement,
    SwitchStatement,
    WhileStatement,
    binary_parts,
    definition_parts,
    field_parts,
    first_child,
    for_parts,
    if_parts,
    index_parts,
    jump_parts,
    leaf_text,
    operand,
    operator,
    ternary_parts,
)

from ...context import LintContext, Node, walk
from ..declarations import declared_variables, signature
from ..syntax import call_args, callee_name, is_tree, root_variable
from .values import Event, base_of, known, size_of

POS, NEG, NAN = "+inf", "-inf", "NaN"
INF = frozenset({POS, NEG})
ALL = frozenset({POS, NEG, NAN})
ONLY_NAN = frozenset({NAN})
NONE: frozenset = frozenset()

# The non-finite values of an expression, per component; one set stands for every component.
Taint = tuple[frozenset, ...]
CLEAN: Taint = (NONE,)

_MAX_CALLERS_DEPTH = 4  # functions up from the division before a return counts as an escape
_MAX_CALL_DEPTH = 4  # calls down, with non-finite arguments, before the call counts as one
_LOOP_PASSES = 3
_SWIZZLE = {c: i for s in ("xyzw", "rgba", "stpq") for i, c in enumerate(s)}
_ORDERED = frozenset({"<", ">", "<=", ">="})
_FLIP = {"<": ">", ">": "<", "<=": ">=", ">=": "<=", "==": "==", "!=": "!="}
_BOOLEAN = frozenset({"<", ">", "<=", ">=", "==", "!=", "&&", "||", "^^"})


class Escaped(Exception):
    """The value reached `sink` (text for a message) with these non-finite values."""

    def __init__(self, sink: str, values: frozenset) -> None:
        super().__init__(sink)
        self.sink, self.values = sink, values


# --- taints -----------------------------------------------------------------------------


def _union(t: Taint) -> frozenset:
    out = NONE
    for s in t:
        out |= s
    return out


def _dirty(t: Taint) -> bool:
    return any(t)


def _zip(a: Taint, b: Taint) -> list[tuple[frozenset, frozenset]]:
    if len(a) == len(b):
        return list(zip(a, b, strict=True))
    if len(a) == 1:
        return [(a[0], s) for s in b]
    if len(b) == 1:
        return [(s, b[0]) for s in a]
    ua, ub = _union(a), _union(b)  # shapes that do not line up: every component alike
    return [(ua, ub)]


def _join(a: Taint, b: Taint) -> Taint:
    return tuple(x | y for x, y in _zip(a, b))


def _map(t: Taint, fn: dict[str, frozenset]) -> Taint:
    """Each non-finite value replaced by what the operation makes of it."""
    out = []
    for s in t:
        r = NONE
        for v in s:
            r |= fn[v]
        out.append(r)
    return tuple(out)


def _flip(t: Taint) -> Taint:
    return _map(t, {POS: frozenset({NEG}), NEG: frozenset({POS}), NAN: ONLY_NAN})


def _nan_only(t: Taint) -> Taint:
    return tuple(s & ONLY_NAN for s in t)


def kinds(values: Iterable[str]) -> str:
    """Names them for a message: "an infinity", "NaN", "an infinity or NaN" for a message."""
    s = frozenset(values)
    inf, nan = bool(s & INF), NAN in s
    return "an infinity or NaN" if inf and nan else ("NaN" if nan else "an infinity")


# What builtins make of a non-finite argument, component by component.
_CLEAR = {POS: NONE, NEG: NONE, NAN: ONLY_NAN}
_KEEP = {POS: frozenset({POS}), NEG: frozenset({NEG}), NAN: ONLY_NAN}
_TO_NAN = {POS: ONLY_NAN, NEG: ONLY_NAN, NAN: ONLY_NAN}
_ELEMENTWISE: dict[str, dict[str, frozenset]] = {
    "sign": _CLEAR,
    "atan": _CLEAR,
    "tanh": _CLEAR,
    "abs": {POS: frozenset({POS}), NEG: frozenset({POS}), NAN: ONLY_NAN},
    "exp": {POS: frozenset({POS}), NEG: NONE, NAN: ONLY_NAN},
    "exp2": {POS: frozenset({POS}), NEG: NONE, NAN: ONLY_NAN},
    "inversesqrt": {POS: NONE, NEG: ONLY_NAN, NAN: ONLY_NAN},
    "sqrt": {POS: frozenset({POS}), NEG: ONLY_NAN, NAN: ONLY_NAN},
    "log": {POS: frozenset({POS}), NEG: ONLY_NAN, NAN: ONLY_NAN},
    "log2": {POS: frozenset({POS}), NEG: ONLY_NAN, NAN: ONLY_NAN},
    "floor": _KEEP,
    "ceil": _KEEP,
    "trunc": _KEEP,
    "round": _KEEP,
    "roundEven": _KEEP,
    "radians": _KEEP,
    "degrees": _KEEP,
    "fract": _TO_NAN,
    "sin": _TO_NAN,
    "cos": _TO_NAN,
    "tan": _TO_NAN,
    "asin": _TO_NAN,
    "acos": _TO_NAN,
    "sinh": _KEEP,
    "cosh": {POS: frozenset({POS}), NEG: frozenset({POS}), NAN: ONLY_NAN},
}
# Builtins whose result for a NaN argument differs between GPUs (GLSL leaves it undefined).
_UNDEFINED_ON_NAN = frozenset({"min", "max", "clamp", "smoothstep", "step"})
# Builtins whose result is a bool or a selection that a non-finite argument cannot make
# non-finite (step(edge, x) is x < edge ? 0.0 : 1.0).
_ABSORBING = frozenset(
    {"step", "isnan", "isinf", "any", "all", "not", "lessThan", "lessThanEqual", "greaterThan",
     "greaterThanEqual", "equal", "notEqual", "textureSize", "floatBitsToInt",
     "floatBitsToUint"}
)  # fmt: skip


# --- the walk ---------------------------------------------------------------------------


class _Env(dict):
    """Local variables with a non-finite value (name -> Taint); absent means clean."""

    def copy(self) -> _Env:
        return _Env(self)


def _join_envs(envs: list[_Env | None]) -> _Env | None:
    live = [e for e in envs if e is not None]
    if not live:
        return None
    out = live[0].copy()
    for e in live[1:]:
        for name, t in e.items():
            out[name] = _join(out[name], t) if name in out else t
    return out


class EscapeCheck:
    """The escape check of one file; `escape(event)` for each event of N011."""

    def __init__(self, ctx: LintContext) -> None:
        from ..model import semantic_model  # built only where an event asks

        assert ctx.tree is not None
        self.ctx = ctx
        self.model = semantic_model(ctx)
        self.parents = ctx.parents()
        self.functions: dict[str, list[Tree]] = {}
        for child in ctx.tree.children:
            if is_tree(child, "function_definition"):
                self.functions.setdefault(signature(child)[0], []).append(child)  # type: ignore[arg-type]
        self._calls: dict[str, list[Tree]] | None = None
        # (function, non-finite parameters) -> what it returns of them, or where they escape
        self.call_memo: dict[tuple, Taint | Escaped] = {}

    # --- the API --------------------------------------------------------------------------

    def escape(self, event: Event) -> Escaped | None:
        """Where the event's non-finite value escapes (None: it is absorbed everywhere)."""
        origin = event.origin()
        start = self._quotient(origin)
        if start is None:
            return Escaped("", ALL)
        taint = self._start_taint(origin)
        if not _dirty(taint):
            return None
        sites: list[Tree] = []
        e = event
        while e.inner is not None:
            assert e.site is not None
            sites.append(e.site)
            e = e.inner
        try:
            fn = self._function_of(start)
            returned = self._flow(fn, start, taint)
            for site in reversed(sites):
                if not _dirty(returned):
                    return None
                fn = self._function_of(site)
                returned = self._flow(fn, site, returned)
            if _dirty(returned):
                self._callers(fn, returned, 1, set())
        except Escaped as escaped:
            return escaped
        except RecursionError:  # an expression nested deeper than the walk can follow
            return Escaped("", ALL)
        return None

    # --- where it starts ------------------------------------------------------------------

    def _quotient(self, origin: Event) -> Tree | None:
        """The node whose value is the non-finite quotient: `a / b`, `a /= b`, `mod(a, b)`."""
        if origin.kind not in ("divide", "mod") or base_of(origin.value.type) != "float":
            return None  # an integer division by 0 is undefined, not an infinity
        parent = self.parents.get(id(origin.expr))
        if origin.kind == "mod":
            call = self.parents.get(id(parent)) if is_tree(parent, "arguments") else None
            return call if is_tree(call, "call") else None
        if is_tree(parent, "binary", "assignment") and operator(parent) in ("/", "/="):  # type: ignore[arg-type]
            return parent
        return None

    def _start_taint(self, origin: Event) -> Taint:
        """Per component: NaN for mod and 0 / 0; an infinity for x / 0 with x not 0, of the
        sign of x times that of the 0 (+0.0 unless computed as -0.0) where x's sign is known;
        both where x is not known exactly and its range holds 0."""
        divisor = origin.value.comps or ()
        if origin.kind == "mod":
            return tuple(ONLY_NAN if known(c) and c == 0 else NONE for c in divisor)
        num = origin.other.comps if origin.other is not None else None
        lo, hi = 0.0, 0.0
        if num is None or not all(known(c) for c in num):
            parent = self.parents.get(id(origin.expr))
            r = self.model.range_of(first_child(parent))  # type: ignore[arg-type]
            lo, hi = r.lo, r.hi
        if not num:
            num = (None,)  # type: ignore[assignment]
        out = []
        for i in range(max(len(divisor), len(num))):  # type: ignore[arg-type]
            d = divisor[i] if len(divisor) > 1 else divisor[0]
            x = num[i] if len(num) > 1 else num[0]  # type: ignore[index,arg-type]
            if not (known(d) and d == 0):
                out.append(NONE)
                continue
            xlo, xhi = lo, hi
            if x is not None and known(x):
                xlo = xhi = float(x)  # type: ignore[arg-type]
            values = NONE
            if xhi > 0.0:
                values |= {POS}
            if xlo < 0.0:
                values |= {NEG}
            if xlo <= 0.0 <= xhi:
                values |= ONLY_NAN
            if math.copysign(1.0, float(d)) < 0:  # type: ignore[arg-type]
                values = _union(_flip((values,)))
            out.append(values)
        return tuple(out)

    def _function_of(self, node: Node) -> Tree:
        while node is not None and not is_tree(node, "function_definition"):
            node = self.parents.get(id(node))  # type: ignore[assignment]
        if node is None:
            raise Escaped("a global initializer", ALL)
        return node  # type: ignore[return-value]

    def _callers(self, fn: Tree, taint: Taint, depth: int, seen: set[int]) -> None:
        """A non-finite value returned from fn: followed into every call of it."""
        name = signature(fn)[0]
        if depth > _MAX_CALLERS_DEPTH or id(fn) in seen:
            raise Escaped(f"the result of {name}()", _union(taint))
        seen.add(id(fn))
        if self._calls is None:
            self._calls = {}
            for node in walk(self.ctx.tree):  # type: ignore[arg-type]
                if node.data == "call":
                    self._calls.setdefault(callee_name(node) or "", []).append(node)
        for call in self._calls.get(name, []):
            caller = self._function_of(call)
            returned = self._flow(caller, call, taint)
            if _dirty(returned):
                self._callers(caller, returned, depth + 1, seen)

    # --- one function ---------------------------------------------------------------------

    def _flow(self, fn: Tree, start: Tree, taint: Taint) -> Taint:
        """What fn returns of the non-finite value that `start` yields; raises Escaped."""
        return _Flow(self, fn, start, taint).run()


class _Flow:
    """The forward walk of one function from the node that yields the non-finite value."""

    def __init__(self, check: EscapeCheck, fn: Tree, start: Tree | None, taint: Taint,
                 env: _Env | None = None, depth: int = 0) -> None:  # fmt: skip
        self.check, self.model = check, check.model
        self.fn, self.start, self.start_taint = fn, start, taint
        self.env0, self.depth = env or _Env(), depth
        self.name, _, params = signature(fn)
        self.locals: set[str] = set()
        for qualifier, _, name in params:
            if not any(w in ("out", "inout") for w in qualifier.split()):
                self.locals.add(name)
        self.outs = {name for q, _, name in params if name} - self.locals
        body = definition_parts(fn)[1]
        for node in walk(body):
            if node.data == "variable_declaration":
                self.locals.update(name for name, _, _ in declared_variables(node)[1])
        self.body = body
        self.returned: Taint = CLEAN
        self.reached = start is None  # a call with non-finite arguments starts at the top

    def run(self) -> Taint:
        self.block(self.body.children, self.env0.copy())
        if not self.reached:  # the walk did not meet it: no telling where it goes
            raise Escaped(f"{self.name}()", _union(self.start_taint))
        return self.returned

    # --- statements -----------------------------------------------------------------------

    def block(self, stmts: Iterable[Node], env: _Env | None) -> _Env | None:
        for stmt in stmts:
            if env is None:
                return None
            env = self.stmt(stmt, env)
        return env

    def stmt(self, node: Node, env: _Env) -> _Env | None:
        if not isinstance(node, Tree):
            return env
        kind = node.data
        if kind == "compound_statement":
            return self.block(node.children, env)
        if kind == "declaration_statement":
            decl = first_child(node)
            if is_tree(decl, "variable_declaration"):
                for name, _, init in declared_variables(decl)[1]:  # type: ignore[arg-type]
                    t = self.expr(init, env) if init is not None else CLEAN
                    self._set(env, name, t)
            return env
        if kind == "expression_statement":
            self.expr(first_child(node), env)
            return env
        if kind == "if_statement":
            cond, then, other = if_parts(node)
            self.expr(cond, env)
            a = self.stmt(then, self.narrow(env.copy(), cond, True))
            b = self.narrow(env.copy(), cond, False)
            if other is not None:
                b = self.stmt(other, b)
            return _join_envs([a, b])
        if kind == "for_statement":
            init, cond, update, body = for_parts(node)
            env = self.stmt(init, env)  # type: ignore[assignment]
            return self._loop(env, cond, update, body)
        if kind == "while_statement":
            loop = WhileStatement(node)
            return self._loop(env, loop.condition, None, loop.body)
        if kind == "do_statement":
            done = DoStatement(node)
            return self._loop(env, done.condition, None, done.body)
        if kind == "switch_statement":
            return self._switch(node, env)
        if kind == "jump_statement":
            word, value = jump_parts(node)
            if word == "return":
                if value is not None:
                    self.returned = _join(self.returned, self.expr(value, env))
                return None
            if word == "discard":
                return None
            return env  # break, continue: the walk goes on, which only adds values
        return env  # an empty statement, a precision or struct declaration

    def _loop(self, env: _Env, cond: Node | None, update: Node | None, body: Node) -> _Env | None:
        """The body walked until its variables stop changing; the loop may not run at all."""
        current = env
        for _ in range(_LOOP_PASSES):
            inner = current.copy()
            if isinstance(cond, Tree):
                if cond.data == "condition_declaration":
                    self._declare_condition(cond, inner)
                else:
                    self.expr(cond, inner)
            after = self.stmt(body, inner)
            if after is not None and isinstance(update, Tree):
                self.expr(update, after)
            joined = _join_envs([current, after])
            if joined == current:
                break
            current = joined  # type: ignore[assignment]
        return current

    def _declare_condition(self, node: Tree, env: _Env) -> None:
        decl = ConditionDeclaration(node)
        self.locals.add(decl.name)
        self._set(env, decl.name, self.expr(decl.initializer, env))

    def _switch(self, node: Tree, env: _Env) -> _Env | None:
        switch = SwitchStatement(node)
        self.expr(switch.selector, env)
        exits: list[_Env | None] = []
        running: _Env | None = None
        has_default = False
        for stmt in switch.body:
            if is_tree(stmt, "case_label", "default_label"):
                has_default = has_default or stmt.data == "default_label"  # type: ignore[union-attr]
                running = _join_envs([running, env.copy()])
            elif is_tree(stmt, "jump_statement") and jump_parts(stmt)[0] == "break":  # type: ignore[arg-type]
                exits.append(running)
                running = None
            elif running is not None:
                running = self.stmt(stmt, running)
        exits.append(running)
        if not has_default:
            exits.append(env)
        return _join_envs(exits)

    # --- conditions -----------------------------------------------------------------------

    def narrow(self, env: _Env, cond: Node, truth: bool) -> _Env:
        """The values left where `cond` is `truth`: `q > c` holds for no -inf or NaN q, and
        fails for no +inf one."""
        if not isinstance(cond, Tree):
            return env
        if cond.data == "unary" and operator(cond) == "!":
            return self.narrow(env, operand(cond), not truth)
        if cond.data != "binary":
            return env
        left, op, right = binary_parts(cond)
        if (op == "&&" and truth) or (op == "||" and not truth):
            return self.narrow(self.narrow(env, left, truth), right, truth)
        if op not in _ORDERED and op not in ("==", "!="):
            return env
        for path, other, o in ((left, right, op), (right, left, _FLIP[op])):
            if _dirty(self.expr(other, env.copy())):
                continue
            removed = _removed(o, truth)
            if removed:
                self._narrow_path(env, path, removed)
        return env

    def _narrow_path(self, env: _Env, node: Node, removed: frozenset) -> None:
        if is_tree(node, "variable"):
            name = leaf_text(node)  # type: ignore[arg-type]
            if name in env:
                env[name] = tuple(s - removed for s in env[name])
        elif is_tree(node, "field"):
            base, field = field_parts(node)  # type: ignore[arg-type]
            if is_tree(base, "variable") and len(field) == 1 and field in _SWIZZLE:
                name = leaf_text(base)  # type: ignore[arg-type]
                t = env.get(name)
                if t is not None and len(t) > _SWIZZLE[field]:
                    t = list(t)
                    t[_SWIZZLE[field]] -= removed
                    env[name] = tuple(t)

    # --- expressions ----------------------------------------------------------------------

    def expr(self, node: Node, env: _Env) -> Taint:
        if node is self.start:
            self.reached = True
            if node.data == "assignment":  # a /= 0: the quotient is stored
                self._store(binary_parts(node)[0], self.start_taint, env)
            else:  # what the call or division reads is walked too (assignments in it)
                for child in node.children:
                    if isinstance(child, Tree):
                        self.expr(child, env)
            return self.start_taint
        if not isinstance(node, Tree):
            return CLEAN
        kind = node.data
        if kind in ("float_literal", "int_literal", "bool_literal"):
            return CLEAN
        if kind == "variable":
            return env.get(leaf_text(node), CLEAN)
        if kind == "field":
            base, name = field_parts(node)
            t = self.expr(base, env)
            if not _dirty(t):
                return CLEAN
            if len(t) > 1 and all(c in _SWIZZLE and _SWIZZLE[c] < len(t) for c in name):
                return tuple(t[_SWIZZLE[c]] for c in name)
            return (_union(t),)
        if kind == "index":
            base, index = index_parts(node)
            self.expr(index, env)
            return (_union(self.expr(base, env)),)
        if kind == "unary":
            t = self.expr(operand(node), env)
            op = operator(node)
            return _flip(t) if op == "-" else (CLEAN if op == "!" else t)
        if kind in ("prefix", "postfix"):
            target = operand(node)
            t = self.expr(target, env)
            if _dirty(t):
                self._store(target, t, env)
            return t
        if kind == "binary":
            return self._binary(node, env)
        if kind == "assignment":
            target, op, rhs = binary_parts(node)
            t = self.expr(rhs, env)
            if op != "=":
                t = self._arith(op[:-1], self.expr(target, env), t, target, rhs)
            self._store(target, t, env)
            return t
        if kind == "ternary":
            cond, a, b = ternary_parts(node)
            self.expr(cond, env)
            ea, eb = self.narrow(env.copy(), cond, True), self.narrow(env.copy(), cond, False)
            ta, tb = self.expr(a, ea), self.expr(b, eb)
            joined = _join_envs([ea, eb])
            env.clear()
            env.update(joined or {})
            return _join(ta, tb)
        if kind == "sequence":
            t = CLEAN
            for part in node.children:
                t = self.expr(part, env)
            return t
        if kind == "constructor":
            return self._constructor(node, env)
        if kind == "call":
            return self._call(node, env)
        # a node kind not modelled: whatever non-finite value it reads escapes with it
        t = CLEAN
        for child in node.children:
            t = _join(t, self.expr(child, env))
        return (_union(t),)

    def _binary(self, node: Tree, env: _Env) -> Taint:
        left, op, right = binary_parts(node)
        a = self.expr(left, env)
        if op in ("&&", "||"):  # the right side runs where the left one decided
            self.expr(right, self.narrow(env.copy(), left, op == "&&"))
            return CLEAN
        b = self.expr(right, env)
        if op in _BOOLEAN:
            return CLEAN  # a comparison turns an infinity into its sign and NaN into false
        return self._arith(op, a, b, left, right)

    def _arith(self, op: str, a: Taint, b: Taint, left: Node, right: Node) -> Taint:
        if not (_dirty(a) or _dirty(b)):
            return CLEAN
        if op in ("+", "-"):
            if op == "-":
                b = _flip(b)
            out = []
            for x, y in _zip(a, b):
                s = x | y
                if x and y and POS in s and NEG in s:  # inf - inf
                    s |= ONLY_NAN
                out.append(s)
            return tuple(out)
        if op in ("*", "/"):
            if _dirty(a) and _dirty(b):
                return tuple(ALL if (x or y) else NONE for x, y in _zip(a, b))
            if op == "/" and _dirty(b):
                return _nan_only(b)  # x / inf is 0
            t, other = (a, right) if _dirty(a) else (b, left)
            r = self.model.range_of(other)
            if r.lo > 0.0:
                return t
            if r.hi < 0.0:
                return _flip(t)
            zero = r.lo <= 0.0 <= r.hi  # inf * 0 is NaN
            return tuple((s | INF | (ONLY_NAN if zero else NONE)) if s & INF else s for s in t)
        return (ALL,)  # %, shifts, bitwise: on ints, not followed

    def _constructor(self, node: Tree, env: _Env) -> Taint:
        args = call_args(node)
        taints = [self.expr(a, env) for a in args]
        if not any(_dirty(t) for t in taints):
            return CLEAN
        n = size_of(self.model.type_of(node))
        if n is None:
            return (_union(_join(CLEAN, tuple(_union(t) for t in taints))),)
        if len(args) == 1:
            t = taints[0]
            return t if len(t) in (1, n) else (_union(t),)
        comps: list[frozenset] = []
        for arg, t in zip(args, taints, strict=True):
            k = size_of(self.model.type_of(arg))
            if k is None:
                return (frozenset().union(*(_union(t) for t in taints)),)
            comps.extend(t if len(t) == k else (t[0] if len(t) == 1 else _union(t),) * k)
        return tuple(comps[:n])

    def _call(self, node: Tree, env: _Env) -> Taint:
        name = callee_name(node) or ""
        args = call_args(node)
        taints = [self.expr(a, env) for a in args]
        if name in self.check.functions:
            return self._call_user(name, taints)
        if not any(_dirty(t) for t in taints):
            return CLEAN
        if name in _UNDEFINED_ON_NAN and any(NAN in _union(t) for t in taints):
            raise Escaped(
                f"{name}(), whose result for a NaN argument GLSL leaves undefined", ONLY_NAN
            )
        if name in _ABSORBING:
            return CLEAN
        if name in _ELEMENTWISE and len(taints) == 1:
            return _map(taints[0], _ELEMENTWISE[name])
        if name == "clamp" and len(taints) == 3:
            x, lo, hi = taints
            return _join(_map(x, _CLEAR), _nan_only(_join(lo, hi)))
        if name == "smoothstep" and len(taints) == 3:
            e0, e1, x = taints
            edges = _union(_join(e0, e1))
            return _join(_map(x, _CLEAR), (ONLY_NAN if edges else NONE,))
        if name in ("max", "min") and len(taints) == 2:
            absorbed = NEG if name == "max" else POS
            out = []
            for x, y in _zip(*taints):
                if x and y:
                    out.append(x | y)
                else:
                    out.append((x or y) - {absorbed})
            return tuple(out)
        # anything else (dot, length, mix, pow, texture ...): every value, all components
        whole = frozenset().union(*(_union(t) for t in taints))
        return (ALL if whole & INF else whole,)

    def _call_user(self, name: str, taints: list[Taint]) -> Taint:
        """What a function of the file returns of the non-finite arguments it is passed, with
        what it stores of them checked in it."""
        if not any(_dirty(t) for t in taints):
            return CLEAN
        fns = [f for f in self.check.functions[name] if len(signature(f)[2]) == len(taints)]
        whole = frozenset().union(*(_union(t) for t in taints))
        if not fns or self.depth >= _MAX_CALL_DEPTH:
            raise Escaped(f"a call of {name}()", whole)
        fn = fns[0]
        params = signature(fn)[2]
        env = _Env()
        for (qualifier, _, param), t in zip(params, taints, strict=True):
            if _dirty(t):
                if any(w in ("out", "inout") for w in qualifier.split()) or not param:
                    raise Escaped(f"a call of {name}()", whole)
                env[param] = t
        key = (id(fn), tuple(sorted((k, v) for k, v in env.items())))
        memo = self.check.call_memo
        if key not in memo:
            try:
                memo[key] = _Flow(self.check, fn, None, CLEAN, env, self.depth + 1).run()
            except Escaped as escaped:
                memo[key] = escaped
        result = memo[key]
        if isinstance(result, Escaped):
            raise result
        return result

    # --- stores ---------------------------------------------------------------------------

    def _set(self, env: _Env, name: str, t: Taint) -> None:
        if _dirty(t):
            env[name] = t
        else:
            env.pop(name, None)

    def _store(self, target: Node, t: Taint, env: _Env) -> None:
        name = root_variable(target)
        if name is None:
            if _dirty(t):
                raise Escaped("a store", _union(t))
            return
        if name not in self.locals:
            if _dirty(t):
                raise Escaped(self._sink(name), _union(t))
            return
        if is_tree(target, "variable"):
            self._set(env, name, t)
            return
        if is_tree(target, "field"):
            base, field = field_parts(target)  # type: ignore[arg-type]
            old = env.get(name, CLEAN)
            n = size_of(self.model.type_of(base))
            if is_tree(base, "variable") and n and all(c in _SWIZZLE for c in field):
                comps = list(old if len(old) == n else (_union(old),) * n)
                for i, c in enumerate(field):
                    if _SWIZZLE[c] < n:
                        comps[_SWIZZLE[c]] = t[i] if len(t) == len(field) else _union(t)
                self._set(env, name, tuple(comps))
                return
        if _dirty(t):  # an element or member: the others keep what they had
            self._set(env, name, _join(env.get(name, CLEAN), (_union(t),)))

    def _sink(self, name: str) -> str:
        if name in self.outs:
            if self.name in ("mainImage", "main"):
                return f"{name} (the pixel's colour)"
            return f"the out parameter {name} of {self.name}()"
        return f"the global {name}"


def _removed(op: str, truth: bool) -> frozenset:
    """The non-finite values of q that `q op c` (c finite) leaves out where it is `truth`."""
    if op == "==":
        return ALL if truth else NONE
    if op == "!=":
        return NONE if truth else ALL
    if truth:
        return frozenset({NEG, NAN}) if op in (">", ">=") else frozenset({POS, NAN})
    return frozenset({POS}) if op in (">", ">=") else frozenset({NEG})


def escape_check(ctx: LintContext) -> EscapeCheck:
    """The file's escape check (built once per file)."""
    return ctx.memo(EscapeCheck)
