"""L006 double-gamma."""

from __future__ import annotations

from collections.abc import Iterator

from glint.compiler.glsl.ast import Assignment, Declarator

from ...analysis.functions import functions
from ...analysis.syntax import calls_in, names_in, root_var
from ...context import LintContext, Node, walk_kind
from ...finding import Finding
from .. import Rule, register
from ._common import ColourOutput, main_image, short_text


@register
class DoubleGamma(Rule):
    """Finds a display encoding (gamma or sRGB) applied to colour that is already encoded.

    Traced in source order through mainImage: a variable assigned an encoded value stays encoded
    while it is reassigned from itself; encoding it again (directly, or through a function whose
    result is an encoded value) is reported, as is an encoding nested in another anywhere. Branches
    are not told apart. An encoding is what L005 takes for one, on a colour (a vec3 or vec4, not a
    vec2 or a float mask), with an exponent in the encoding window: a lift/gamma/gain grade such
    as `pow(col, 1.0 - uGamma)` with a value of 1.25 is not one.

    Why is this bad?
        Encoding twice is gamma 4.84 instead of 2.2: the image looks washed out and flat, with
        lifted blacks. It typically happens when a helper encodes and mainImage encodes again.

    Example:
        col = pow(col, vec3(0.4545));
        fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);

    Use instead:
        fragColor = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);

    Fix safety:
        No fix: which of the two encodings to keep is the author's choice.

    References:
        - IEC 61966-2-1:1999, the sRGB colour space
        - Gritz and d'Eon, "The Importance of Being Linear", GPU Gems 3, ch. 24, 2007
    """

    code = "L006"
    name = "double-gamma"
    default = False  # opt-in: no finding on the corpus, so no measured precision
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        output = ColourOutput(ctx)
        reported: set[int] = set()
        for fn in functions(ctx):
            for node in calls_in(fn.body):
                inner = output.gamma_of(node, fn)
                if inner is not None and any(
                    output.gamma_of(n, fn) is not None for n in calls_in(inner)
                ) and id(node) not in reported:  # fmt: skip
                    reported.add(id(node))
                    yield self._finding(ctx, node)
        found = main_image(ctx)
        if found is None:
            return
        fn, _ = found
        encoded: set[str] = set()
        for node in walk_kind(fn.body, "declarator", "assignment"):
            if node.data == "declarator":
                declarator = Declarator(node)
                init = declarator.initializer
                if init is None:
                    continue
                target, value = declarator.name, init
            else:
                assignment = Assignment(node)
                if assignment.op != "=":
                    continue
                target, value = root_var(assignment.target) or "", assignment.value
            for call in calls_in(value):
                inner = output.gamma_of(call, fn)
                if inner is not None and names_in(inner) & encoded and id(call) not in reported:
                    reported.add(id(call))
                    yield self._finding(ctx, call)
            top = output._peel(value)
            if output.gamma_of(top, fn) is not None or names_in(value) & encoded:
                encoded.add(target)
            else:
                encoded.discard(target)

    def _finding(self, ctx: LintContext, node: Node) -> Finding:
        return self.report(
            ctx,
            node,
            f"`{short_text(ctx, node)}` encodes for the display a colour that is already encoded "
            "(gamma applied twice)",
        )
