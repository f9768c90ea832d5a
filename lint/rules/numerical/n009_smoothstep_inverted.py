"""N009 smoothstep-inverted."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.model import call_args, semantic_model
from ...context import LintContext
from ...finding import Finding, Fix
from .. import register
from ._common import NumericalRule, builtin_calls, text


@register
class SmoothstepInverted(NumericalRule):
    """Finds `smoothstep(e0, e1, x)` whose edges are constants with e0 >= e1.

    Why is this bad?
        GLSL leaves smoothstep undefined when edge0 >= edge1. Most GPUs evaluate the usual formula
        and give a reversed ramp, but not all, and e0 == e1 divides by zero. A reversed ramp is
        written 1.0 - smoothstep(e1, e0, x).

    Example:
        float fade = smoothstep(1.0, 0.0, d);

    Use instead:
        float fade = 1.0 - smoothstep(0.0, 1.0, d);

    Fix safety:
        Safe: for edges strictly reversed, 1.0 - smoothstep(e1, e0, x) is the same curve the usual
        formula gives (the Hermite ramp is symmetric: s(1 - t) = 1 - s(t)), now defined. Equal edges
        have no such rewrite and are not fixed.

    References:
        - GLSL ES 3.00 spec §8.3 (Common Functions): smoothstep is undefined if edge0 >= edge1
        - Khronos reference page:
          https://registry.khronos.org/OpenGL-Refpages/es3/html/smoothstep.xhtml
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
