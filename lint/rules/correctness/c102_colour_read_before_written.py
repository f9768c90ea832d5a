"""C102 colour-read-before-written."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.flow import function_flows, mask_names
from ...context import LintContext
from ...finding import Finding
from .. import Rule, register
from ._data_flow import main_colour

_ALPHA = 1 << 3  # the missing mask of a read that lacks only `.w`


@register
class ColourReadBeforeWritten(Rule):
    """Finds mainImage's `out` colour read before it is written, such as `fragColor.rgb *= 0.5;` or
    `fragColor += ...` as the first use, or passed to an `inout` parameter that reads it (the
    message names the components the callee reads before writing them). The clearing idioms
    `O -= O`, `O *= 0.` and `o = o*0. - d` are writes, and a read that only misses the alpha is
    not reported (ShaderToy never shows the Image pass's alpha).

    Why is this bad?
        An `out` parameter starts undefined, not as ShaderToy's black; reading it gives whatever the
        driver leaves there, so the result differs between GPUs.

    Example:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            fragColor.rgb += vec3(0.5);
            fragColor.a = 1.0;
        }

    Use instead:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            fragColor = vec4(0.0);
            fragColor.rgb += vec3(0.5);
            fragColor.a = 1.0;
        }

    Fix safety:
        No fix: the starting value (black, transparent, something else) is the author's choice.

    References:
        - GLSL ES 3.00 spec §6.1.1 (Function Calling Conventions: `out` parameters are not copied
          in)
    """

    code = "C102"
    name = "colour-read-before-written"
    default = False  # fewer than 15 findings on the corpus (6 of 7 worth)
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for flow in function_flows(ctx):
            colour = main_colour(flow)
            for read in flow.reads:
                if read.var is colour and read.missing != _ALPHA:
                    what = f"`{read.var.name}{mask_names(read.var, read.missing)}`"
                    message = (
                        f"{what} is read before mainImage writes it; out parameters start undefined"
                    )
                    yield self.report(ctx, read.node, message)
