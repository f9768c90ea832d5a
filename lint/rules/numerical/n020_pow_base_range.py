"""N020 pow-base-range."""

from __future__ import annotations

from collections.abc import Iterator

from ...context import LintContext
from ...finding import Finding
from .. import register
from ._common import NumericalRule, range_note, text, wrap_fix
from ._pow import negative_evidence, pow_bases, range_reaches_negative


@register
class PowBaseRange(NumericalRule):
    """Finds `pow(x, y)` whose base may be negative by the range the model computes, without a
    named input where it is (those are N001): a sum whose lower bound is below 0, a variable
    assigned from several such terms.

    Interval arithmetic treats every occurrence of a variable as independent, so a range that
    reaches below 0 may be an artefact: `col * 0.7 + col * col * 0.3` for col in [0, 1] is never
    negative. Read each finding: clamp the base where the value can really go negative.

    Why is this bad?
        GLSL leaves pow undefined for x < 0; GPUs return NaN there, and one NaN in a colour
        spreads through a blur or turns the pixel black.

    Example:
        float fog = pow(0.5 - 0.5 * q.z, 2.0);  // q.z in [-5, 5]

    Use instead:
        float fog = pow(max(0.5 - 0.5 * q.z, 0.0), 2.0);

    Fix safety:
        Unsafe: clamping the base at 0 changes the result wherever it was negative; that was
        undefined before, but the author may have meant abs(x) or a sign-preserving power.

    References:
        - GLSL ES 3.00 spec §8.2 (Exponential Functions): pow is undefined for x < 0
        - Khronos reference page: https://registry.khronos.org/OpenGL-Refpages/es3/html/pow.xhtml
    """

    code = "N020"
    name = "pow-base-range"
    certainty = "possible"
    default = False  # opt-in: a range alone is no evidence that the value is reached
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for _, base_node, base in pow_bases(ctx):
            if not range_reaches_negative(base) or negative_evidence(base) is not None:
                continue
            shown = text(ctx, base_node)
            note = range_note(base, "an unclamped dot product takes either sign")
            message = f"pow base {shown} may be negative ({note}); clamp it: max({shown}, 0.0)"
            fix = wrap_fix(ctx, base_node, "max({}, 0.0)", "clamp the base at 0")
            yield self.emit(ctx, base_node, message, fix)
