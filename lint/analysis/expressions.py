"""The semantic model's expression evaluator: the Value of an expression in an environment of
variables (literals, operators, swizzles and indexing, constructors, calls of builtins and of
the file's functions), with tighter rules where interval arithmetic alone is loose: a
polynomial in one variable, and relations between variables that a guard on the path records
(`y - x > 0` inside `if (x < y)`)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Protocol

from lark import Tree

from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import (
    binary_parts,
    field_parts,
    first_child,
    index_parts,
    leaf_text,
    operand,
    operator,
    ternary_parts,
    variable_name,
)
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

from ..context import Node
from . import witness as W
from .builtin_rules import (
    REACH_ZERO,
    builtin_length,
    builtin_result,
    builtin_witness,
    cross_facts,
    keeps_zero,
    sum_of,
)
from .ranges import (
    BOOL,
    INF,
    NONNEG,
    UNKNOWN,
    ZERO_ONE,
    Interval,
    floor_like,
    hull_all,
    poly_range,
)
from .syntax import (
    call_args,
    callee_name,
    int_value,
    is_tree,
    same_expression,
    spec_text,
    swizzle_index,
    var_key,
)
from .values import Comps, Env, Function, Value


class ModelView(Protocol):
    """What the evaluator asks of the semantic model (model.Model): its structs, the functions
    of the file, the value of an expression where the model recorded it, and an environment
    narrowed by a condition. A protocol, so that this module does not import the model, which
    imports it."""

    structs: dict[str, dict[str, str]]

    def value_of(self, expr: Node) -> Value: ...

    def function(self, name: str, arity: int) -> Function | None: ...

    def refine(self, env: Env, cond: Node, truth: bool) -> Env: ...

    def polynomial(self, node: Tree) -> tuple[Node, list[float]] | None: ...

    def same_operands(self, node: Tree) -> bool: ...


ASSIGN_OPS = {"+=": "+", "-=": "-", "*=": "*", "/=": "/"}


class Evaluator:
    """Evaluates an expression in an environment (plain recursion on expressions: the runner
    turns a RecursionError on absurdly deep input into finding C006)."""

    def __init__(
        self,
        model: ModelView,
        env: Env,
        memo: dict[int, Value] | None = None,
        seen: dict[int, Value] | None = None,
    ) -> None:
        """`memo`: the model's values of nodes where it recorded them (each child is then
        evaluated in its own recorded environment); `seen`: values of nodes already evaluated
        in this very environment (a statement's call sites, then the statement)."""
        self.model = model
        self.env = env
        self.memo = memo
        self.known = memo if memo is not None else seen

    def eval(self, node: Node) -> Value:
        if not isinstance(node, Tree):
            return Value()
        known = self.known
        if known is not None and (value := known.get(id(node))) is not None:
            return value
        handler = _HANDLERS.get(node.data)
        value = handler(self, node) if handler is not None else Value()
        if known is not None:
            known[id(node)] = value
        return value

    # A child is evaluated here, in this environment (RecordedEvaluator looks it up instead).
    # A class attribute, not `self._sub = self.eval`: a bound method kept on its own instance
    # is a reference cycle, and every evaluator would wait for the cycle collector.
    _sub = eval

    # --- leaves ----------------------------------------------------------------------------

    def _float_literal(self, node: Tree) -> Value:
        text = leaf_text(node).rstrip("fF")
        x = float(text)
        return Value("float", Interval.point(x), zero=x == 0)

    def _int_literal(self, node: Tree) -> Value:
        text = leaf_text(node)
        n = int_value(text)
        ty = "uint" if text[-1] in "uU" else "int"
        return Value(ty, Interval.point(float(n)) if n is not None else UNKNOWN, zero=n == 0)

    def _bool_literal(self, node: Tree) -> Value:
        return Value("bool", Interval.point(1.0 if leaf_text(node) == "true" else 0.0))

    def _variable(self, node: Tree) -> Value:
        return self.env.get(leaf_text(node)) or Value()

    # --- operators -------------------------------------------------------------------------

    def _unary(self, node: Tree) -> Value:
        op, value = operator(node), self._sub(operand(node))
        if op == "-":
            comps = tuple(-c for c in value.comps) if value.comps is not None else None
            wit = value.wit
            if wit is not None:
                wit = W.Witness(tuple(map(W.negate, wit.parts)), wit.why)
            return value.but(range=-value.range, comps=comps, wit=wit)
        if op == "+":
            return value
        if op == "!":
            return Value("bool", BOOL)
        return Value(value.type)

    def _prefix(self, node: Tree) -> Value:
        return Value(self._sub(operand(node)).type)

    def _postfix(self, node: Tree) -> Value:
        return Value(self._sub(operand(node)).type)

    def _binary(self, node: Tree) -> Value:
        left, op, right = binary_parts(node)
        a, b = self._sub(left), self._sub(right)
        ty = T.binary(op, a.type, b.type)
        if ty == "bool":
            return Value("bool", BOOL)
        both_units = a.unit and b.unit and T.is_vector(a.type)
        if op in _ARITH:
            rng, comps = self._arith(op, a, b, ty, op == "*" and self.model.same_operands(node))
            if op != "/":
                rng, comps = self._polynomial(node, ty, rng, comps)
            if comps is None:
                rng = rng.meet(self._relation(op, left, right, a, b))
            zero = _zero_of(op, a, b) and rng.may_be_zero
            origin = {"+": "sum", "-": "difference"}.get(op) if both_units else None
            why = ((a.zero and a.why) or (b.zero and b.why) or None) if zero else None
            wit = _binary_witness(op, a, b, ty, rng, comps)
            rotated = _rotated(op, a, b, ty)
            if rotated is not None:
                return rotated
            return Value(ty, rng, origin=origin, zero=zero, comps=comps, why=why, wit=wit)
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
            return sum_of(a.range * b.range, inner), None  # a row times a column
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
            squares = [self._square_root_node(n) for n in (left, right)]
            if None not in squares:
                y, x = squares
                lower = self._sub(x).range  # type: ignore[arg-type]
                if lower.is_nonnegative and _related(env, x, "<=", y):  # type: ignore[arg-type]
                    return NONNEG  # 0 <= x <= y: y*y - x*x >= 0
        if op == "/" and a.range.is_nonnegative and _related(env, left, "<=", right):
            return ZERO_ONE  # 0 <= x <= y (so y > 0 where x > 0): x / y in [0, 1]
        return UNKNOWN

    def _square_root_node(self, node: Node) -> Node | None:
        """x for `x * x`."""
        if not (is_tree(node, "binary") and operator(node) == "*"):  # type: ignore[arg-type]
            return None
        return first_child(node) if self.model.same_operands(node) else None  # type: ignore

    def _polynomial(
        self, node: Tree, ty: str | None, rng: Interval, comps: Comps
    ) -> tuple[Interval, Comps]:
        """Tighter bounds for a polynomial in one variable (written more than once): interval
        arithmetic treats each occurrence as independent, so t*t*(3.0 - 2.0*t), the Hermite
        weight of value noise, comes out [0, 3] for t in [0, 1] instead of [0, 1]."""
        found = self.model.polynomial(node)
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
        cond, then, other = ternary_parts(node)
        if self.memo is not None:
            a, b = self._sub(then), self._sub(other)
        else:
            a = Evaluator(self.model, self.model.refine(self.env, cond, True)).eval(then)
            b = Evaluator(self.model, self.model.refine(self.env, cond, False)).eval(other)
        value = a.join(b)
        return value if value.type else value.but(type=a.type or b.type)

    def _assignment(self, node: Tree) -> Value:
        target, op, rhs = binary_parts(node)
        old, new = self._sub(target), self._sub(rhs)
        if op == "=":
            return new.but(type=old.type or new.type)
        if op in ASSIGN_OPS:
            arith = ASSIGN_OPS[op]
            rotated = _rotated(arith, old, new, old.type)
            if rotated is not None:
                return rotated
            rng, comps = self._arith(arith, old, new, old.type, False)
            wit = _binary_witness(arith, old, new, old.type, rng, comps)
            return Value(old.type, rng, zero=_zero_of(arith, old, new), comps=comps, wit=wit)
        return Value(old.type)

    def _sequence(self, node: Tree) -> Value:
        *before, last = node.children  # `a, b, c`: evaluated in order, the last one's value
        for child in before:
            self._sub(child)
        return self._sub(last)

    # --- access ----------------------------------------------------------------------------

    def _field(self, node: Tree) -> Value:
        base_node, name = field_parts(node)
        base = self._sub(base_node)
        swizzled = T.swizzle(base.type, name)
        if swizzled is not None:
            unit = base.unit and len(name) == T.size(base.type) and len(set(name)) == len(name)
            parts = base.parts(T.size(base.type))
            indices = [swizzle_index(c) for c in name]
            if max(indices) >= len(parts):  # `v2.z`: invalid, glslang reports it
                return Value(swizzled)
            picked = tuple(parts[i] for i in indices)
            wit = None
            if base.wit is not None:
                pairs = W.pairs(base.wit, parts)
                wit = W.make([pairs[i] for i in indices], base.wit.why, list(picked))
            if len(picked) == 1:  # the vector's evidence of a 0 may be another component's:
                # eps.x of vec2(4.0 / iResolution.y, 0.0) is not 0 because eps.y is
                zero = base.zero and picked[0].may_be_zero and not picked[0].is_unknown
                origin = base.origin if base.origin in ("sin", "cos") else None
                return Value(swizzled, picked[0], origin=origin, zero=zero, why=base.why, wit=wit)
            return Value(swizzled, unit=unit, zero=base.zero, comps=picked, wit=wit)
        member = self.model.structs.get(base.type or "", {}).get(name)
        return Value(member)

    def _index(self, node: Tree) -> Value:
        base_node, index_node = index_parts(node)
        base = self._sub(base_node)
        index = self._sub(index_node).range
        element = T.element(base.type)
        # a struct array element's range says nothing; a vector's component is in its hull
        known = bool(T.components(element) or T.matrix_shape(element))
        rng = base.range if known else UNKNOWN
        n = T.size(base.type)
        wit = None
        if n > 1 and index.is_point and 0 <= index.lo < n:
            rng = base.parts(n)[int(index.lo)]
            if base.wit is not None:
                pair = W.pairs(base.wit, base.parts(n))[int(index.lo)]
                wit = W.make([pair], base.wit.why, [rng])
        return Value(element, rng, zero=known and base.zero, wit=wit)

    # --- calls and constructors ------------------------------------------------------------

    def _constructor(self, node: Tree) -> Value:
        ty = spec_text(first_child(node))  # type: ignore[arg-type]  # the type_specifier
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
        elif _is_rotation(ty, args, call_args(node)):
            origin = "rotation"
        wit = _constructor_witness(ty, args, comps)
        return Value(ty, rng, unit, origin, zero=zero, comps=comps, wit=wit)

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
        head = first_child(node)  # the callee
        args = call_args(node)
        values = [self._sub(a) for a in args]
        if is_tree(head, "field") and field_parts(head)[1] == "length":  # type: ignore[arg-type]
            base = self._sub(first_child(head))  # type: ignore[arg-type]
            n = T.size(base.type)
            return Value("int", Interval.point(float(n)) if n > 1 else NONNEG)
        name = callee_name(node)
        if name is None:
            return Value()
        fn = self.model.function(name, len(args))
        if fn is not None:
            result = fn.result or Value(fn.return_type)
            return result.but(type=fn.return_type)
        if name not in BUILTIN_FUNCTIONS:
            return Value()
        ty = T.builtin_return(name, [v.type for v in values])
        rng, unit, comps = builtin_result(name, values, args, T.size(ty))
        if comps is not None:
            rng = hull_all(comps)
        zero = rng.may_be_zero and (name in REACH_ZERO or keeps_zero(name, values))
        why = next((v.why for v in values if v.zero and v.why), None) if zero else None
        origin = name
        ortho: tuple[tuple[str, Value], ...] = ()
        if name == "cross" and len(values) == 2:
            origin, unit, ortho = cross_facts(args, values, unit)
        elif name == "normalize" and values:
            ortho = values[0].ortho  # the same direction
        wit = builtin_witness(name, values, args, rng, comps)
        return Value(ty, rng, unit, origin, zero, comps, why=why, ortho=ortho, wit=wit)


# The evaluator's method for each kind of expression node (`_binary` for "binary" ...).
_HANDLERS: dict[str, Callable[[Evaluator, Tree], Value]] = {
    kind: getattr(Evaluator, "_" + kind)
    for kind in ("float_literal", "int_literal", "bool_literal", "variable", "unary", "prefix",
                 "postfix", "binary", "ternary", "assignment", "sequence", "field", "index",
                 "constructor", "call")
}  # fmt: skip

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


class RecordedEvaluator(Evaluator):
    """An evaluator whose children take the values the model recorded for them, each in its
    own environment (narrowed branches), where it recorded one."""

    def _sub(self, node: Node) -> Value:
        if isinstance(node, Tree):
            return self.model.value_of(node)
        return self.eval(node)


_POLY_SIZE = 64  # nodes: longer expressions are left to interval arithmetic


_POLY_DEGREE = 8


def as_polynomial(node: Tree) -> tuple[Node, list[float]] | None:
    """(x, coefficients) when `node` is a polynomial with constant coefficients in one
    expression x that occurs at least twice (+, -, *, unary minus, division by a constant);
    None otherwise."""
    atoms: list[Node] = []
    budget = [_POLY_SIZE]
    coeffs = _poly(node, atoms, budget)
    if coeffs is None or len(atoms) < 2:
        return None
    return atoms[0], coeffs


def _poly(n: Node, atoms: list[Node], budget: list[int]) -> list[float] | None:
    """`n`'s coefficients in the one expression `atoms` collects (a module function, not a
    recursive closure: a closure that calls itself is a reference cycle left to the collector)."""
    budget[0] -= 1
    if budget[0] < 0 or not isinstance(n, Tree):
        return None
    if n.data in ("float_literal", "int_literal"):
        text = leaf_text(n).rstrip("fFuU")
        try:
            return [float(text) if n.data == "float_literal" else float(int_value(text) or 0)]
        except ValueError:
            return None
    if n.data == "unary" and operator(n) in "+-":
        inner = _poly(operand(n), atoms, budget)
        if inner is None:
            return None
        return inner if operator(n) == "+" else [-c for c in inner]
    if n.data == "binary" and operator(n) in ("+", "-", "*", "/"):
        left, op, right = binary_parts(n)
        a, b = _poly(left, atoms, budget), _poly(right, atoms, budget)
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


def _trig_axis(ty: str, nodes: list[Node]) -> bool:
    """vec2/vec3(sin(x), cos(x)) with zeros elsewhere, in any order: a unit vector."""
    if ty not in ("vec2", "vec3") or len(nodes) != T.size(ty):
        return False
    trig = {}
    for n in nodes:
        if is_tree(n, "float_literal", "int_literal"):
            text = leaf_text(n).rstrip("fF")  # type: ignore[arg-type]
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


def _binary_witness(
    op: str, a: Value, b: Value, ty: str | None, rng: Interval, comps: Comps
) -> W.Witness | None:
    """The witness of a op b (witness.py), component by component; none for matrices."""
    if a.wit is None and b.wit is None:
        return None  # constants alone are no news: their range says it all
    if T.matrix_shape(a.type) or T.matrix_shape(b.type):
        return None
    n = T.size(ty) or 1
    ra, rb = a.parts(n), b.parts(n)
    pa, pb = W.pairs(a.wit, ra), W.pairs(b.wit, rb)
    combine = W.BINARY[op]
    parts = [combine(x, rx, y, ry) for x, rx, y, ry in zip(pa, ra, pb, rb, strict=True)]
    why = (a.wit or b.wit).why  # type: ignore[union-attr]
    return W.make(parts, why, list(comps) if comps is not None else [rng] * n)


def _constructor_witness(ty: str, args: list[Value], comps: Comps) -> W.Witness | None:
    """vecN(...)'s witness: its arguments' components in order, a scalar broadcast."""
    if not any(a.wit is not None for a in args):
        return None
    n = T.size(ty)
    if n < 2 or comps is None:
        return None
    parts: list[W.Pair] = []
    why = next(a.wit.why for a in args if a.wit is not None)
    for a in args:
        k = T.size(a.type)
        if k == 0 or T.components(ty)[0] != T.components(a.type)[0]:  # type: ignore[index]
            # a conversion (int to float): no witness
            parts += [W.NOTHING] * max(k, 1)
            continue
        parts += W.pairs(a.wit, a.parts(k))
    if len(parts) == 1:
        parts *= n
    if len(parts) < n:
        return None
    return W.make(parts[:n], why, list(comps))


def _is_rotation(ty: str, args: list[Value], nodes: list[Node]) -> bool:
    """mat2(c, s, -s, c) (or its transpose) of c = cos(a), s = sin(a); mat3(u, v, w) of unit
    vectors known pairwise orthogonal (a look-at camera's basis): matrices that keep lengths."""
    if ty == "mat2" and len(args) == 4:
        origins = [a.origin for a in args]
        if origins[0] != origins[3] or origins[1] != origins[2]:
            return False
        if {origins[0], origins[1]} != {"sin", "cos"}:
            return False
        negated = [is_tree(n, "unary") and operator(n) == "-" for n in nodes]  # type: ignore
        return negated in ([False, False, True, False], [False, True, False, False])
    if ty == "mat3" and len(args) == 3 and all(a.unit and a.type == "vec3" for a in args):
        names = [variable_name(n) for n in nodes]
        for i in range(3):
            for j in range(i + 1, 3):
                if not (_orthogonal(args[i], names[j], args[j])
                        or _orthogonal(args[j], names[i], args[i])):  # fmt: skip
                    return False
        return True
    return False


def _orthogonal(a: Value, name: str | None, b: Value) -> bool:
    return name is not None and any(n == name and v is b for n, v in a.ortho)


def _rotated(op: str, a: Value, b: Value, ty: str | None) -> Value | None:
    """A rotation times a vector (either side): the vector's length, so a unit vector stays
    one, and every component within that length."""
    if op != "*" or not T.is_vector(ty):
        return None
    if a.origin == "rotation" and T.matrix_shape(a.type):
        vec = b
    elif b.origin == "rotation" and T.matrix_shape(b.type):
        vec = a
    else:
        return None
    n = T.size(ty)
    if T.size(vec.type) != n:
        return None
    reach = 1.0 if vec.unit else builtin_length(vec, n).hi
    comps = tuple(Interval(-reach, reach) for _ in range(n))
    return Value(ty, unit=vec.unit, origin="rotated", comps=comps)
