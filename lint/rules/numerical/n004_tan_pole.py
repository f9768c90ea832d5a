"""N004 tan-pole."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.model import semantic_model
from ...analysis.ranges import reaches_tan_pole
from ...analysis.syntax import call_args
from ...context import LintContext
from ...finding import Finding
from .. import register
from ._common import NumericalRule, builtin_calls, text


@register
class TanPole(NumericalRule):
    """Finds `tan(x)` where the range of x reaches a pole, π/2 + kπ.

    Why is this bad?
        tan grows without bound near its poles and flips sign across them; a field of view or an
        animated angle that reaches π/2 gives infinities and a picture that tears or goes black.

    Example:
        float k = tan(iTime);

    Use instead:
        float k = tan(clamp(angle, -1.5, 1.5));   // keep away from ±π/2

    Fix safety:
        No fix: the range the angle should stay in is the author's choice.

    References:
        - GLSL ES 3.00 spec §8.1 (Angle and Trigonometry Functions)
        - Khronos reference page: https://registry.khronos.org/OpenGL-Refpages/es3/html/tan.xhtml
    """

    code = "N004"
    name = "tan-pole"
    default = False  # opt-in: no finding on the corpus, so no measured precision
    certainty = "possible"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for call, _ in builtin_calls(ctx, "tan"):
            args = call_args(call)
            if len(args) != 1:
                continue
            r = semantic_model(ctx).range_of(args[0])  # built for the first tan only
            if reaches_tan_pole(r):
                message = (
                    f"tan of {text(ctx, args[0])} reaches a pole at π/2 + kπ "
                    f"(range {r.describe()}); keep the angle inside (-π/2, π/2)"
                )
                yield self.emit(ctx, args[0], message)
