"""N007 mod-atan-zero."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.model import semantic_model
from ...analysis.ranges import Interval
from ...analysis.syntax import call_args
from ...analysis.values import Value
from ...context import LintContext
from ...finding import Finding
from .. import register
from ._common import NumericalRule, builtin_calls, reaches_zero, text


@register
class ModAtanZero(NumericalRule):
    """Finds `mod(x, 0)` and `atan(y, x)` whose two arguments may both be zero.

    A constant 0 divisor (`mod(x, 0.0)`) or `atan(0.0, 0.0)` is an error: the result is undefined
    on every run, whatever the inputs. Arguments that only may both be 0 are a warning: the
    value is undefined at those inputs only (often one pixel or one instant).

    Why is this bad?
        mod(x, 0) divides by zero and atan(0, 0) is undefined in GLSL; both give NaN or an arbitrary
        value that differs between GPUs. Polar coordinates of the origin are the usual way to reach
        atan(0, 0).

    Example:
        float m = mod(x, 0.0);

    Use instead:
        float m = mod(x, period);   // with period > 0

    Fix safety:
        No fix.

    References:
        - GLSL ES 3.00 spec §8.1 (atan(y, x) is undefined when x and y are both 0) and §8.3 (Common
          Functions: mod(x, y) is x - y * floor(x / y))
        - Khronos reference pages: atan, mod
    """

    code = "N007"
    name = "mod-atan-zero"
    certainty = "possible"
    default = False  # below 80% worth acting on in the labelled corpus sample
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        zero = Interval.point(0.0)
        for call, name in builtin_calls(ctx, "mod", "atan"):
            args = call_args(call)
            if len(args) != 2:
                continue
            a, b = (model.value_of(x) for x in args)
            if name == "mod" and b.range == zero:
                yield self.emit(
                    ctx, call, "mod by zero is undefined", severity="error", certainty="certain"
                )
            elif name == "atan" and a.range == zero and b.range == zero:
                yield self.emit(
                    ctx, call, "atan(0, 0) is undefined", severity="error", certainty="certain"
                )
            elif name == "atan" and _both_zero(a, b):
                message = (
                    f"atan({text(ctx, args[0], 24)}, {text(ctx, args[1], 24)}): both may be 0 "
                    f"(ranges {a.range.describe()} and {b.range.describe()}); atan(0, 0) is "
                    "undefined"
                )
                yield self.emit(ctx, call, message)


def _both_zero(a: Value, b: Value) -> bool:
    # Only bounded coordinates that reach 0 on evidence: polar angles of screen positions
    # (uv - 0.5) meet (0, 0) at most at one pixel centre, and sin and cos of one angle never
    # vanish together, so those are left alone.
    trig = {"sin", "cos"}
    return all(reaches_zero(v) and v.range.is_bounded and v.origin not in trig for v in (a, b))
