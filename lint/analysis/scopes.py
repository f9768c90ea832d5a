"""The variables in scope during the semantic model's forward pass (`Scopes`), and what happens
to them where control flow merges (`join_scopes`) and where a loop assigns them (`widen`)."""

from __future__ import annotations

from collections.abc import Sequence
from itertools import compress
from operator import is_not

from ..context import Node, tokens
from .ranges import UNKNOWN
from .values import Value


def names_of(expr: Node) -> frozenset[str]:
    """The words of an expression (a variable's name among them)."""
    return frozenset(str(token) for token in tokens(expr))


class Scopes:
    """Variables in scope during the forward pass: a stack of frames, and whether the code
    here is reachable (after return/break/continue/discard it is not)."""

    def __init__(self, frames: list[dict[str, Value]] | None = None, dead: bool = False):
        self.frames = frames if frames is not None else [{}]
        self.dead = dead

    def copy(self) -> Scopes:
        return Scopes([dict(f) for f in self.frames], self.dead)

    def flat(self) -> dict[str, Value]:
        out: dict[str, Value] = {}
        for frame in self.frames:
            out.update(frame)
        return out

    def env_for(self, expr: Node, names: frozenset[str] | None = None) -> dict[str, Value]:
        """The variables in scope that `expr` names (`names`, when the caller knows them): all
        an evaluation of it can read.

        The model keeps each expression's environment for later queries (`record`). A copy of
        every variable in scope (`flat`) per expression made the analysis quadratic in time
        and memory on long functions (a chain of 1000 declarations kept 1000 copies of up to
        1000 variables); the names an expression contains are few."""
        wanted = set(names_of(expr) if names is None else names)
        env: dict[str, Value] = {}
        for frame in reversed(self.frames):  # the innermost declaration of a name wins
            if wanted.isdisjoint(frame):
                continue
            found = wanted & frame.keys()
            for name in found:
                env[name] = frame[name]
            wanted -= found
            if not wanted:
                break
        return env

    def push(self) -> None:
        self.frames.append({})

    def pop(self) -> None:
        self.frames.pop()

    def lookup(self, name: str) -> Value | None:
        for frame in reversed(self.frames):
            if name in frame:
                return frame[name]
        return None

    def declare(self, name: str, value: Value) -> None:
        self.frames[-1][name] = value

    def assign(self, name: str, value: Value) -> None:
        for frame in reversed(self.frames):
            if name in frame:
                frame[name] = value
                return

    def become(self, other: Scopes) -> None:
        self.frames, self.dead = other.frames, other.dead


def join_scopes(items: Sequence[Scopes]) -> Scopes:
    """The state after control flow merges: per variable, the join of every live path. Frames
    deeper than the shallowest path (blocks left by `break`) are out of scope there."""
    live = [s for s in items if not s.dead]
    if not live:
        out = items[0].copy()
        out.dead = True
        return out
    depth = min(len(s.frames) for s in live)
    frames: list[dict[str, Value]] = []
    for i in range(depth):
        first = live[0].frames[i]
        if not first:  # a block that declares nothing (a name must be on every path)
            frames.append({})
            continue
        others = [s.frames[i] for s in live[1:]]
        names = list(first)
        if all(list(other) == names for other in others):
            # The paths are copies of one state: the same names, and mostly the very same
            # Value objects (a branch assigns a few variables). Find the names whose objects
            # differ with C-level iteration and join only those; a Python-level pass over every
            # variable in scope at each merge was quadratic in long code.
            changed: dict[str, list[Value]] = {}
            for other in others:
                for name in compress(names, map(is_not, first.values(), other.values())):
                    changed.setdefault(name, [first[name]]).append(other[name])
            frame = dict(first)
            for name, values in changed.items():
                frame[name] = _join_values(values)
        else:
            frame = {}
            for name in names:
                values = [other.get(name) for other in others]
                if None not in values:
                    frame[name] = _join_values([first[name], *values])  # type: ignore[list-item]
        frames.append(frame)
    return Scopes(frames)


def _join_values(values: list[Value]) -> Value:
    """The join of the values, each distinct object once (the join is idempotent)."""
    joined, seen = values[0], {id(values[0])}
    for value in values[1:]:
        if id(value) not in seen:
            seen.add(id(value))
            joined = joined.join(value)
    return joined


def widen(scopes: Scopes, names: set[str], keep_flags: bool = True) -> Scopes:
    """The variables `names` with unknown ranges; unit and origin kept unless told not to
    (a loop's later passes take them away where the body breaks them)."""
    out = scopes.copy()
    for frame in out.frames:
        for name in names & frame.keys():
            v = frame[name]
            frame[name] = Value(v.type, UNKNOWN, v.unit, v.origin) if keep_flags else Value(v.type)
    return out
