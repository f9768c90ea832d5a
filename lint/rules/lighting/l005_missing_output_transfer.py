"""L005 missing-output-transfer."""

from __future__ import annotations

from collections.abc import Iterator

from ...context import LintContext
from ...finding import Finding
from .. import Rule, register
from ._common import ColourOutput, data_output, main_image, output_writes
from ._terms import lights_surface


@register
class MissingOutputTransfer(Rule):
    """Finds a lit shader that writes linear colour to the output without a gamma or sRGB encoding
    anywhere.

    A shader counts as lit when it shades a 3D surface: a dot of two vec3, a normal with a light,
    view or half vector (by role or a light-like name), in code mainImage runs, whose value
    reaches the colour (a term computed and never used does not count). 2D art, hashes of an
    argument named n and ray-plane intersections are left alone. Any output curve the author
    chose counts: an encoding (a pow by 0.38 to 0.5, a sqrt of a colour, a function named like
    gamma/sRGB/outputTransfer), a pow of a colour by a constant in (0, 1), or a pow by an exponent
    named gamma as written (`#define GAMMA 1.3`); anywhere in the shader, since where it sits is
    for L006 to judge. Output that is data for another pass is left alone: a non-constant alpha,
    a texel that stores state, a normal packed as n * 0.5 + 0.5, radiance of 10 or more with no
    tone map, or a palette of constant colours. Other buffer passes that hand linear colour to the
    Image pass: suppress L005 there (`// glint: file-ignore[L005, L007]`).

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
    default = False  # opt-in: few of its sampled findings on real shaders are worth acting on

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        found = main_image(ctx)
        if found is None or not lights_surface(ctx) or ColourOutput(ctx).any_curve():
            return
        if data_output(ctx):
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
