"""Numerical hazards: builtins called outside their domain, divisions by values that reach zero,
degenerate normalize, and constant arguments that make clamp/smoothstep undefined.

Every rule asks the semantic model for value ranges instead of matching text, so
`pow(max(dot(N, H), 0.0), s)` is clean and `pow(dot(N, H), s)` is not. A range the model cannot
bound is unknown and never reported: a finding needs evidence, a finite bound reached by the
value (dot of unit vectors in [-1, 1], a length that starts at 0) or a value that is a raw dot
product, length or cross product.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator

from lark import Token, Tree

from ..analysis.model import Model, Value, call_args, callee_name, semantic_model
from ..analysis.ranges import Interval, reaches_tan_pole
from ..analysis.types import components, size
from ..context import LintContext, walk
from ..finding import Finding, Fix, Severity
from . import Rule, register

Node = Tree | Token
EPSILON = "1e-4"  # the divisor floor N005's fix inserts
LOG_FLOOR = "1e-6"  # log(0) is -inf, so the floor for log must be above zero


# --- evidence: when a range really reaches a bad value --------------------------------------


# How far past a limit a bound must be to count: 1 - exp(-x) may come out as -2e-16 from the
# bounds' own rounding, which is not a negative value anyone wrote.
SLACK = 1e-9


def reaches_below(r: Interval, c: float) -> bool:
    """Values below c are reached on evidence: a finite lower bound under c, or a range that
    lies under c entirely. (-inf, 1] from `1.0 - x * x` with x unknown is no such evidence."""
    return r.lo < c - SLACK and (r.lo > -math.inf or r.hi <= c)


def reaches_above(r: Interval, c: float) -> bool:
    return r.hi > c + SLACK and (r.hi < math.inf or r.lo >= c)


def reaches_zero(v: Value) -> bool:
    """Zero is in the range on evidence: a value the model knows reaches 0 (a length, a dot
    product, sin, max(x, 0.0), x - c across c, a product with such a factor). A range that
    merely contains 0 after interval arithmetic is no evidence: GGX's 1 + NoH²(a² - 1) is in
    [0, 1.25] by intervals and never below a²."""
    r = v.range
    if not r.may_be_zero:
        return False
    return v.zero or v.origin in ("dot", "length", "distance")


def is_raw_dot(v: Value) -> bool:
    return v.origin == "dot"


# --- helpers --------------------------------------------------------------------------------


def builtin_calls(ctx: LintContext, model: Model, *names: str) -> Iterator[tuple[Tree, str]]:
    """Calls of these builtins (a user function of the same name is not the builtin)."""
    for node in ctx.nodes("call"):
        name = callee_name(node)
        if name in names and name not in model.functions:
            yield node, name


def text(ctx: LintContext, node: Node, limit: int = 48) -> str:
    """The expression as written, on one line, shortened for a message."""
    s = re.sub(r"\s+", " ", ctx.node_text(node)).strip()
    return s if len(s) <= limit else s[: limit - 3] + "..."


def range_note(v: Value, fallback: str) -> str:
    return f"range {v.range.describe()}" if not v.range.is_unknown else fallback


def wrap_fix(ctx: LintContext, node: Node, template: str, message: str) -> Fix | None:
    """An unsafe fix that rewrites `node` as `template` with {} the node's text; None where
    a macro makes the position untrustworthy."""
    edit = ctx.replace(node, template.format(ctx.node_text(node).strip()))
    return Fix(message, (edit,), "unsafe") if edit is not None else None


class NumericalRule(Rule):
    category = "numerical"

    def emit(self, ctx: LintContext, where: Node, message: str, fix: Fix | None = None,
             severity: Severity | None = None) -> Finding:  # fmt: skip
        return ctx.finding(self.code, severity or self.severity, where, message, fix)


# --- the rules ------------------------------------------------------------------------------


@register
class PowNegativeBase(NumericalRule):
    """Finds `pow(x, y)` whose base may be negative, such as an unclamped dot product.

    Why it matters: GLSL leaves pow undefined for x < 0; GPUs return NaN or garbage there, and
    one NaN in a specular term turns the pixel black or spreads through a blur. N·H is negative
    on every surface facing away from the half vector.

    Example:
        float spec = pow(dot(N, H), shininess);

    Fix:
        float spec = pow(max(dot(N, H), 0.0), shininess);
    """

    code = "N001"
    name = "pow-negative-base"
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, _ in builtin_calls(ctx, model, "pow"):
            args = call_args(call)
            if len(args) != 2:
                continue
            base = model.value_of(args[0])
            negative = reaches_below(base.range, 0.0) or (
                is_raw_dot(base) and base.range.may_be_negative
            )
            if not negative:
                continue
            shown = text(ctx, args[0])
            note = range_note(base, "an unclamped dot product takes either sign")
            message = f"pow base {shown} may be negative ({note}); clamp it: max({shown}, 0.0)"
            fix = wrap_fix(ctx, args[0], "max({}, 0.0)", "clamp the base at 0")
            yield self.emit(ctx, args[0], message, fix)


@register
class SqrtLogDomain(NumericalRule):
    """Finds `sqrt` or `inversesqrt` of a value that may be negative, and `log`/`log2` of a
    value that may be zero or negative.

    Why it matters: outside their domain these are undefined in GLSL and give NaN (or -inf
    for log(0)) on real GPUs; `1.0 - x * x` goes slightly negative by rounding even when x is
    a cosine, and a dot product is negative half the time.

    Example:
        float s = sqrt(1.0 - dot(N, L));   // fine only while dot(N, L) <= 1
        float d = sqrt(dot(N, L));

    Fix:
        float d = sqrt(max(dot(N, L), 0.0));
    """

    code = "N002"
    name = "sqrt-log-domain"
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        names = ("sqrt", "inversesqrt", "log", "log2")
        for call, name in builtin_calls(ctx, model, *names):
            args = call_args(call)
            if len(args) != 1:
                continue
            v = model.value_of(args[0])
            shown = text(ctx, args[0])
            raw_dot = is_raw_dot(v) and v.range.may_be_negative
            if name in ("sqrt", "inversesqrt"):
                if not (reaches_below(v.range, 0.0) or raw_dot):
                    continue
                note = range_note(v, "an unclamped dot product takes either sign")
                message = f"{name} of {shown}, which may be negative ({note})"
                floor = "0.0"
            else:
                if not (reaches_below(v.range, 0.0) or raw_dot or _touches_zero(v.range)):
                    continue
                note = range_note(v, "an unclamped dot product takes either sign")
                message = f"{name} of {shown}, which may be zero or negative ({note})"
                floor = LOG_FLOOR
            message += f"; clamp it: max({shown}, {floor})"
            fix = wrap_fix(ctx, args[0], "max({}, " + floor + ")", f"clamp the argument at {floor}")
            yield self.emit(ctx, args[0], message, fix)


def _touches_zero(r: Interval) -> bool:
    # log of [0, b]: the value reaches 0 exactly (max(x, 0.0), a clamp, a constant 0)
    return r.lo == 0 and r.hi < math.inf or r.hi <= 0 and not r.is_unknown


@register
class AcosAsinDomain(NumericalRule):
    """Finds `acos`/`asin` of a value that may leave [-1, 1], including an unclamped dot product
    of unit vectors.

    Why it matters: acos and asin are undefined outside [-1, 1] and give NaN there. The dot
    product of two normalized vectors is mathematically within [-1, 1] but rounds to
    1.0000001 for nearly parallel vectors, and the angle becomes NaN exactly where the
    vectors align.

    Example:
        float angle = acos(dot(a, b));

    Fix:
        float angle = acos(clamp(dot(a, b), -1.0, 1.0));
    """

    code = "N003"
    name = "acos-asin-domain"
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, name in builtin_calls(ctx, model, "acos", "asin"):
            args = call_args(call)
            if len(args) != 1:
                continue
            v = model.value_of(args[0])
            shown = text(ctx, args[0])
            if reaches_below(v.range, -1.0) or reaches_above(v.range, 1.0):
                why = f"may leave [-1, 1] (range {v.range.describe()})"
            elif is_raw_dot(v) and (v.range.lo <= -1 or v.range.hi >= 1):
                why = "is an unclamped dot product, which rounds past ±1 for parallel vectors"
            else:
                continue
            message = f"{name} of {shown} {why}; clamp it: clamp({shown}, -1.0, 1.0)"
            fix = wrap_fix(ctx, args[0], "clamp({}, -1.0, 1.0)", "clamp the argument to [-1, 1]")
            yield self.emit(ctx, args[0], message, fix)


@register
class TanPole(NumericalRule):
    """Finds `tan(x)` where the range of x reaches a pole, π/2 + kπ.

    Why it matters: tan grows without bound near its poles and flips sign across them; a
    field of view or an animated angle that reaches π/2 gives infinities and a picture that
    tears or goes black.

    Example:
        float k = tan(iTime);

    Fix:
        float k = tan(clamp(angle, -1.5, 1.5));   // keep away from ±π/2
    """

    code = "N004"
    name = "tan-pole"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, _ in builtin_calls(ctx, model, "tan"):
            args = call_args(call)
            if len(args) != 1:
                continue
            r = model.range_of(args[0])
            if reaches_tan_pole(r):
                message = (
                    f"tan of {text(ctx, args[0])} reaches a pole at π/2 + kπ "
                    f"(range {r.describe()}); keep the angle inside (-π/2, π/2)"
                )
                yield self.emit(ctx, args[0], message)


@register
class DivisionByZero(NumericalRule):
    """Finds a division by a value that can be zero: a dot product, a length or distance, a
    square, a clamped value that reaches 0, a constant 0, without an epsilon.

    Why it matters: x / 0 is infinity (0 / 0 is NaN), which survives tone mapping as a white
    or black pixel and poisons everything it is mixed with. A length is 0 at the origin, N·L
    is 0 at the terminator and negative beyond it.

    Example:
        float atten = 1.0 / dot(d, d);
        vec3 dir = p / length(p);

    Fix:
        float atten = 1.0 / max(dot(d, d), 1e-4);
    """

    code = "N005"
    name = "division-by-zero"
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for node in walk(ctx.tree):  # type: ignore[arg-type]
            divisor = _divisor(node)
            if divisor is None:
                continue
            v = model.value_of(divisor)
            if not reaches_zero(v):
                continue
            shown = text(ctx, divisor)
            fix = None
            advice = "guard it"
            # a floor keeps the meaning only for divisors that are never negative
            if v.range.is_nonnegative and (components(v.type) or ("", 0))[0] == "float":
                advice = f"add an epsilon: max({shown}, {EPSILON})"
                fix = wrap_fix(ctx, divisor, "max({}, " + EPSILON + ")", "floor the divisor")
            message = f"division by {shown}, which may be 0 (range {v.range.describe()}); {advice}"
            yield self.emit(ctx, divisor, message, fix)


def _divisor(node: Tree) -> Node | None:
    if node.data == "binary" and str(node.children[1]) == "/":
        return node.children[2]
    if node.data == "assignment" and str(node.children[1]) == "/=":
        return node.children[2]
    return None


@register
class NormalizeZero(NumericalRule):
    """Finds `normalize(v)` of a vector that may be zero: the sum or difference of two unit
    vectors (V + L), a cross product of two computed vectors, a constant zero vector.

    Why it matters: normalize(0) divides by zero and gives NaN. V + L is zero when the light
    is straight behind the surface seen from the viewer; a cross product is zero when its two
    vectors are parallel. (A cross product with a constant axis, the world-up of a look-at
    camera, is not reported: it degenerates only along that one chosen direction.)

    Example:
        vec3 H = normalize(V + L);

    Fix:
        vec3 h = V + L;
        vec3 H = h * inversesqrt(max(dot(h, h), 1e-8));
    """

    code = "N006"
    name = "normalize-zero"

    _WHY = {
        "sum": "the sum of two unit vectors is zero when they are opposite",
        "difference": "the difference of two unit vectors is zero when they are equal",
        "cross": "a cross product is zero when its vectors are parallel",
    }

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, _ in builtin_calls(ctx, model, "normalize"):
            args = call_args(call)
            if len(args) != 1:
                continue
            v = model.value_of(args[0])
            parts = v.parts(size(v.type) or 1)
            if not all(c.may_be_zero for c in parts):
                continue  # some component never reaches 0
            why = self._WHY.get(v.origin or "")
            if why is None and all(c == Interval.point(0.0) for c in parts):
                why = "it is the zero vector"
            if why is None:
                continue
            shown = text(ctx, args[0])
            message = (
                f"normalize of {shown}, which may be zero: {why}; guard the length, e.g. "
                f"v * inversesqrt(max(dot(v, v), 1e-8))"
            )
            yield self.emit(ctx, args[0], message)


@register
class ModAtanZero(NumericalRule):
    """Finds `mod(x, 0)` and `atan(y, x)` whose two arguments may both be zero.

    Why it matters: mod(x, 0) divides by zero and atan(0, 0) is undefined in GLSL; both give
    NaN or an arbitrary value that differs between GPUs. Polar coordinates of the origin are
    the usual way to reach atan(0, 0).

    Example:
        float a = atan(0.0, 0.0);
        float m = mod(x, 0.0);

    Fix:
        float m = mod(x, period);   // with period > 0
    """

    code = "N007"
    name = "mod-atan-zero"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        zero = Interval.point(0.0)
        for call, name in builtin_calls(ctx, model, "mod", "atan"):
            args = call_args(call)
            if len(args) != 2:
                continue
            a, b = (model.value_of(x) for x in args)
            if name == "mod" and b.range == zero:
                yield self.emit(ctx, call, "mod by zero is undefined", severity="error")
            elif name == "atan" and a.range == zero and b.range == zero:
                yield self.emit(ctx, call, "atan(0, 0) is undefined", severity="error")
            elif name == "atan" and _both_zero(a, b):
                message = (
                    f"atan({text(ctx, args[0], 24)}, {text(ctx, args[1], 24)}): both may be 0 "
                    f"(ranges {a.range.describe()} and {b.range.describe()}); atan(0, 0) is "
                    "undefined"
                )
                yield self.emit(ctx, call, message)


def _both_zero(a: Value, b: Value) -> bool:
    # Only bounded coordinates that reach 0 on evidence: polar angles of screen positions
    # (uv - 0.5) meet (0, 0) at most at one pixel centre, and sin and cos of one angle never
    # vanish together, so those are left alone.
    trig = {"sin", "cos"}
    return all(reaches_zero(v) and v.range.is_bounded and v.origin not in trig for v in (a, b))


@register
class ClampInverted(NumericalRule):
    """Finds `clamp(x, lo, hi)` whose bounds are constants with lo > hi.

    Why it matters: GLSL leaves clamp undefined when minVal > maxVal; GPUs compute
    min(max(x, lo), hi), which is the constant hi whatever x is. The bounds were almost
    certainly written the wrong way round.

    Example:
        float v = clamp(x, 1.0, 0.0);

    Fix:
        float v = clamp(x, 0.0, 1.0);
    """

    code = "N008"
    name = "clamp-inverted"
    severity = "error"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, _ in builtin_calls(ctx, model, "clamp"):
            args = call_args(call)
            if len(args) != 3:
                continue
            lo, hi = model.range_of(args[1]), model.range_of(args[2])
            if lo.lo > hi.hi:
                message = (
                    f"clamp bounds are inverted: {text(ctx, args[1], 24)} > "
                    f"{text(ctx, args[2], 24)}; the result is always the upper bound (undefined "
                    "in GLSL); swap them"
                )
                yield self.emit(ctx, call, message)


@register
class SmoothstepInverted(NumericalRule):
    """Finds `smoothstep(e0, e1, x)` whose edges are constants with e0 >= e1.

    Why it matters: GLSL leaves smoothstep undefined when edge0 >= edge1. Most GPUs evaluate
    the usual formula and give a reversed ramp, but not all, and e0 == e1 divides by zero.
    A reversed ramp is written 1.0 - smoothstep(e1, e0, x).

    Example:
        float fade = smoothstep(1.0, 0.0, d);

    Fix:
        float fade = 1.0 - smoothstep(0.0, 1.0, d);
    """

    code = "N009"
    name = "smoothstep-inverted"
    severity = "error"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, _ in builtin_calls(ctx, model, "smoothstep"):
            args = call_args(call)
            if len(args) != 3:
                continue
            e0, e1 = model.range_of(args[0]), model.range_of(args[1])
            if e0.lo < e1.hi:
                continue
            a, b, x = (ctx.node_text(n).strip() for n in args)
            fix = None
            if e0.lo > e1.hi:  # strictly reversed: the mirrored ramp is the same curve
                edit = ctx.replace(call, f"(1.0 - smoothstep({b}, {a}, {x}))")
                fix = Fix("write the reversed ramp as 1.0 - smoothstep", (edit,)) if edit else None
                advice = f"write 1.0 - smoothstep({text(ctx, args[1], 24)}, " + (
                    f"{text(ctx, args[0], 24)}, ...)"
                )
            else:
                advice = "the edges are equal: use step() or separate them"
            message = (
                f"smoothstep edges {text(ctx, args[0], 24)} >= {text(ctx, args[1], 24)} are "
                f"undefined in GLSL; {advice}"
            )
            yield self.emit(ctx, call, message, fix)
