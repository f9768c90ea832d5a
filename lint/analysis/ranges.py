"""Interval arithmetic over the reals: the value ranges the semantic model gives expressions.

An `Interval` is closed, [lo, hi], with ±inf for "unbounded on that side"; (-inf, inf) is
"unknown" and never makes a rule report anything. Vectors get the hull of their components.
Operations are sound: for x in a and y in b, `a + b` contains x + y, and so on. Floating-point
rounding is monotone, so the bounds computed here also hold for the float results of sample
points inside the operands (the property tests check exactly that).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

INF = math.inf
HALF_PI = math.pi / 2


@dataclass(frozen=True, init=False)
class Interval:
    lo: float = -INF
    hi: float = INF

    def __init__(self, lo: float = -INF, hi: float = INF) -> None:
        # A NaN bound (inf - inf, 0 * inf) would make every comparison false: widen instead
        # (x != x only for NaN). Written out rather than the frozen dataclass's __init__ and a
        # __post_init__: the model makes intervals by the million, and this is a third of it.
        fields = self.__dict__
        fields["lo"] = -INF if lo != lo else lo
        fields["hi"] = INF if hi != hi else hi

    # --- construction ----------------------------------------------------------------------

    @staticmethod
    def point(x: float) -> Interval:
        return Interval(x, x)

    @staticmethod
    def unknown() -> Interval:
        return UNKNOWN

    # --- questions rules ask ---------------------------------------------------------------

    @property
    def is_unknown(self) -> bool:
        return self.lo == -INF and self.hi == INF

    @property
    def is_point(self) -> bool:
        return self.lo == self.hi

    @property
    def is_bounded(self) -> bool:
        return math.isfinite(self.lo) and math.isfinite(self.hi)

    @property
    def may_be_negative(self) -> bool:
        return self.lo < 0

    @property
    def may_be_zero(self) -> bool:
        return self.lo <= 0 <= self.hi

    @property
    def may_be_positive(self) -> bool:
        return self.hi > 0

    @property
    def is_nonnegative(self) -> bool:
        return self.lo >= 0

    @property
    def is_positive(self) -> bool:
        return self.lo > 0

    def within(self, lo: float, hi: float) -> bool:
        """Whether every value lies in [lo, hi]."""
        return lo <= self.lo and self.hi <= hi

    def contains(self, x: float) -> bool:
        return self.lo <= x <= self.hi

    def describe(self) -> str:
        """For messages: "[-1, 1]", "[0, inf)", "(-inf, 2]", "unknown"."""
        if self.is_unknown:
            return "unknown"
        left = "(-inf" if self.lo == -INF else f"[{_num(self.lo)}"
        right = "inf)" if self.hi == INF else f"{_num(self.hi)}]"
        return f"{left}, {right}"

    # --- lattice ---------------------------------------------------------------------------

    def hull(self, other: Interval) -> Interval:
        return Interval(min(self.lo, other.lo), max(self.hi, other.hi))

    def meet(self, other: Interval) -> Interval:
        """The intersection; an empty one (contradictory facts) stays unknown-free by
        keeping `self`, which is always sound."""
        lo, hi = max(self.lo, other.lo), min(self.hi, other.hi)
        return Interval(lo, hi) if lo <= hi else self

    # --- arithmetic ------------------------------------------------------------------------

    def __neg__(self) -> Interval:
        return Interval(-self.hi, -self.lo)

    def __add__(self, other: Interval) -> Interval:
        return Interval(self.lo + other.lo, self.hi + other.hi)

    def __sub__(self, other: Interval) -> Interval:
        return Interval(self.lo - other.hi, self.hi - other.lo)

    def __mul__(self, other: Interval) -> Interval:
        products = [_mul(a, b) for a in (self.lo, self.hi) for b in (other.lo, other.hi)]
        return Interval(min(products), max(products))

    def __truediv__(self, other: Interval) -> Interval:
        if other.lo > 0 or other.hi < 0:
            quotients = [_div(a, b) for a in (self.lo, self.hi) for b in (other.lo, other.hi)]
            quotients = [q for q in quotients if not math.isnan(q)]  # inf / inf: a limit
            return Interval(min(quotients), max(quotients))
        if other.lo == 0 and other.hi > 0:  # (0, b]: the quotient only grows towards zero
            return _towards_zero(self, other.hi)
        if other.hi == 0 and other.lo < 0:
            return -_towards_zero(self, -other.lo)
        return UNKNOWN  # the divisor takes both signs, or is exactly zero

    def scale(self, k: float) -> Interval:
        return self * Interval.point(k)

    def square(self) -> Interval:
        """x * x for the same x: never negative (tighter than self * self)."""
        a, b = _mul(self.lo, self.lo), _mul(self.hi, self.hi)
        if self.may_be_zero:
            return Interval(0.0, max(a, b))
        return Interval(min(a, b), max(a, b))

    def abs(self) -> Interval:
        if self.lo >= 0:
            return self
        if self.hi <= 0:
            return -self
        return Interval(0.0, max(-self.lo, self.hi))

    def min(self, other: Interval) -> Interval:
        return Interval(min(self.lo, other.lo), min(self.hi, other.hi))

    def max(self, other: Interval) -> Interval:
        return Interval(max(self.lo, other.lo), max(self.hi, other.hi))

    def clamp(self, lo: Interval, hi: Interval) -> Interval:
        return self.max(lo).min(hi)

    def monotone(self, f: Callable[[float], float]) -> Interval:
        """f applied to the bounds of an increasing f, one ulp outwards (libm's exp or atan
        may round either way)."""
        return Interval(_outward(f, self.lo, -INF), _outward(f, self.hi, INF))


UNKNOWN = Interval(-INF, INF)
UNIT = Interval(-1.0, 1.0)
ZERO_ONE = Interval(0.0, 1.0)
NONNEG = Interval(0.0, INF)
BOOL = ZERO_ONE


def _num(x: float) -> str:
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return f"{x:.4g}"


def _mul(a: float, b: float) -> float:
    # 0 * inf is 0 here: an unbounded factor is a large finite value, never infinity itself.
    if a == 0 or b == 0:
        return 0.0
    return a * b


def _inv(x: float) -> float:
    return 0.0 if math.isinf(x) else 1 / x


def _div(a: float, b: float) -> float:
    if math.isinf(b):
        return math.nan if math.isinf(a) else 0.0
    return a / b


def _towards_zero(num: Interval, hi: float) -> Interval:
    """num / d for d in (0, hi]: unbounded away from zero on the numerator's side."""
    if num.lo >= 0:
        return Interval(_div(num.lo, hi), INF)
    if num.hi <= 0:
        return Interval(-INF, _div(num.hi, hi))
    return UNKNOWN


def _outward(f: Callable[[float], float], x: float, direction: float) -> float:
    y = _safe(f, x, direction)
    if _integral(x) and _integral(y):
        return y  # exp(0) = 1, log2(8) = 3: libm gets integers exactly
    return math.nextafter(y, direction)


def _integral(x: float) -> bool:
    return not math.isfinite(x) or x == int(x)


def _safe(f: Callable[[float], float], x: float, fallback: float) -> float:
    try:
        y = f(x)
    except (OverflowError, ValueError, ZeroDivisionError):
        return fallback
    return fallback if math.isnan(y) else float(y)


def hull_all(items: Sequence[Interval]) -> Interval:
    if not items:
        return UNKNOWN
    out = items[0]
    for item in items[1:]:
        out = out.hull(item)
    return out


# --- builtin functions --------------------------------------------------------------------


def sin_range(x: Interval) -> Interval:
    return _periodic(x, math.sin, HALF_PI)


def cos_range(x: Interval) -> Interval:
    return _periodic(x, math.cos, 0.0)


# Beyond this magnitude a float is no longer precise to a small part of π: where its steps
# reach π, `k * π` stops growing with k and the extrema cannot be told apart (a loop over
# them never ended on a value grown to 1e20 by a loop's widening).
_PRECISE_ANGLE = 2.0**40


def _periodic(x: Interval, f: Callable[[float], float], peak: float) -> Interval:
    """sin or cos over x: the values at the ends and at every extremum (peak + kπ) inside."""
    if not x.is_bounded or x.hi - x.lo >= 2 * math.pi or max(-x.lo, x.hi) > _PRECISE_ANGLE:
        return UNIT
    values = [f(x.lo), f(x.hi)]
    k = math.ceil((x.lo - peak) / math.pi)
    for _ in range(3):  # narrower than 2π: at most two extrema inside
        if peak + k * math.pi > x.hi:
            break
        values.append(1.0 if k % 2 == 0 else -1.0)
        k += 1
    return Interval(max(-1.0, min(values)), min(1.0, max(values)))


def tan_range(x: Interval) -> Interval:
    """Bounded and increasing between two poles, unknown across one."""
    if reaches_tan_pole(x) or not x.is_bounded:
        return UNKNOWN
    return Interval(math.tan(x.lo), math.tan(x.hi))


def reaches_tan_pole(x: Interval) -> bool:
    """Whether x contains π/2 + kπ for some integer k."""
    if x.is_unknown:
        return False  # nothing is known, so nothing is reported
    if not x.is_bounded:
        return True
    k = math.ceil((x.lo - HALF_PI) / math.pi)
    return HALF_PI + k * math.pi <= x.hi


def exp_range(x: Interval, f: Callable[[float], float] = math.exp) -> Interval:
    # exp is never 0: keep the lower bound above zero even where it underflows.
    out = x.monotone(f)
    return Interval(max(out.lo, 5e-324), out.hi)


def log_range(x: Interval, f: Callable[[float], float] = math.log) -> Interval:
    if x.hi <= 0:
        return UNKNOWN
    return Interval(max(x.lo, 0.0), x.hi).monotone(lambda v: f(v) if v > 0 else -INF)


def sqrt_range(x: Interval) -> Interval:
    return Interval(math.sqrt(max(x.lo, 0.0)), math.sqrt(max(x.hi, 0.0)))


def inversesqrt_range(x: Interval) -> Interval:
    if x.lo > 0:
        return Interval(_inv(math.sqrt(x.hi)), 1 / math.sqrt(x.lo))
    return Interval(0.0, INF)


def pow_range(base: Interval, exponent: Interval) -> Interval:
    """GLSL's pow is undefined for a negative base, never negative where it is defined."""
    if base.lo >= 0 and exponent.is_point:
        e = exponent.lo
        if e == 0:
            return Interval.point(1.0)
        lo, hi = (base.lo, base.hi) if e > 0 else (base.hi, base.lo)
        return Interval(_pow(lo, e), _pow(hi, e))
    if base.lo >= 1 and exponent.lo >= 0:
        return Interval(1.0, INF)
    if base.within(0, 1) and exponent.lo >= 0:
        return ZERO_ONE
    return NONNEG


def _pow(x: float, e: float) -> float:
    if x == 0:
        return 0.0 if e > 0 else INF
    try:
        return x**e
    except OverflowError:
        return INF


def mod_range(x: Interval, y: Interval) -> Interval:
    if y.lo > 0:  # GLSL mod is x - y * floor(x / y): in [0, y) for positive y
        return Interval(0.0, y.hi)
    if y.hi < 0:
        return Interval(y.lo, 0.0)
    return UNKNOWN


def atan_range(y: Interval, x: Interval | None) -> Interval:
    if x is None:
        return y.monotone(math.atan)
    if x.lo > 0:  # the right half-plane: atan(y, x) = atan(y / x)
        return Interval(-HALF_PI, HALF_PI)
    return Interval(-math.pi, math.pi)


def step_range(edge: Interval, x: Interval) -> Interval:
    if x.lo >= edge.hi:
        return Interval.point(1.0)
    if x.hi < edge.lo:
        return Interval.point(0.0)
    return ZERO_ONE


def mix_range(x: Interval, y: Interval, a: Interval) -> Interval:
    """x (1 - a) + y a is linear in each of x, y and a: its extremes are at the corners."""
    if a.within(0, 1):
        return x.hull(y)
    values = [
        _mul(xv, 1 - av) + _mul(yv, av)
        for xv in (x.lo, x.hi)
        for yv in (y.lo, y.hi)
        for av in (a.lo, a.hi)
    ]
    if any(math.isnan(v) for v in values):
        return UNKNOWN
    return Interval(min(values), max(values))


def sign_range(x: Interval) -> Interval:
    lo = -1.0 if x.lo < 0 else (0.0 if x.lo == 0 else 1.0)
    hi = 1.0 if x.hi > 0 else (0.0 if x.hi == 0 else -1.0)
    return Interval(lo, hi)


def floor_like(f: Callable[[float], float]) -> Callable[[Interval], Interval]:
    return lambda x: Interval(_safe(f, x.lo, -INF), _safe(f, x.hi, INF))


def fract_range(x: Interval) -> Interval:
    if x.is_bounded and math.floor(x.lo) == math.floor(x.hi):
        return Interval(x.lo - math.floor(x.lo), x.hi - math.floor(x.lo))
    return ZERO_ONE


def length_bound(x: Interval, n: int) -> Interval:
    """length() of an n-component vector whose components lie in x."""
    far = max(abs(x.lo), abs(x.hi))
    near = 0.0 if x.may_be_zero else min(abs(x.lo), abs(x.hi))
    return Interval(near * math.sqrt(n), _mul(far, math.sqrt(n)))


def poly_range(coeffs: Sequence[float], x: Interval) -> Interval:
    """The range of the polynomial sum(coeffs[k] * x**k) over a bounded x: its values at the
    ends and at the critical points inside (the real roots of the derivative). Exact where
    interval arithmetic is not: t*t*(3 - 2t), the smoothstep weight, is [0, 1] on [0, 1], not
    [0, 3]. The values at the critical points are widened by a relative 1e-12 for the roots'
    own rounding; the ends are evaluated as given."""
    if not x.is_bounded:
        return UNKNOWN
    import numpy as np  # only here: the linter imports numpy for this one computation

    def at(v: float) -> float:
        return math.fsum(c * v**k for k, c in enumerate(coeffs))

    try:
        return _poly_range(coeffs, x, at, np)
    except OverflowError:
        return UNKNOWN


def _poly_range(coeffs: Sequence[float], x: Interval, at: Callable[[float], float],
                np: Any) -> Interval:  # fmt: skip
    values = [at(x.lo), at(x.hi)]
    lo, hi = min(values), max(values)
    derivative = [k * c for k, c in enumerate(coeffs)][1:]
    while derivative and derivative[-1] == 0:
        derivative.pop()
    if len(derivative) > 1 and x.lo < x.hi:
        if abs(derivative[-1]) < 1e-9 * max(abs(c) for c in derivative):
            return UNKNOWN  # badly scaled: interval arithmetic's own bound stands
        try:
            with np.errstate(all="ignore"):
                roots = np.roots(list(reversed(derivative)))
        except (np.linalg.LinAlgError, ValueError):
            return UNKNOWN  # badly scaled: interval arithmetic's own bound stands
        for root in roots:
            r = float(root.real)
            if not math.isfinite(r):
                return UNKNOWN  # any point inside is a value p takes: a complex root is harmless
            if x.lo < r < x.hi:
                v = at(r)
                margin = 1e-12 * max(1.0, abs(v))
                lo, hi = min(lo, v - margin), max(hi, v + margin)
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return UNKNOWN
    return Interval(lo, hi)
