"""The variables in scope along the first path (`State`), and how the states after two branches
join: a component both branches agree on stays exact."""

from __future__ import annotations

from .values import MV, NO_TAGS, Sym, known, union


class State:
    """The variables in scope on the path: frames of names, innermost last. Frame 0 holds the
    globals this path wrote; the others are read from `shared` (not copied per branch)."""

    __slots__ = ("frames", "shared", "dead", "control")

    def __init__(self, shared: dict[str, MV], frames: list[dict[str, MV]] | None = None) -> None:
        self.shared = shared
        self.frames = frames if frames is not None else [{}]
        self.dead = False
        self.control: frozenset = NO_TAGS  # the moments that chose this path

    def copy(self) -> State:
        out = State(self.shared, [dict(f) for f in self.frames])
        out.dead, out.control = self.dead, self.control
        return out

    def lookup(self, name: str) -> MV | None:
        for frame in reversed(self.frames):
            if name in frame:
                return frame[name]
        return self.shared.get(name)

    def declare(self, name: str, value: MV) -> None:
        self.frames[-1][name] = value

    def assign(self, name: str, value: MV) -> None:
        for frame in reversed(self.frames):
            if name in frame:
                frame[name] = value
                return
        if name in self.shared:
            self.frames[0][name] = value

    def push(self) -> None:
        self.frames.append({})

    def pop(self) -> None:
        self.frames.pop()

    def become(self, other: State) -> None:
        self.frames, self.dead, self.control = other.frames, other.dead, other.control


def join_values(values: list[MV]) -> MV:
    first = values[0]
    if all(v is first for v in values):
        return first
    if first.comps is None or any(
        v.comps is None or len(v.comps) != len(first.comps) for v in values
    ):
        return MV(first.type)
    comps = []
    for i, c in enumerate(first.comps):
        same = all(v.comps[i] is c or (known(c) and known(v.comps[i]) and v.comps[i] == c  # type: ignore[index]
                                         and type(v.comps[i]) is type(c)) for v in values)  # type: ignore[index]  # fmt: skip
        comps.append(c if same else Sym())
    return MV(first.type, tuple(comps), union(*(v.tags for v in values)))


def join_states(base: State, states: list[State]) -> State:
    """The state after branches that started from `base`: a variable all live branches agree
    on keeps its value."""
    live = [s for s in states if not s.dead]
    if not live:
        out = base.copy()
        out.dead = True
        return out
    if len(live) == 1:
        out = live[0]
        out.control = base.control
        return out
    out = base.copy()
    depth = len(base.frames)
    for i in range(depth):
        names: set[str] = set()
        for s in live:
            frame = s.frames[i]
            for name, value in frame.items():
                if base.frames[i].get(name) is not value:
                    names.add(name)
        for name in names:
            values = [s.frames[i].get(name) or s.lookup(name) for s in live]
            if any(v is None for v in values):
                continue
            out.frames[i][name] = join_values(values)  # type: ignore[arg-type]
    return out
