"""What the semantic model knows about one value (`Value`): its GLSL type, range, whether it
is a unit vector, where it comes from and the evidence of a 0; and the join of two values where
control flow merges (the hull of the ranges, the facts that hold on both paths); and what it
knows about a function of the file (`Function`), which the expressions that call it read."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from lark import Tree

from . import witness as W
from .ranges import UNKNOWN, Interval, hull_all
from .witness import Witness

Env = Mapping[str, "Value"]


@dataclass(frozen=True, init=False)
class Value:
    """What the model knows about a value: GLSL type, range (hull of the components), whether
    it is a unit vector, and its origin: the builtin that produced it ("dot", "length",
    "cross" ...) or "sum"/"difference" of two unit vectors. `zero` says that 0 is reached on
    evidence (a constant 0, max(x, 0.0), a length, a product with such a factor), not merely
    inside a range widened by interval arithmetic: (0.5 - x) * x is in [0, inf) for x in
    [0, 0.5] without being 0 anywhere the author cares about."""

    type: str | None = None
    range: Interval = UNKNOWN
    unit: bool = False
    origin: str | None = None
    zero: bool = False
    comps: tuple[Interval, ...] | None = None  # per component of a vector, when known
    # Where the evidence of a 0 comes from, when it is far from the expression (a parameter
    # given an unclamped dot product at a call site): for messages.
    why: str | None = None
    # Relations to other variables (`x < y` inside `if (x < y)`): (part, op, name, value)
    # says self (or its component `part`, "" for the whole) op name, while the variable
    # `name` names (or is the base of) still holds that very Value object.
    rel: tuple[tuple[str, str, str, Value], ...] = ()
    # The variables (name, value) this vector is known orthogonal to: a cross product's
    # operands, and so normalize(cross(a, b)).
    ortho: tuple[tuple[str, Value], ...] = ()
    # Values taken at named reachable inputs (witness.py): the evidence a domain error needs.
    wit: Witness | None = None

    def __init__(
        self,
        type: str | None = None,
        range: Interval = UNKNOWN,
        unit: bool = False,
        origin: str | None = None,
        zero: bool = False,
        comps: tuple[Interval, ...] | None = None,
        why: str | None = None,
        rel: tuple[tuple[str, str, str, Value], ...] = (),
        ortho: tuple[tuple[str, Value], ...] = (),
        wit: Witness | None = None,
    ) -> None:
        # Written out rather than the frozen dataclass's __init__ (a setattr per field): the
        # model makes values by the hundred thousand.
        if comps is not None:  # the range is always the hull of the components
            range = hull_all(comps)
        fields = self.__dict__
        fields["type"], fields["range"], fields["unit"] = type, range, unit
        fields["origin"], fields["zero"], fields["comps"] = origin, zero, comps
        fields["why"], fields["rel"], fields["ortho"] = why, rel, ortho
        fields["wit"] = wit

    def but(self, **changes: object) -> Value:
        """This value with some fields changed: dataclasses.replace, without its cost (it
        builds the keyword arguments of every field and runs __init__ again)."""
        new = object.__new__(Value)
        fields = new.__dict__
        fields.update(self.__dict__)
        fields.update(changes)
        if fields["comps"] is not None and ("comps" in changes or "range" in changes):
            fields["range"] = hull_all(fields["comps"])  # type: ignore[arg-type]
        return new

    def parts(self, n: int) -> list[Interval]:
        """n component ranges: the known ones, else the hull for each (a scalar broadcasts)."""
        if self.comps is not None and len(self.comps) == n:
            return list(self.comps)
        return [self.range] * n

    def join(self, other: Value) -> Value:
        comps = None
        if (
            self.comps is not None
            and other.comps is not None
            and (len(self.comps) == len(other.comps))
        ):
            comps = tuple(a.hull(b) for a, b in zip(self.comps, other.comps, strict=True))
        return Value(
            self.type if self.type == other.type else None,
            self.range.hull(other.range),
            self.unit and other.unit,
            self.origin if self.origin == other.origin else None,
            self.zero or other.zero,
            comps,
            self.why or other.why,
            _common_facts(self.rel, other.rel),
            _common_facts(self.ortho, other.ortho),
            W.join(self.wit, other.wit),
        )

    def unknown(self) -> Value:
        """The same variable, nothing known about its value."""
        return Value(self.type)


def _common_facts(a: tuple, b: tuple) -> tuple:  # type: ignore[type-arg]
    """The facts that hold on both paths (the same fact about the very same value)."""
    if not a or not b:
        return ()
    return tuple(f for f in a if any(f[:-1] == g[:-1] and f[-1] is g[-1] for g in b))


Comps = tuple[Interval, ...] | None  # ranges per component of a vector, when known


@dataclass
class Function:
    """A function of the file as the model knows it: its signature, and once the forward pass
    has run its body, the join of what it returns."""

    name: str
    node: Tree
    return_type: str
    params: list[tuple[str, str, str]]  # (qualifier, type, name)
    result: Value | None = None  # the join of what its return statements give
