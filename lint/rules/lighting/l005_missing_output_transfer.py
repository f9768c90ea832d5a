"""L005 missing-output-transfer."""

from __future__ import annotations

from collections.abc import Iterator

from ...context import LintContext
from ...finding import Finding
from .. import Rule, register
from ._common import ColourOutput, main_image, output_writes
from ._terms import (
    mentions_normal,
)


@register
class MissingOutputTransfer(Rule):
    """Finds a lit shader that writes linear colour to the output without a gamma or sRGB encoding
    anywhere.

    A shader counts as lit when it takes a dot product with a normal (2D art and image effects are
    left alone: their colours are already display values). An encoding is a pow by an exponent of
    0.38 to 0.5 (1/2.2, 0.4545, 1/2.4), a pow by something named gamma, a sqrt of a colour (gamma
    2), or a function named like gamma/sRGB/outputTransfer; anywhere in the shader counts, since
    where it sits is for L006 to judge. A buffer pass that hands linear colour to the Image pass is
    correct without an encoding: suppress L005 there (`// glint: file-ignore[L005, L007]`).

    Why is this bad?
        Lighting is computed in linear units, but the display expects sRGB-encoded values; without
        the encoding midtones come out far too dark and the falloff of light looks harsh. ShaderToy
        does not encode for you.

    Example:
        col = albedo * max(dot(n, l), 0.0);
        fragColor = vec4(col, 1.0);

    Use instead:
        col = albedo * max(dot(n, l), 0.0);
        fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);

    Fix safety:
        No fix: where the encoding belongs (after a tone map, before dithering) is the author's
        choice.

    References:
        - IEC 61966-2-1:1999, the sRGB colour space
        - Gritz and d'Eon, "The Importance of Being Linear", GPU Gems 3, ch. 24, 2007
    """

    code = "L005"
    name = "missing-output-transfer"
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        found = main_image(ctx)
        if found is None or not mentions_normal(ctx) or ColourOutput(ctx).any_gamma():
            return
        fn, out = found
        writes = output_writes(fn, out)
        if writes:
            yield self.report(
                ctx,
                writes[-1],
                f"lit colour reaches `{out}` without a gamma/sRGB encoding: apply "
                "pow(col, vec3(1.0 / 2.2)) (or an sRGB curve) before writing it",
            )
