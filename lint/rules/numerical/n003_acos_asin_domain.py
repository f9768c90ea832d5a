"""N003 acos-asin-domain."""

from __future__ import annotations

import math
from collections.abc import Iterator

from ...analysis.model import semantic_model
from ...analysis.ranges import Interval
from ...analysis.syntax import call_args
from ...context import LintContext
from ...finding import Finding
from .. import register
from ._common import SLACK, NumericalRule, builtin_calls, is_raw_dot, reaches_below, text, wrap_fix


def reaches_above(r: Interval, c: float) -> bool:
    return r.hi > c + SLACK and (r.hi < math.inf or r.lo >= c)


@register
class AcosAsinDomain(NumericalRule):
    """Finds `acos`/`asin` of a value that may leave [-1, 1], including an unclamped dot product of
    unit vectors.

    Why is this bad?
        acos and asin are undefined outside [-1, 1] and give NaN there. The dot product of two
        normalized vectors is mathematically within [-1, 1] but rounds to 1.0000001 for nearly
        parallel vectors, and the angle becomes NaN exactly where the vectors align.

    Example:
        float angle = acos(dot(a, b));

    Use instead:
        float angle = acos(clamp(dot(a, b), -1.0, 1.0));

    Fix safety:
        Unsafe: the clamp changes the result wherever the argument was outside [-1, 1]; for a
        rounding error that is the intent, for a value far outside it hides a bug.

    References:
        - GLSL ES 3.00 spec §8.1 (Angle and Trigonometry Functions): asin and acos are undefined for
          |x| > 1
        - Khronos reference pages: acos, asin
    """

    code = "N003"
    name = "acos-asin-domain"
    certainty = "possible"
    default = False  # opt-in: few of its sampled findings on real shaders are worth acting on
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, name in builtin_calls(ctx, "acos", "asin"):
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
