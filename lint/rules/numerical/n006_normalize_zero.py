"""N006 normalize-zero."""

from __future__ import annotations

from collections.abc import Iterator

from glint.compiler.glsl.types import size

from ...analysis.model import semantic_model
from ...analysis.ranges import Interval
from ...analysis.syntax import call_args
from ...context import LintContext
from ...finding import Finding
from .. import register
from ._common import NumericalRule, builtin_calls, text


@register
class NormalizeZero(NumericalRule):
    """Finds `normalize(v)` of a vector that may be zero: the sum or difference of two unit vectors
    (V + L), a cross product of two computed vectors, a constant zero vector.

    A cross product with a constant axis, the world-up of a look-at camera, is not reported: it
    degenerates only along that one chosen direction.

    Why is this bad?
        normalize(0) divides by zero and gives NaN. V + L is zero when the light is straight behind
        the surface seen from the viewer; a cross product is zero when its two vectors are parallel.

    Example:
        vec3 H = normalize(V + L);

    Use instead:
        vec3 h = V + L;
        vec3 H = h * inversesqrt(max(dot(h, h), 1e-8));

    Fix safety:
        No fix: the guard needs a temporary, and what a zero vector should become (any unit vector,
        the normal) is the author's choice.

    References:
        - GLSL ES 3.00 spec §8.5 (Geometric Functions): normalize(x) is x / length(x)
        - Khronos reference page: normalize
    """

    code = "N006"
    name = "normalize-zero"
    certainty = "possible"
    default = False  # opt-in: few of its sampled findings on real shaders are worth acting on

    _WHY = {
        "sum": "the sum of two unit vectors is zero when they are opposite",
        "difference": "the difference of two unit vectors is zero when they are equal",
        "cross": "a cross product is zero when its vectors are parallel",
    }

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        model = semantic_model(ctx)
        for call, _ in builtin_calls(ctx, "normalize"):
            args = call_args(call)
            if len(args) != 1:
                continue
            v = model.value_of(args[0])
            parts = v.parts(size(v.type) or 1)
            if not all(c.may_be_zero for c in parts):
                continue  # some component never reaches 0
            why = self._WHY.get(v.origin or "")
            if why is None and all(c == Interval.point(0.0) for c in parts):
                why = "it is the zero vector"
            if why is None:
                continue
            shown = text(ctx, args[0])
            message = (
                f"normalize of {shown}, which may be zero: {why}; guard the length, e.g. "
                f"v * inversesqrt(max(dot(v, v), 1e-8))"
            )
            yield self.emit(ctx, args[0], message)
