"""N008 clamp-inverted."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.model import call_args, semantic_model
from ...context import LintContext
from ...finding import Finding
from .. import register
from ._common import NumericalRule, builtin_calls, text


@register
class ClampInverted(NumericalRule):
    """Finds `clamp(x, lo, hi)` whose bounds are constants with lo > hi.

    Why is this bad?
        GLSL leaves clamp undefined when minVal > maxVal; GPUs compute min(max(x, lo), hi), which is
        the constant hi whatever x is. The bounds were almost certainly written the wrong way round.

    Example:
        float v = clamp(x, 1.0, 0.0);

    Use instead:
        float v = clamp(x, 0.0, 1.0);

    Fix safety:
        No fix: swapping the bounds changes the result from a constant to x, which is almost
        certainly meant but is a change of value.

    References:
        - GLSL ES 3.00 spec §8.3 (Common Functions): clamp is undefined if minVal > maxVal
        - Khronos reference page: https://registry.khronos.org/OpenGL-Refpages/es3/html/clamp.xhtml
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
