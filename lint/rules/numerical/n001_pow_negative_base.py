"""N001 pow-negative-base."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.model import semantic_model
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


@register
class PowNegativeBase(NumericalRule):
    """Finds `pow(x, y)` whose base may be negative, such as an unclamped dot product.

    Why is this bad?
        GLSL leaves pow undefined for x < 0; GPUs return NaN or garbage there, and one NaN in a
        specular term turns the pixel black or spreads through a blur. N·H is negative on every
        surface facing away from the half vector.

    Example:
        float spec = pow(dot(N, H), shininess);

    Use instead:
        float spec = pow(max(dot(N, H), 0.0), shininess);

    Fix safety:
        Unsafe: clamping the base at 0 changes the result wherever it was negative; that was
        undefined before, but the author may have meant abs(x) or a sign-preserving power.

    References:
        - GLSL ES 3.00 spec §8.2 (Exponential Functions): pow is undefined for x < 0, and for x = 0
          with y <= 0
        - Khronos reference page: https://registry.khronos.org/OpenGL-Refpages/es3/html/pow.xhtml
    """

    code = "N001"
    name = "pow-negative-base"
    default = False  # opt-in: few of its sampled findings on real shaders are worth acting on
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, _ in builtin_calls(ctx, "pow"):
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
