"""N011 division-by-zero-at-moment."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import leaf_text

from ...analysis.model import semantic_model
from ...analysis.moments import Event, moments, show
from ...analysis.moments.escape import Escaped, escape_check, kinds
from ...analysis.syntax import call_args, callee_name
from ...context import LintContext, walk_kind
from ...finding import Finding
from .. import register
from ._common import Node, NumericalRule, divisor_of, reaches_below, text
from ._moments import (
    advice,
    call_phrase,
    first_per_origin,
    moment_phrase,
    ordered_events,
    reportable,
)


@register
class DivisionByZeroAtMoment(NumericalRule):
    """Finds a division, `mod` or `atan(y, x)` by a value that is exactly 0 at a moment every
    shader reaches: the first frame (iTime, iFrame and iTimeDelta are 0), before the first click
    (iMouse is 0), the first iteration of a loop (the variables it advances still hold their
    starting values), the constants a call passes (`tl(t, 0.0, 0.0)` into a function that
    divides by their difference), or a `uniform` that ShaderToy never sets (0). Also a divisor
    `max(0.0, x)` where x goes below 0: it is exactly 0 for every such x.

    The shader is run once along that first path with exact constants (see
    lint/analysis/moments/); a value it does not know exactly is never reported. A divisor
    whose range merely touches 0 is N005's (opt-in).

    Only a division whose infinity or NaN reaches something is reported: the pixel's colour,
    an out parameter, a global, a return value that goes on. One that is only compared
    (`t > 0.0` rejects -inf and NaN), bounded (clamp, smoothstep, step; `max(0.0, -inf)` is
    0) or left in a component nobody reads goes no further. x / 0 is an infinity, 0 / 0 and
    mod(x, 0) are NaN, which min, max and clamp do not reliably absorb.

    Why is this bad?
        x / 0 is infinity and 0 / 0 is NaN, and they reach the pixel or, in a buffer, the state
        it keeps for every later frame. A moment that always comes (the first frame, the first
        step of a march) is not a corner case: it happens on every run.

    Example:
        float t = 0.0;
        for (int i = 0; i < 64; i++) {
            float h = map(ro + rd * t);
            res = min(res, k * h / t);
            t += h;
        }

    Use instead:
        float t = 0.02;
        for (int i = 0; i < 64; i++) {
            float h = map(ro + rd * t);
            res = min(res, k * h / t);
            t += h;
        }

    Fix safety:
        No fix: where to start, or what to divide by, is the author's choice.

    References:
        - GLSL ES 3.00 spec §4.5.1 (Range and Precision) and §8.1, §8.3 (atan(y, x) is undefined
          for x = y = 0; mod(x, y) is x - y * floor(x / y))
        - IEEE 754: x / 0 is ±infinity, 0 / 0 is NaN
    """

    code = "N011"
    name = "division-by-zero-at-moment"
    certainty = "certain"
    default = False  # until its corpus findings are judged

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        found = moments(ctx)
        reported: set[int] = set()
        events = [e for e in ordered_events(ctx, found) if e.kind in ("divide", "mod", "atan")]
        sinks: dict[int, Escaped | None] = {}
        kept = []
        for event in events:
            if event.kind != "atan" and reportable(event):
                # only where the infinity or NaN reaches something (atan(0, 0) is not one)
                sinks[id(event)] = escape_check(ctx).escape(event)
                if sinks[id(event)] is None:
                    continue
            kept.append(event)
        for event, others in first_per_origin(kept):
            message = self._message(ctx, event, sinks.get(id(event)))
            if message is None:
                continue
            if others:
                message += f" (and {others} more call{'s' if others > 1 else ''} like it)"
            reported.add(ctx.span(event.where)[0])
            yield self.emit(ctx, event.where, message)
        yield from self._half_space(ctx, reported)

    def _message(self, ctx: LintContext, event: Event, sink: Escaped | None) -> str | None:
        inner = event.origin()
        if not reportable(event):
            return None
        what = {"divide": "divide by", "mod": "take mod by", "atan": "call atan(0, 0) at"}[
            event.kind
        ]
        nan = ""
        if inner.kind == "divide" and inner.other is not None and inner.other.has_zero():
            nan = " (0/0: NaN)"
        reaches = f", and {kinds(sink.values)} reaches {sink.sink}" if sink and sink.sink else ""
        shown = text(ctx, inner.expr)
        moment = moment_phrase(event.tags)
        if event.site is not None:
            head = call_phrase(ctx, event, f"{what} {shown}")
            tail = f", {moment}" if event.tags else ""
            fix = f"pass values that keep it non-zero or guard it in {event.callee}()"
            return f"{head}{tail}{nan}{reaches}; {fix}"
        if event.kind == "atan":
            head = f"atan({shown}) has both arguments 0"
        elif event.kind == "mod":
            head = f"mod by {shown}, which is {show(event.value)}"
        else:
            head = f"divides by {shown}, which is {show(event.value)}"
        return f"{head} {moment}{nan}{reaches}; {advice(event.tags, shown, 'dividing')}"

    def _half_space(self, ctx: LintContext, reported: set[int]) -> Iterator[Finding]:
        """`x / max(0.0, y)`: 0 for every y <= 0, where y is known to go below 0."""
        model = None
        for node in walk_kind(ctx.tree, "binary", "assignment"):  # type: ignore[arg-type]
            divisor = divisor_of(node)
            if divisor is None:
                continue
            other = _floored_at_zero(divisor)
            if other is None:
                continue
            line = ctx.span(divisor)[0]
            if line in reported:
                continue
            model = model or semantic_model(ctx)
            r = model.range_of(other)
            if not reaches_below(r, 0.0) or r.lo == -float("inf"):
                continue
            shown, inside = text(ctx, divisor), text(ctx, other, 32)
            message = (
                f"divides by {shown}, which is exactly 0 for every {inside} <= 0 ({inside} is "
                f"in {r.describe()}); floor it above 0 (max({inside}, 1e-4)) or branch on the "
                "sign first"
            )
            reported.add(line)
            yield self.emit(ctx, divisor, message)


def _floored_at_zero(node: Node) -> Node | None:
    """x for `max(0.0, x)`, `max(x, 0.0)` or `clamp(x, 0.0, hi)`."""
    if not (isinstance(node, Tree) and node.data == "call"):
        return None
    name, args = callee_name(node), call_args(node)
    if name == "max" and len(args) == 2:
        if _is_zero(args[0]):
            return args[1]
        if _is_zero(args[1]):
            return args[0]
    if name == "clamp" and len(args) == 3 and _is_zero(args[1]):
        return args[0]
    return None


def _is_zero(node: Node) -> bool:
    if isinstance(node, Tree) and node.data in ("float_literal", "int_literal"):
        try:
            return float(leaf_text(node).rstrip("fFuU")) == 0.0
        except ValueError:
            return False
    return False
