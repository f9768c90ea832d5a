"""N010 value-passed-as-bound."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.constants import is_compile_time
from ...analysis.functions import function_at, functions
from ...analysis.model import semantic_model
from ...analysis.syntax import call_args
from ...context import LintContext, Node
from ...finding import Finding
from .. import register
from ._common import NumericalRule, builtin_calls, text


@register
class ValuePassedAsBound(NumericalRule):
    """Finds `clamp` and `smoothstep` calls whose value argument is a constant while one of the
    bounds (edges) varies: the arguments are in the wrong order, the value passed where a bound
    belongs, as in `clamp(0.2, 0.5, v)` or `smoothstep(d, 0.0, 0.01)`.

    The value is clamp's first argument and smoothstep's last. Clamping or smoothing a constant
    between one constant and one varying bound is not something anyone means: `clamp(0.2, 0.5,
    v)` is `min(0.5, v)`, unclamped below, and `smoothstep(d, 0.0, 0.01)` has reversed edges
    whenever d > 0, undefined in GLSL. Calls with both bounds varying, or the value varying, are
    not reported: the reversed-edge idiom `smoothstep(0.01, 0.0, d)` passes the value last as it
    should. Bounds inverted over their whole ranges are N008's (clamp-inverted).

    Why is this bad?
        The call does not limit the value at all: clamp(0.2, 0.5, v) returns v wherever v < 0.5,
        including below 0.2 and below zero; smoothstep(d, 0.0, 0.01) ramps the wrong way and is
        undefined for every d > 0.

    Example:
        float w = clamp(0.2, 0.5, 0.5 - z * 0.01);
        float m = smoothstep(length(uv), 0.0, 0.01);

    Use instead:
        float w = clamp(0.5 - z * 0.01, 0.2, 0.5);
        float m = smoothstep(0.0, 0.01, length(uv));

    Fix safety:
        No fix: reordering the arguments changes the value wherever the call misbehaved, which is
        the point, but the author must confirm which order was meant.

    References:
        - GLSL ES 3.00 spec §8.3 (Common Functions): clamp(x, minVal, maxVal) and
          smoothstep(edge0, edge1, x)
    """

    code = "N010"
    name = "value-passed-as-bound"
    certainty = "certain"
    default = False  # opt-in: fewer than 15 findings on the corpus to judge it by
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        fns = functions(ctx)
        for call, name in builtin_calls(ctx, "clamp", "smoothstep"):
            args = call_args(call)
            if len(args) != 3:
                continue
            fn = function_at(fns, call)
            value, bounds = (args[0], args[1:]) if name == "clamp" else (args[2], args[:2])
            if not is_compile_time(ctx, value, fn):
                continue
            fixed = [is_compile_time(ctx, b, fn) for b in bounds]
            if fixed.count(True) != 1:
                continue
            moving = bounds[fixed.index(False)]
            model = semantic_model(ctx)
            if model.range_of(moving).is_point:
                continue  # a value the model knows exactly: constant after all
            lo, hi = (model.range_of(b) for b in bounds)
            if name == "clamp" and lo.lo >= hi.hi:
                continue  # N008 reports it: the bounds are inverted whatever the order
            yield self.emit(ctx, call, _message(ctx, name, args, moving, fixed))


def _message(ctx: LintContext, name: str, args: list[Node], moving: Node, fixed: list[bool]) -> str:
    shown = [text(ctx, a, 32) for a in args]
    call = f"{name}({', '.join(shown)})"
    v = text(ctx, moving, 32)
    if name == "clamp":
        constants = [shown[0], shown[2 if fixed[1] else 1]]
        intended = f"clamp({v}, {', '.join(sorted(constants, key=_number))})"
        role = "upper" if not fixed[1] else "lower"
        effect = (
            f"the result follows {v} wherever it is below the larger constant, unclamped"
            if role == "upper"
            else f"the result follows {v} wherever it is above the constant, unclamped"
        )
        return (
            f"{call}: clamp takes the value first, but the value here is the constant "
            f"{shown[0]} and {v} is passed as the {role} bound; {effect}; write {intended}"
        )
    constants = [shown[2], shown[1 if fixed[1] else 0]]
    intended = f"smoothstep({', '.join(sorted(constants, key=_number))}, {v})"
    return (
        f"{call}: smoothstep takes the value last, but the value here is the constant "
        f"{shown[2]} and {v} is passed as an edge; the edges are reversed or equal wherever "
        f"{v} passes the other edge (undefined in GLSL); write {intended}"
    )


def _number(shown: str) -> float:
    """Sort key: a literal's value, so the constants come out low first (names keep order)."""
    try:
        return float(shown.rstrip("fF"))
    except ValueError:
        return 0.0
