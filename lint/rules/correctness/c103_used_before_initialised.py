"""C103 used-before-initialised."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.flow import function_flows, mask_names
from ...context import LintContext
from ...finding import Finding
from .. import Rule, register
from ._data_flow import main_colour


@register
class UsedBeforeInitialised(Rule):
    """Finds a local variable read before it is given a value on some path (declared without an
    initialiser, assigned only in one branch or in a loop that may not run), and an `out` parameter
    read before the function writes it.

    Why is this bad?
        GLSL does not zero local variables. An uninitialised value is whatever the register held, so
        the shader looks right on one GPU and flickers on another.

    Example:
        float d;
        if (hit) d = t;
        col *= exp(-d);

    Use instead:
        float d = 1e10;
        if (hit) d = t;
        col *= exp(-d);

    Fix safety:
        No fix: the right initial value depends on what the variable means.

    References:
        - GLSL ES 3.00 spec §6.1.1 (Function Calling Conventions: `out` parameters are not copied
          in)
        - CWE-457, Use of Uninitialized Variable
    """

    code = "C103"
    name = "used-before-initialised"
    default = False  # below 90% worth acting on in the labelled corpus sample
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for flow in function_flows(ctx):
            colour = main_colour(flow)
            for read in flow.reads:
                var = read.var
                if var is colour:
                    continue
                what = f"`{var.name}{mask_names(var, read.missing)}`"
                if var.kind == "out":
                    message = (
                        f"out parameter {what} is read before {flow.name} writes it; "
                        "out parameters start undefined (use `inout` to pass a value in)"
                    )
                else:
                    line = ctx.span(var.token)[0]
                    message = (
                        f"{what} may be read before it is given a value (declared without "
                        f"one on line {line}); GLSL does not zero local variables"
                    )
                yield self.report(ctx, read.node, message)
