"""N008 clamp-inverted."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.constants import const_value
from ...analysis.model import semantic_model
from ...analysis.syntax import call_args
from ...context import LintContext, Node
from ...finding import Finding
from .. import register
from ._common import NumericalRule, builtin_calls, text


@register
class ClampInverted(NumericalRule):
    """Finds `clamp(x, lo, hi)` whose lower bound is at or above the upper bound over their whole
    ranges: constants written the wrong way round (`clamp(x, 1.0, 0.0)`), or the arguments in the
    wrong order (`clamp(0.0, 1.0, v)`, the value passed where a bound belongs).

    Constant bounds with lo > hi are an error: the result is the constant upper bound whatever x
    is, on every run and every GPU. Anything else is a warning: with `clamp(0.0, 1.0, v)` and v in
    [-1, 1] the result is always the third argument, v itself, unclamped: wrong wherever v leaves
    [0, 1], right where it does not.

    Why is this bad?
        GLSL leaves clamp undefined when minVal > maxVal; GPUs compute min(max(x, lo), hi), which is
        hi whatever x is. The bounds were almost certainly written the wrong way round, or the
        value was passed last (clamp takes the value first).

    Example:
        float v = clamp(x, 1.0, 0.0);
        float w = clamp(0.0, 1.0, s);

    Use instead:
        float v = clamp(x, 0.0, 1.0);
        float w = clamp(s, 0.0, 1.0);

    Fix safety:
        No fix: swapping the bounds changes the result from a constant to x, which is almost
        certainly meant but is a change of value.

    References:
        - GLSL ES 3.00 spec §8.3 (Common Functions): clamp is undefined if minVal > maxVal
        - Khronos reference page: https://registry.khronos.org/OpenGL-Refpages/es3/html/clamp.xhtml
    """

    code = "N008"
    name = "clamp-inverted"
    default = False  # opt-in: no finding on the corpus, so no measured precision
    certainty = "certain"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for call, _ in builtin_calls(ctx, "clamp"):
            args = call_args(call)
            if len(args) != 3 or _literal_order(args[1], args[2]):
                continue
            model = semantic_model(ctx)  # built for the first clamp that needs ranges
            x = model.range_of(args[0])
            lo, hi = model.range_of(args[1]), model.range_of(args[2])
            if not lo.lo >= hi.hi:  # lo >= hi for every value of both
                continue
            if lo.is_point and lo == hi:  # clamp(x, 1.0, 1.0): a constant, written on purpose
                continue
            shown = [text(ctx, a, 24) for a in args]
            if lo.is_point and hi.is_point and lo.lo > hi.lo:
                message = (
                    f"clamp bounds are inverted: {shown[1]} > {shown[2]}; the result is always "
                    "the upper bound (undefined in GLSL); swap them"
                )
                # a warning, not an error: the code compiles and GPUs compute min(max(x, lo),
                # hi); 5 of 6 such clamps in real shaders were constants tuned by eye
                yield self.emit(ctx, call, message)
            elif x.is_point:
                message = (
                    f"clamp({shown[0]}, {shown[1]}, {shown[2]}): the arguments look swapped "
                    f"(clamp takes the value first): the lower bound {shown[1]} is never below "
                    f"the upper bound {shown[2]}, so the result is always {shown[2]}, unclamped; "
                    f"write clamp({shown[2]}, {shown[0]}, {shown[1]})"
                )
                yield self.emit(ctx, call, message)
            else:
                message = (
                    f"clamp bounds are inverted: {shown[1]} >= {shown[2]} for every value "
                    f"(ranges {lo.describe()} and {hi.describe()}); the result is always the upper "
                    "bound (undefined in GLSL where lo > hi)"
                )
                yield self.emit(ctx, call, message)


def _literal_order(lo: Node, hi: Node) -> bool:
    """Whether both bounds are literal values (`0.0`, `-1.`, `vec3(1.0)`, `2.0 / 50.0`) with
    lo < hi: the usual clamp(x, 0.0, 1.0) is in order without asking the semantic model, which
    is expensive. Named constants are not folded: a local may shadow a global's name."""
    a, b = const_value(lo), const_value(hi)
    return a is not None and b is not None and a < b
