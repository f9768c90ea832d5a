"""C104 out-parameter-read-before-written."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.flow import function_flows, mask_names
from ...context import LintContext
from ...finding import Finding
from .. import Rule, register
from ._data_flow import by_variable, main_colour


@register
class OutParameterReadBeforeWritten(Rule):
    """Finds an `out` parameter that a function reads before it writes it (`itrc++` or `t += d`
    on an `out float`, passing it to an `in` parameter), on some path. One finding per parameter,
    at its first such read. mainImage's colour is C102's.

    Why is this bad?
        An `out` parameter is not copied in: it starts undefined, whatever the caller put in the
        argument. A counter or accumulator passed as `out` counts from garbage on some GPUs.

    Example:
        float march(vec3 ro, vec3 rd, out float steps) {
            float t = 0.0;
            for (int i = 0; i < 64; i++) { steps++; t += map(ro + rd * t); }
            return t;
        }

    Use instead:
        float march(vec3 ro, vec3 rd, out float steps) {
            float t = 0.0;
            steps = 0.0;
            for (int i = 0; i < 64; i++) { steps++; t += map(ro + rd * t); }
            return t;
        }

    Fix safety:
        No fix: write a start value first, or declare the parameter `inout` when the caller's value
        is meant to come in.

    References:
        - GLSL ES 3.00 spec §6.1.1 (Function Calling Conventions: `out` parameters are not copied
          in)
    """

    code = "C104"
    name = "out-parameter-read-before-written"
    default = False  # fewer than 15 judged findings on the corpus
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for flow in function_flows(ctx):
            colour = main_colour(flow)
            reads = [r for r in flow.reads if r.var.kind == "out" and r.var is not colour]
            for group in by_variable([r for r in reads if not r.correlated]).values():
                read = group[0]
                var = read.var
                missing = 0
                for other in group:
                    missing |= other.missing
                what = f"`{var.name}{mask_names(var, missing)}`"
                message = (
                    f"out parameter {what} is read here before {flow.name} writes it: out "
                    "parameters are not copied in, so it starts undefined whatever the caller "
                    f"passed; write a start value first, or declare it `inout`"
                )
                yield self.report(ctx, read.node, message)
