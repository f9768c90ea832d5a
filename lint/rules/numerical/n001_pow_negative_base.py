"""N001 pow-negative-base."""

from __future__ import annotations

from collections.abc import Iterator

from ...context import LintContext
from ...finding import Finding
from .. import register
from ._common import NumericalRule, text, wrap_fix
from ._pow import negative_evidence, never_negative, pow_bases


@register
class PowNegativeBase(NumericalRule):
    """Finds `pow(x, y)` whose base is negative at a reachable input: a base whose whole range
    is at or below 0 (`pow(clamp(t, 1.0, 3.0) - 3.0, 2.0)`), or one that is negative at a named
    input: the first frame (`pow(iTime - 1.0, 2.0)`, iTime = 0), the bottom-left pixel
    (`pow(fragCoord.y / iResolution.y - 0.5, 2.0)`; the y of a view ray `normalize(vec3(uv,
    1.0))`, which points down there; not after a camera matrix, whose world sign depends on
    where the camera looks), sin or cos of an unbounded argument (`pow(sin(iTime), 7.0)`, a
    colour channel `sin(iTime)` carried through a function's return and a product into
    `pow(col, vec3(0.4545))`), an unclamped dot product with a direction
    (`pow(dot(R, V), 32.0)`: negative where R faces away from V).

    A base that only reaches below 0 by interval arithmetic, without such an input, is N020
    (opt-in).

    Why is this bad?
        GLSL leaves pow undefined for x < 0; GPUs compute it as exp2(y * log2(x)) and return
        NaN there, even for y = 2.0 (only a compiler that rewrites pow(x, 2.0) as x * x hides
        it). One NaN in a specular term turns the pixel black or spreads through a blur.

    Example:
        float spec = pow(dot(R, V), 32.0);

    Use instead:
        float spec = pow(max(dot(R, V), 0.0), 32.0);

    Fix safety:
        Unsafe: clamping the base at 0 changes the result wherever it was negative; that was
        undefined before, but the author may have meant abs(x), x * x, or a sign-preserving
        power.

    References:
        - GLSL ES 3.00 spec §8.2 (Exponential Functions): pow is undefined for x < 0, and for x = 0
          with y <= 0
        - Khronos reference page: https://registry.khronos.org/OpenGL-Refpages/es3/html/pow.xhtml
    """

    code = "N001"
    name = "pow-negative-base"
    default = True  # judged on both corpora (lint/precision.py)
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        # a base that is plainly never negative has no evidence of a negative value to find
        for _, base_node, base in pow_bases(ctx, skip=never_negative):
            why = negative_evidence(base)
            if why is None:
                continue
            shown = text(ctx, base_node)
            message = (
                f"pow base {shown} {why}: pow is undefined there (NaN on most GPUs); "
                f"clamp it: pow(max({shown}, 0.0), ...), or use abs({shown}) for a curve "
                f"symmetric about 0, or write a square as a product"
            )
            fix = wrap_fix(ctx, base_node, "max({}, 0.0)", "clamp the base at 0")
            # never above 0: wrong for every input; a witness: wrong at the input it names
            sure = "certain" if why.startswith("is never above 0") else "likely"
            yield self.emit(ctx, base_node, message, fix, certainty=sure)
