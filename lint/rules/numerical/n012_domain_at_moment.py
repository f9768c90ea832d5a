"""N012 domain-at-moment."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.moments import Event, moments, show
from ...context import LintContext
from ...finding import Finding
from .. import register
from ._common import NumericalRule, text
from ._moments import (
    advice,
    call_phrase,
    first_per_origin,
    moment_phrase,
    ordered_events,
    reportable,
)

_DOMAIN = {
    "sqrt": "sqrt of a negative value is undefined (NaN)",
    "inversesqrt": "inversesqrt of a value <= 0 is undefined (inf or NaN)",
    "log": "log of a value <= 0 is undefined (-inf or NaN)",
    "log2": "log2 of a value <= 0 is undefined (-inf or NaN)",
    "pow": "pow(x, y) is undefined for x < 0, and for x = 0 with y <= 0",
    "acos": "acos outside [-1, 1] is undefined (NaN)",
    "asin": "asin outside [-1, 1] is undefined (NaN)",
    "normalize": "normalize of a zero vector divides by 0 (NaN)",
}


@register
class DomainAtMoment(NumericalRule):
    """Finds `sqrt`, `inversesqrt`, `log`, `log2`, `pow`, `acos`, `asin` or `normalize` called
    with a value outside its domain at a moment every shader reaches: the first frame (iTime,
    iFrame and iTimeDelta are 0), before the first click (iMouse is 0), the first iteration of a
    loop, the constants a call passes, or a `uniform` that ShaderToy never sets (0).

    The shader is run once along that first path with exact constants (see
    lint/analysis/moments/); a value it does not know exactly is never reported. A range that
    merely reaches outside the domain is N001, N002, N003 or N006's (opt-in).

    Why is this bad?
        Outside their domain these builtins are undefined in GLSL and give NaN or infinity on
        real GPUs, which reaches the pixel or, in a buffer, every later frame.

    Example:
        vec2 dir = normalize(iMouse.xy - 0.5 * iResolution.xy + 0.5 * iResolution.xy);

    Use instead:
        vec2 m = iMouse.xy - 0.5 * iResolution.xy + 0.5 * iResolution.xy;
        vec2 dir = dot(m, m) > 0.0 ? normalize(m) : vec2(1.0, 0.0);

    Fix safety:
        No fix: what the value should be at that moment is the author's choice.

    References:
        - GLSL ES 3.00 spec §8.1, §8.2 (Angle, Trigonometry and Exponential Functions), §8.5
          (Geometric Functions)
    """

    code = "N012"
    name = "domain-at-moment"
    certainty = "certain"
    default = False  # until its corpus findings are judged

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        events = [e for e in ordered_events(ctx, moments(ctx)) if e.kind in _DOMAIN]
        for event, others in first_per_origin(events):
            message = self._message(ctx, event)
            if message is None:
                continue
            if others:
                message += f" (and {others} more call{'s' if others > 1 else ''} like it)"
            yield self.emit(ctx, event.where, message)

    def _message(self, ctx: LintContext, event: Event) -> str | None:
        if not reportable(event):
            return None
        inner = event.origin()
        shown = text(ctx, inner.expr)
        moment = moment_phrase(event.tags)
        why = _DOMAIN[inner.kind]
        if event.site is not None:
            head = call_phrase(ctx, event, f"call {inner.kind}({shown})")
            tail = f", {moment}" if event.tags else ""
            return f"{head}{tail}: {why}; pass values inside its domain or guard it"
        value = show(event.value)
        if inner.kind == "pow" and event.other is not None:
            value += f" (exponent {show(event.other)})"
        fix = advice(event.tags, shown)
        # `log(iTime)` needs no "with iTime = 0.0": the moment says so
        named = any(t[0] == "frame" and t[1] == shown for t in event.tags)
        held = "" if named else f" with {shown} = {value}"
        return f"{event.kind}({shown}){held} {moment}: {why}; {fix}"
