"""Witnesses: values an expression really takes at a named reachable input, beside its range.

A range is sound but says nothing about which of its values occur: `1.0 + dot(n, rd)` comes
out as [-1, 3] by interval arithmetic for vectors the model cannot prove unit, though it is
never negative. A rule that reports a domain error by default needs evidence that the bad value
is reached. A witness is that evidence, per component: `low` says the value is <= low at some
reachable input, `high` that it is >= high at some (possibly other) input, and `why` names the
input ("at the first frame, iTime = 0", "sin takes both signs"). (inf, -inf) is "nothing known".

The rules combine a witness of one operand with the sound range of the other, so they stay
sound for any input: at the input where x <= low, x + y <= low + max(y). Constants are their
own witnesses. The builtins that keep a witness are listed in `builtin_witness`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .ranges import INF, Interval

Pair = tuple[float, float]  # (low, high): value <= low somewhere, value >= high somewhere
NOTHING: Pair = (INF, -INF)

# The first frame and the bottom-left pixel: the inputs every shader meets.
FIRST_FRAME = "at the first frame, iTime = 0"
FIRST_FRAME_COUNT = "at the first frame, iFrame = 0"
# The bottom-left pixel's centre: every screen coordinate built from fragCoord is at its lowest
# there (a view ray built from it points down and left in the camera's frame).
CORNER_PIXEL = "at the bottom-left pixel, fragCoord = (0.5, 0.5)"
# A view ray normalized from the screen coordinate, before any camera matrix turns it (the
# witness does not survive a matrix: a world direction's sign depends on where the camera looks,
# only a rotation of the other components, `rd.xz *= rot`, keeps it).
VIEW_RAY = "for view rays towards the bottom-left of the screen"
TRIG = "where sin or cos of an unbounded argument is negative"
DOT = "where the vectors of an unclamped dot product with a direction face away"


@dataclass(frozen=True)
class Witness:
    parts: tuple[Pair, ...]  # one per component (one for a scalar)
    why: str


def pairs(w: Witness | None, comps: list[Interval]) -> list[Pair]:
    """The witnesses of n components (`comps`, the value's component ranges): the value's own,
    a scalar's broadcast, and a constant component as its own witness."""
    n = len(comps)
    if w is not None and len(w.parts) == n:
        out = list(w.parts)
    elif w is not None and len(w.parts) == 1:
        out = [w.parts[0]] * n
    else:
        out = [NOTHING] * n
    for i, c in enumerate(comps):
        if c.is_point and math.isfinite(c.lo):
            out[i] = (min(out[i][0], c.lo), max(out[i][1], c.lo))
    return out


def make(parts: list[Pair], why: str | None, comps: list[Interval]) -> Witness | None:
    """A witness of these parts, each dropped where it contradicts the range (a witness below
    the lower bound: the range was narrowed by a condition the witness's input fails)."""
    out: list[Pair] = []
    for (lo, hi), c in zip(parts, comps, strict=True):
        out.append((lo if lo >= c.lo and not math.isnan(lo) else INF,
                    hi if hi <= c.hi and not math.isnan(hi) else -INF))  # fmt: skip
    if why is None or all(p == NOTHING for p in out):
        return None
    return Witness(tuple(out), why)


def join(a: Witness | None, b: Witness | None) -> Witness | None:
    """Either path's witness is reached on that path: the lower low and the higher high."""
    if a is None or b is None:
        return a or b
    if len(a.parts) != len(b.parts):
        return None
    parts = tuple((min(x[0], y[0]), max(x[1], y[1])) for x, y in zip(a.parts, b.parts, strict=True))
    return Witness(parts, a.why)


def negate(p: Pair) -> Pair:
    return (-p[1], -p[0])


def add(a: Pair, ra: Interval, b: Pair, rb: Interval) -> Pair:
    """x + y at x's witness input (y anywhere in its range), or at y's."""
    return (min(a[0] + rb.hi, b[0] + ra.hi), max(a[1] + rb.lo, b[1] + ra.lo))


def sub(a: Pair, ra: Interval, b: Pair, rb: Interval) -> Pair:
    return add(a, ra, negate(b), -rb)


def _scaled(p: Pair, r: Interval) -> Pair:
    """x * y at x's witness input, for y of one sign (its range r): with y >= 0, x <= low
    gives x y <= low * min(y) where low <= 0, and <= low * max(y) where low > 0."""
    if r.hi <= 0 and r.lo < 0:
        return negate(_scaled(p, -r))
    if r.lo < 0:
        return NOTHING
    lo, hi = p
    if lo != INF:
        lo = _times(lo, r.lo if lo <= 0 else r.hi)
    if hi != -INF:
        hi = _times(hi, r.lo if hi >= 0 else r.hi)
    return (lo, hi)


def _times(a: float, b: float) -> float:
    return 0.0 if a == 0 or b == 0 else a * b


def mul(a: Pair, ra: Interval, b: Pair, rb: Interval) -> Pair:
    x, y = _scaled(a, rb), _scaled(b, ra)
    return (min(x[0], y[0]), max(x[1], y[1]))


def div(a: Pair, ra: Interval, b: Pair, rb: Interval) -> Pair:
    """x / y at x's witness input, for y of one sign: x times 1 / y, whose range is
    [1 / max y, 1 / min y]. A negative x <= low gives x / y <= low / max y (at least as far
    from 0), a positive one only x / y <= low / min y (1 / iResolution.x is at most 1 / the
    smallest canvas)."""
    if rb.lo > 0:
        return _scaled(a, Interval(1 / rb.hi if math.isfinite(rb.hi) else 0.0, 1 / rb.lo))
    if rb.hi < 0:
        return _scaled(a, Interval(1 / rb.hi, 1 / rb.lo if math.isfinite(rb.lo) else 0.0))
    return NOTHING


def minimum(a: Pair, ra: Interval, b: Pair, rb: Interval) -> Pair:
    return (min(a[0], b[0]), max(min(a[1], rb.lo), min(b[1], ra.lo)))


def maximum(a: Pair, ra: Interval, b: Pair, rb: Interval) -> Pair:
    return negate(minimum(negate(a), -ra, negate(b), -rb))


BINARY = {"+": add, "-": sub, "*": mul, "/": div}


def unbounded_trig(x: Interval) -> bool:
    """Whether sin or cos of x sweeps a whole period on evidence: x is unbounded (a time, a
    position, an unknown parameter) or spans more than 2π."""
    return not x.is_bounded or x.hi - x.lo >= 2 * math.pi


# Some value of a sign, however close to 0 (how far is not known): a normalized component of a
# vector of unbounded length, a dot product of vectors that face away.
SOME = 1e-30


def normalized(p: Pair, longest: float) -> Pair:
    """A component of normalize(v) at v's witness: it keeps its sign, scaled by at most
    1 / longest (the largest length v takes); of an unbounded v only the sign is known."""
    if longest <= 0 or math.isnan(longest):
        return NOTHING
    if not math.isfinite(longest):
        return (-SOME if p[0] < 0 else INF, SOME if p[1] > 0 else -INF)
    lo = p[0] / longest if p[0] < 0 else INF
    hi = p[1] / longest if p[1] > 0 else -INF
    return (max(lo, -1.0) if lo < INF else INF, min(hi, 1.0) if hi > -INF else -INF)
