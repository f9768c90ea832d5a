"""N002 sqrt-log-domain."""

from __future__ import annotations

import math
from collections.abc import Iterator

from ...analysis.model import semantic_model
from ...analysis.ranges import Interval
from ...analysis.syntax import call_args
from ...context import LintContext
from ...finding import Finding
from .. import register
from ._common import (
    NumericalRule,
    builtin_calls,
    is_raw_dot,
    range_note,
    reaches_below,
    text,
    wrap_fix,
)

LOG_FLOOR = "1e-6"  # log(0) is -inf, so the floor for log must be above zero


@register
class SqrtLogDomain(NumericalRule):
    """Finds `sqrt` or `inversesqrt` of a value that may be negative, and `log`/`log2` of a value
    that may be zero or negative.

    Why is this bad?
        Outside their domain these are undefined in GLSL and give NaN (or -inf for log(0)) on real
        GPUs; `1.0 - x * x` goes slightly negative by rounding even when x is a cosine, and a dot
        product is negative half the time.

    Example:
        float d = sqrt(dot(N, L));

    Use instead:
        float d = sqrt(max(dot(N, L), 0.0));

    Fix safety:
        Unsafe: the inserted floor (0.0 for sqrt, 1e-6 for log) changes the result wherever the
        argument was below it, and a value far below zero usually means a bug elsewhere.

    References:
        - GLSL ES 3.00 spec §8.2 (Exponential Functions): sqrt undefined for x < 0, inversesqrt for
          x <= 0, log and log2 for x <= 0
        - Khronos reference pages: sqrt, inversesqrt, log, log2
    """

    code = "N002"
    name = "sqrt-log-domain"
    certainty = "possible"
    default = False  # opt-in: few of its sampled findings on real shaders are worth acting on
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        names = ("sqrt", "inversesqrt", "log", "log2")
        for call, name in builtin_calls(ctx, *names):
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
