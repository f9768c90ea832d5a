"""N009 smoothstep-inverted."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from ...analysis.model import Model, semantic_model
from ...analysis.ranges import Interval
from ...analysis.syntax import call_args
from ...context import LintContext
from ...finding import Finding, Fix
from .. import register
from ._common import Node, NumericalRule, builtin_calls, text


@register
class SmoothstepInverted(NumericalRule):
    """Finds `smoothstep(e0, e1, x)` whose edges are reversed (e0 > e1 for every value) or equal
    (both the same constant).

    Both are warnings, not errors (an error is code that does not compile or is wrong on every
    run). Equal edges: smoothstep(e, e, x) divides by zero; GPUs give a step at e (some authors
    use it as one), and 0/0 = NaN where x == e exactly. Reversed edges are a portability note:
    GLSL leaves them undefined, but every GPU and ShaderToy runner evaluates the usual formula
    and draws the mirrored ramp, the same image on every run; authors write
    `smoothstep(aa, 0.0, d)` on purpose as an anti-aliased mask. The rewrite below is defined
    everywhere and draws the same curve.
    Edges are called equal only when both are the same constant: a positive width such as
    `2.0 / iResolution.y` or `fwidth(d)` against 0.0 is a reversed ramp, not a step.

    Why is this bad?
        GLSL leaves smoothstep undefined when edge0 >= edge1. Today's GPUs give a reversed ramp
        for e0 > e1, but a conforming implementation need not, and e0 == e1 divides by zero. A
        reversed ramp is written 1.0 - smoothstep(e1, e0, x).

    Example:
        float fade = smoothstep(1.0, 0.0, d);

    Use instead:
        float fade = 1.0 - smoothstep(0.0, 1.0, d);

    Fix safety:
        Safe: for edges strictly reversed, 1.0 - smoothstep(e1, e0, x) is the same curve the usual
        formula gives (the Hermite ramp is symmetric: s(1 - t) = 1 - s(t)), now defined. Equal edges
        have no such rewrite and are not fixed.

    References:
        - GLSL ES 3.00 spec §8.3 (Common Functions): smoothstep is undefined if edge0 >= edge1
        - Khronos reference page:
          https://registry.khronos.org/OpenGL-Refpages/es3/html/smoothstep.xhtml
    """

    code = "N009"
    name = "smoothstep-inverted"
    certainty = "certain"
    default = False  # opt-in: few of its sampled findings on real shaders are worth acting on
    severity = "warning"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, _ in builtin_calls(ctx, "smoothstep"):
            args = call_args(call)
            if len(args) != 3:
                continue
            e0, e1 = model.range_of(args[0]), model.range_of(args[1])
            if e0.lo < e1.hi:
                continue
            a, b, x = (ctx.node_text(n).strip() for n in args)
            shown0, shown1 = _edge(ctx, model, args[0], e0), _edge(ctx, model, args[1], e1)
            if e0.is_point and e1.is_point and e0.lo == e1.lo:
                message = (
                    f"smoothstep edges {shown0} and {shown1} are equal: it divides by zero (NaN "
                    "at x == edge) and is a step elsewhere; use step() or separate them"
                )
                yield self.emit(ctx, call, message)
                continue
            edit = ctx.replace(call, f"(1.0 - smoothstep({b}, {a}, {x}))")
            fix = Fix("write the reversed ramp as 1.0 - smoothstep", (edit,)) if edit else None
            message = (
                f"smoothstep edges are reversed ({shown0} >= {shown1}): undefined in GLSL, though "
                "today's GPUs draw the mirrored ramp; for portability write "
                f"1.0 - smoothstep({text(ctx, args[1], 24)}, {text(ctx, args[0], 24)}, ...)"
            )
            yield self.emit(ctx, call, message, fix)


def _edge(ctx: LintContext, model: Model, node: Node, r: Interval) -> str:
    """An edge for the message: its value when constant (a macro's expansion says little)."""
    if r.is_point and isinstance(node, Tree) and node.data not in ("float_literal", "int_literal"):
        return f"{text(ctx, node, 24)} = {r.lo:g}"
    return text(ctx, node, 24)
