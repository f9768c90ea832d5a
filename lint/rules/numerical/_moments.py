"""How N011 and N012 name the moment at which a value is exact (lint/analysis/moments/): the
first frame, before the first click, the first iteration of a loop, a uniform ShaderToy does not
set, the constants passed at a call site."""

from __future__ import annotations

from lark import Tree

from ...analysis.moments import Event, Moments, show
from ...context import LintContext, Node, walk
from ._common import text

# Which moment a message leads with when a value depends on several.
_ORDER = {"uniform": 0, "frame": 1, "mouse": 2, "loop": 3}


_LITERAL_PARTS = frozenset(
    {"float_literal", "int_literal", "bool_literal", "constructor", "type_specifier",
     "arguments", "unary", "binary", "array_specifier"}
)  # fmt: skip


def is_literal(node: Node) -> bool:
    """An expression of literals only (`0.0`, `vec2(1.0, 0.0)`): a 0 written on purpose, such
    as `1.0 / 0.0` for an infinity."""
    return not isinstance(node, Tree) or all(n.data in _LITERAL_PARTS for n in walk(node))


def reportable(event: Event) -> bool:
    """An event at a moment, through a call, or on every run through a name (`x / n` with
    n = 0.0 and nothing changing it), not a literal 0 written as such."""
    return event.site is not None or bool(event.tags) or not is_literal(event.expr)


def moment_phrase(tags: frozenset) -> str:
    """When the value is what it is: "at the first frame (iTime = 0)", "on the first iteration
    of the loop at line 260 (t = 0.0 before it)"; "" for a value that holds on every run."""
    parts: list[str] = []
    frame = sorted(t[1] for t in tags if t[0] == "frame")
    loops: set[int] = set()
    for tag in sorted((t for t in tags if t[0] in _ORDER), key=lambda t: (_ORDER[t[0]], t[1:])):
        if tag[0] == "uniform":
            parts.append(
                f"because ShaderToy never sets `uniform {tag[1]}` (line {tag[2]}), which is then 0"
            )
        elif tag[0] == "frame" and frame:
            parts.append(f"at the first frame ({', '.join(f'{n} = 0' for n in frame)})")
            frame = []
        elif tag[0] == "mouse":
            parts.append("until the first mouse click (iMouse = vec4(0))")
        elif tag[0] == "loop" and tag[1] not in loops:
            held = sorted(f"{t[2]} = {t[3]}" for t in tags if t[0] == "loop" and t[1] == tag[1])
            loops.add(tag[1])
            parts.append(
                f"on the first iteration of the loop at line {tag[1]} ({', '.join(held)} before it)"
            )
    return ", ".join(parts) or "on every run"


def advice(tags: frozenset, shown: str, use: str = "using it") -> str:
    """What to do, for the moment the message leads with."""
    lead = min((t for t in tags if t[0] in _ORDER), key=lambda t: _ORDER[t[0]], default=None)
    if lead is None:
        return "fix the constant or guard the operation"
    if lead[0] == "uniform":
        return f"give {lead[1]} a non-zero default where the host does not set it, or guard it"
    if lead[0] == "loop":
        return f"start {lead[2]} at a safe value (small and positive) or advance it before {use}"
    if lead[0] == "mouse":
        return "guard it (iMouse is 0 until the user clicks): test iMouse.z > 0.0 first"
    return f"guard it (max({shown}, 1e-4) or an offset time): the first frame is always shown"


def call_phrase(ctx: LintContext, event: Event, what: str) -> str:
    """`tl(time, 0.0, 0.0)` makes tl divide by `ix - im` (line 49), which is 0.0 with
    range = 0.0: for an event lifted to its call site."""
    inner = event.origin()
    line = ctx.span(inner.expr)[0]
    args = ", ".join(f"{name} = {show(value)}" for name, value in event.args)
    with_args = f" with {args}" if args else ""
    return (
        f"{text(ctx, event.where, 40)} makes {event.callee}() {what} (line {line}), which is "
        f"{show(inner.value)}{with_args}"
    )


def ordered_events(ctx: LintContext, found: Moments | None) -> list[Event]:
    """The file's events in source order."""
    if found is None:
        return []
    return sorted(found.events.values(), key=lambda e: ctx.span(e.where)[:2])


def first_per_origin(events: list[Event]) -> list[tuple[Event, int]]:
    """One finding per defect: of the calls that make one division (or builtin call) of a
    function fail, the first, with how many more do."""
    firsts: dict[tuple[int, str], list] = {}
    for event in events:
        origin = event.origin()
        key = (id(origin.expr), origin.kind)
        if key in firsts:
            firsts[key][1] += 1
        else:
            firsts[key] = [event, 0]
    return [(event, others) for event, others in firsts.values()]
