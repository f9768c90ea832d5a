"""N005 division-by-zero."""

from __future__ import annotations

from collections.abc import Iterator

from glint.compiler.glsl.types import components

from ...analysis.model import semantic_model
from ...context import LintContext, walk_kind
from ...finding import Finding, Fix
from .. import register
from ._common import Node, NumericalRule, divisor_of, reaches_zero, text, wrap_fix

EPSILON = "1e-4"  # the divisor floor N005's fix inserts


@register
class DivisionByZero(NumericalRule):
    """Finds a division by a value that can be zero: a dot product, a length or distance, a square,
    a clamped value that reaches 0, a constant 0, without an epsilon.

    Why is this bad?
        x / 0 is infinity (0 / 0 is NaN), which survives tone mapping as a white or black pixel and
        poisons everything it is mixed with. A length is 0 at the origin, N·L is 0 at the terminator
        and negative beyond it.

    Example:
        float atten = 1.0 / dot(d, d);

    Use instead:
        float atten = 1.0 / max(dot(d, d), 1e-4);

    Fix safety:
        Unsafe: the floor (1e-4) changes the result wherever the divisor was below it, not only at
        zero. It is offered only for float divisors that are never negative, where a floor keeps the
        sign.

    References:
        - GLSL ES 3.00 spec §4.5.1 (Range and Precision)
        - IEEE 754: x / 0 is ±infinity, 0 / 0 is NaN
    """

    code = "N005"
    name = "division-by-zero"
    certainty = "possible"
    default = False  # opt-in: few of its sampled findings on real shaders are worth acting on
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        # One finding per divisor on a line: `0.1 / d, 0.2 / d` is one defect (d may be 0),
        # with a fix that floors every occurrence.
        found: dict[tuple[int, str], tuple[Node, str, list[Node]]] = {}
        for node in walk_kind(ctx.tree, "binary", "assignment"):  # type: ignore[arg-type]
            divisor = divisor_of(node)
            if divisor is None:
                continue
            v = model.value_of(divisor)
            if not reaches_zero(v):
                continue
            shown = text(ctx, divisor)
            key = (ctx.span(divisor)[0], " ".join(ctx.node_text(divisor).split()))
            if key in found:
                found[key][2].append(divisor)
                continue
            advice = "guard it"
            floored = v.range.is_nonnegative and (components(v.type) or ("", 0))[0] == "float"
            # a floor keeps the meaning only for divisors that are never negative
            if floored:
                advice = f"add an epsilon: max({shown}, {EPSILON})"
            source = f"; it comes from {v.why}" if v.why else ""
            message = (
                f"division by {shown}, which may be 0 (range {v.range.describe()}{source}); "
                f"{advice}"
            )
            found[key] = (divisor, message, [divisor] if floored else [])
        for first, message, floors in found.values():
            yield self.emit(ctx, first, message, _floor_fix(ctx, floors))


def _floor_fix(ctx: LintContext, divisors: list[Node]) -> Fix | None:
    """Floor every occurrence of the divisor at EPSILON; None if one cannot be edited."""
    edits = []
    for divisor in divisors:
        fix = wrap_fix(ctx, divisor, "max({}, " + EPSILON + ")", "floor the divisor")
        if fix is None:
            return None
        edits += fix.edits
    return Fix("floor the divisor", tuple(edits), "unsafe") if edits else None
