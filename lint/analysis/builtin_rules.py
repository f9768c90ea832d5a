"""What the builtin functions do to values: the range of each builtin's result from its
arguments' ranges (a table of interval functions by name and arity, and rules of their own for
the geometric builtins: dot, length, distance, normalize, cross, reflect, faceforward), whether
the result is a unit vector, and which builtins reach or keep a 0 on evidence."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable

from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import variable_name
from glint.compiler.glsl.keywords import words

from ..context import Node
from . import witness as W
from .ranges import (
    HALF_PI,
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
    pow_range,
    sign_range,
    sin_range,
    sqrt_range,
    step_range,
    tan_range,
)
from .syntax import same_expression
from .values import Comps, Value

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


def builtin_result(
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


def sum_of(term: Interval, n: int) -> Interval:
    """The sum of n terms each in `term`; any count from 1 to 4 when n is unknown."""
    if n:
        return term.scale(float(n))
    return hull_all([term.scale(float(k)) for k in range(1, 5)])


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
        return sum_of(a.range.square(), n), False, None
    if n:
        rng = _total(x * y for x, y in zip(a.parts(n), b.parts(n), strict=True))
    else:
        rng = sum_of(a.range * b.range, n)
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


def builtin_length(v: Value, n: int) -> Interval:
    """The range of length(v) for an n-component v."""
    return _length(v, n)


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


# --- evidence of a 0 ---------------------------------------------------------------------

# Builtins whose result really passes through 0 when its range contains it (a length at the
# origin, sin at kπ, fract at integers), as opposed to a range widened by interval arithmetic.
REACH_ZERO = words(
    """length distance dot cross sin cos tan asin atan sinh tanh fract mod floor ceil trunc
    round roundEven sign step smoothstep"""
)


# Builtins with f(0) = 0 (or that pass an argument through): evidence of a 0 in an argument is
# evidence of a 0 in the result. pow(2.0, floor(b)) is 1 where b is 0; exp, cos, inversesqrt
# never give 0 for a 0.
_KEEP_ZERO = words(
    """abs sqrt sign min max clamp mix radians degrees sinh tanh asin atan normalize reflect
    faceforward dFdx dFdy fwidth"""
)


def keeps_zero(name: str, values: list[Value]) -> bool:
    if name == "pow":
        return bool(values) and values[0].zero
    return name in _KEEP_ZERO and any(v.zero for v in values)


def cross_facts(
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
    keys = [variable_name(n) for n in nodes]
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


# --- witnesses: values reached at a named input (witness.py) -------------------------------

# A negative value a dot product with a direction reaches, for the witness: some negative value,
# however small (how negative is not known).
_SOME_NEGATIVE = -W.SOME


def builtin_witness(
    name: str, values: list[Value], nodes: list[Node], rng: Interval, comps: Comps
) -> W.Witness | None:
    """What a builtin's result reaches on evidence: sin and cos of an unbounded argument
    sweep [-1, 1]; min, max, clamp and abs keep their arguments' witnesses; normalize keeps a
    component's sign; a dot product with a direction (a unit vector) of the other vector, whose
    range takes both signs, is negative where they face away (N·H, R·V)."""
    n = len(comps) if comps is not None else 1
    out_comps = list(comps) if comps is not None else [rng]
    if name in ("sin", "cos") and len(values) == 1:
        parts = [(-1.0, 1.0) if W.unbounded_trig(c) else W.NOTHING for c in values[0].parts(n)]
        return W.make(parts, W.TRIG, out_comps)
    if name == "dot" and len(values) == 2:
        a, b = values
        if (same_expression(nodes[0], nodes[1]) or not (a.unit or b.unit)
                or not rng.lo < 0 < rng.hi or not rng.is_bounded):  # fmt: skip
            return None
        return W.make([(_SOME_NEGATIVE, -_SOME_NEGATIVE)], W.DOT, out_comps)
    wits = [v.wit for v in values if v.wit is not None]
    if not wits:
        return None
    why = wits[0].why
    columns = [W.pairs(v.wit, v.parts(n)) for v in values]
    ranges = [v.parts(n) for v in values]
    if name in ("min", "max") and len(values) == 2:
        f = W.minimum if name == "min" else W.maximum
        parts = [f(columns[0][i], ranges[0][i], columns[1][i], ranges[1][i]) for i in range(n)]
        return W.make(parts, why, out_comps)
    if name == "clamp" and len(values) == 3:
        parts = []
        for i in range(n):
            low = W.maximum(columns[0][i], ranges[0][i], columns[1][i], ranges[1][i])
            raised = ranges[0][i].max(ranges[1][i])
            parts.append(W.minimum(low, raised, columns[2][i], ranges[2][i]))
        return W.make(parts, why, out_comps)
    if name == "abs" and len(values) == 1:
        parts = [(W.INF, max(p[1], -p[0])) for p in columns[0]]
        return W.make(parts, why, out_comps)
    if name == "normalize" and len(values) == 1 and T.size(values[0].type) > 1:
        v = values[0]
        k = T.size(v.type)
        longest = _length(Value(v.type, comps=tuple(v.parts(k))), k).hi
        parts = [W.normalized(p, longest) for p in W.pairs(v.wit, v.parts(k))]
        return W.make(parts, W.VIEW_RAY if why == W.CORNER_PIXEL else why, out_comps)
    return None
