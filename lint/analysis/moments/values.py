"""The value model of the first-path evaluation: each value is a type and its components, every
component either an exact constant or an unknown (`Sym`), with the tags of the moments its
exactness depends on; `Event` is what the evaluation reports. Also what ShaderToy's inputs hold
at those moments, and the small helpers every other module builds values with."""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass

from lark import Tree

from glint.compiler.glsl import types as T

from ...context import Node

# A tag: ("frame", name) the first frame; ("mouse",) before the first click; ("loop", line,
# name, value text) the first iteration of the loop at line; ("uniform", name, line) a uniform
# ShaderToy does not set; ("param", index) an exact argument of the function being evaluated.
NO_TAGS: frozenset = frozenset()

# ShaderToy's inputs at the first frame. iMouse stays 0 until the first click.
FRAME_ZERO = {"iTime": "float", "iFrame": "int", "iTimeDelta": "float"}
SHADERTOY_INPUTS = frozenset(
    {
        "iResolution",
        "iTime",
        "iTimeDelta",
        "iFrame",
        "iFrameRate",
        "iChannelTime",
        "iChannelResolution",
        "iMouse",
        "iChannel0",
        "iChannel1",
        "iChannel2",
        "iChannel3",
        "iDate",
        "iSampleRate",
        "iGlobalTime",
    }
)


class Sym:
    """An unknown value with an identity."""

    __slots__ = ()


Comp = float | int | bool | Sym


def known(c: Comp) -> bool:
    return not isinstance(c, Sym)


@dataclass(frozen=True, slots=True)
class MV:
    """A value on the first path: its type, its components (None: not followed) and the tags of
    the moments its exact components depend on."""

    type: str | None
    comps: tuple[Comp, ...] | None = None
    tags: frozenset = NO_TAGS

    def exact(self) -> bool:
        return self.comps is not None and all(known(c) for c in self.comps)

    def has_zero(self) -> bool:
        return self.comps is not None and any(known(c) and c == 0 for c in self.comps)

    def but(self, tags: frozenset) -> MV:
        return MV(self.type, self.comps, tags)


@dataclass(frozen=True)
class Event:
    """A division by an exact 0 or a builtin outside its domain on the first path.

    kind: "divide" (`/`, `/=`), "mod", "atan", or the builtin's name for a domain event.
    expr: the offending expression (a divisor, the builtin's argument, the call); value: its
    value; other: the numerator (of mod: x; of pow: the exponent); tags: the moments it depends
    on. site: the call where it is reported when it depends on the arguments passed there, and
    inner: the event inside the callee it lifts, with `args` the callee's parameters (name,
    value) that made it."""

    kind: str
    expr: Node
    value: MV
    other: MV | None
    tags: frozenset
    site: Tree | None = None
    inner: Event | None = None
    callee: str = ""
    args: tuple[tuple[str, MV], ...] = ()

    @property
    def where(self) -> Node:
        return self.site if self.site is not None else self.expr

    def origin(self) -> Event:
        """The event in the function where the division or call is written."""
        event = self
        while event.inner is not None:
            event = event.inner
        return event


# --- types --------------------------------------------------------------------------------


def size_of(type_: str | None) -> int | None:
    """Components of a scalar or vector type; None for anything not followed."""
    return T.size(type_) or None


def base_of(type_: str | None) -> str:
    """How a value's components are held: a uint's as a Python int, like an int's."""
    element = T.element_type(type_) or "float"
    return "int" if element == "uint" else element


vector_type = T.vector


def unknown(type_: str | None, tags: frozenset = NO_TAGS) -> MV:
    n = size_of(type_)
    return MV(type_, tuple(Sym() for _ in range(n)) if n else None, tags)


def f32(x: float) -> float | None:
    """x rounded to a float32, as the GPU holds it; None where it is not finite there."""
    if math.isnan(x) or math.isinf(x):
        return None
    try:
        return struct.unpack("f", struct.pack("f", x))[0]
    except OverflowError:
        return None


def cast(base: str, c: Comp) -> Comp:
    if not known(c):
        return c
    if base == "float":
        r = f32(float(c))
        return Sym() if r is None else r
    if base == "int":
        try:
            return int(c)
        except (OverflowError, ValueError):
            return Sym()
    return bool(c)


def union(*sets: frozenset) -> frozenset:
    out = NO_TAGS
    for s in sets:
        if s:
            out = s if not out else out | s
    return out


def show(v: MV) -> str:
    """An exact value as GLSL writes it: 0.0, vec3(0.0), vec2(1.0, 0.0)."""
    if v.comps is None:
        return "?"
    parts = [_show_comp(c) for c in v.comps]
    if len(parts) == 1:
        return parts[0]
    if len(set(parts)) == 1:
        return f"{v.type}({parts[0]})"
    return f"{v.type}({', '.join(parts)})"


def _show_comp(c: Comp) -> str:
    if not known(c):
        return "?"
    if isinstance(c, bool):
        return "true" if c else "false"
    if isinstance(c, int):
        return str(c)
    text = f"{c:.6g}"
    return text if any(ch in text for ch in ".en") else text + ".0"


def zero_of(type_: str, tags: frozenset) -> MV:
    n = size_of(type_)
    if n is None:
        return MV(type_, None, tags)
    base = base_of(type_)
    zero: Comp = 0.0 if base == "float" else (0 if base == "int" else False)
    return MV(type_, (zero,) * n, tags)


def truth_of(v: MV) -> bool | None:
    if v.comps and len(v.comps) == 1 and known(v.comps[0]):
        return bool(v.comps[0])
    return None


def broadcast(a: tuple[Comp, ...], b: tuple[Comp, ...]) -> tuple[Comp, ...]:
    return a * len(b) if len(a) == 1 and len(b) > 1 else a


def construct(type_: str, n: int, args: list[MV]) -> MV:
    comps: list[Comp] = []
    tags = union(*(a.tags for a in args))
    for a in args:
        if a.comps is None:
            return unknown(type_)
        comps.extend(a.comps)
    base = base_of(type_)
    if len(comps) == 1 and n > 1:
        comps = comps * n
    if len(comps) < n:
        return unknown(type_)
    return MV(type_, tuple(cast(base, c) for c in comps[:n]), tags)
