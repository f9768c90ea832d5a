"""Calls to the file's own functions along the first path: each function is evaluated once per
tuple of exact arguments (memoised), and an event that depends on an argument is lifted to the
call site with the tags of what was passed there. A mixin of `Moments`."""

from __future__ import annotations

from dataclasses import dataclass, field

from lark import Tree

from glint.compiler.glsl.ast import definition_parts

from ...context import Node, walk
from ..syntax import call_args, callee_name
from .state import State, join_values
from .values import MV, NO_TAGS, Event, Sym, known, union, unknown

MAX_VARIANTS = 6  # argument tuples evaluated per function before it is run with unknowns
MAX_DEPTH = 12  # calls deep


@dataclass
class Fn:
    """A function of the file and how many argument tuples it was evaluated with."""

    name: str
    node: Tree
    return_type: str
    params: list[tuple[str, str, str]]  # (qualifiers, type, name)
    variants: int = 0


@dataclass
class Frame:
    """The function being evaluated: its returns and the events that depend on its
    arguments (lifted to the call site by the caller)."""

    fn: Fn
    returns: list[MV] = field(default_factory=list)
    pending: list[Event] = field(default_factory=list)


def writes_back(qualifier: str) -> bool:
    """Whether a parameter of these qualifiers is written back to its argument."""
    return any(word in ("out", "inout") for word in qualifier.split())


class CallEvaluator:
    """Evaluates calls to the file's functions and records events; the walkers (`block`,
    `writes`, `_forget`) come from the other mixins of `Moments`."""

    functions: dict[str, list[Fn]]  # the file's functions by name (overloads in order)
    events: dict[tuple[int, str], Event]  # by (id of the node reported at, kind)
    globals: dict[str, MV]  # the globals' values after their declarations
    mutable_globals: set[str]  # globals some function writes
    _memo: dict[tuple, tuple[MV, list[Event]]]  # (function, exact arguments) -> result
    _stack: list[Frame]
    _active: set[int]  # ids of the functions being evaluated (recursion ends there)
    _fn_globals: dict[int, frozenset[str]]  # memo of `_global_writes`

    def _evaluate(self, fn: Fn, args: list[MV], entry: bool = False) -> tuple[MV, list[Event]]:
        key = (id(fn.node), tuple(None if a.comps is None else tuple(c if known(c) else None
                                  for c in a.comps) for a in args))  # fmt: skip
        if key in self._memo:
            ret, pending = self._memo[key]
            return ret, pending
        if not entry and any(k is not None and any(c is not None for c in k) for k in key[1]):
            if fn.variants >= MAX_VARIANTS:  # enough variants: what holds for any argument
                return self._evaluate(fn, [unknown(a.type) for a in args])
            fn.variants += 1
        if id(fn.node) in self._active or len(self._stack) > MAX_DEPTH:
            return unknown(fn.return_type), []
        shared = self.globals
        if not entry:  # a global some function writes may hold anything when this one runs
            shared = dict(self.globals)
            for name in self.mutable_globals:
                shared[name] = unknown(shared[name].type)
        state = State(shared)
        state.push()
        for i, ((qualifier, type_, name), arg) in enumerate(zip(fn.params, args, strict=False)):
            if not name:
                continue
            if "out" in qualifier.split() and "inout" not in qualifier.split():
                value = unknown(type_)
            elif arg.comps is not None and any(known(c) for c in arg.comps):
                comps = tuple(c if known(c) else Sym() for c in arg.comps)
                value = MV(type_, comps, frozenset({("param", i)}))
            else:
                value = unknown(type_)
            state.declare(name, value)
        frame = Frame(fn)
        self._stack.append(frame)
        self._active.add(id(fn.node))
        try:
            body = definition_parts(fn.node)[1]
            self.block(body.children, state)
        finally:
            self._active.discard(id(fn.node))
            self._stack.pop()
        ret = join_values(frame.returns) if frame.returns else unknown(fn.return_type)
        ret = MV(fn.return_type, ret.comps, ret.tags)
        self._memo[key] = (ret, frame.pending)
        return ret, frame.pending

    def _call_user(self, call: Tree, name: str, args: list[MV], state: State) -> MV:
        fns = [f for f in self.functions.get(name, []) if len(f.params) == len(args)]
        if not fns:
            return MV(None)
        fn = fns[0]
        ret, pending = self._evaluate(fn, args)
        subst = {("param", i): a.tags for i, a in enumerate(args)}
        for ev in pending:
            params = [t for t in ev.tags if t[0] == "param"]
            tags = union(
                frozenset(t for t in ev.tags if t[0] != "param"),
                *(subst.get(t, NO_TAGS) for t in params),
                state.control,
            )
            used = tuple((fn.params[t[1]][2], args[t[1]]) for t in sorted(params))
            self.emit(Event(ev.kind, ev.expr, ev.value, ev.other, tags, call, ev, name, used))
        ret_tags = ret.tags
        if any(t[0] == "param" for t in ret_tags):
            ret_tags = union(
                frozenset(t for t in ret_tags if t[0] != "param"),
                *(subst.get(t, NO_TAGS) for t in ret_tags if t[0] == "param"),
            )
        # what the call writes: out arguments and the globals functions write
        for (qualifier, _, _), arg in zip(fn.params, call_args(call), strict=False):
            if writes_back(qualifier):
                self._forget(arg, state)
        for g in self._global_writes(fn):
            if state.lookup(g) is not None:
                state.assign(g, unknown(state.lookup(g).type))  # type: ignore[union-attr]
        # each call returns its own unknowns: two calls of one memoised variant are not equal
        comps = tuple(c if known(c) else Sym() for c in ret.comps) if ret.comps else ret.comps
        return MV(ret.type, comps, ret_tags)

    def _global_writes(self, fn: Fn) -> frozenset[str]:
        """The globals a function writes, itself or through the functions it calls."""
        key = id(fn.node)
        if key in self._fn_globals:
            return self._fn_globals[key]
        self._fn_globals[key] = frozenset()  # a cycle (invalid GLSL) ends here
        body = definition_parts(fn.node)[1]
        names = set(self.writes(body) & self.mutable_globals)
        for call in self._calls_in(body):
            name = callee_name(call)
            for callee in self.functions.get(name or "", []):
                names |= self._global_writes(callee)
        self._fn_globals[key] = frozenset(names)
        return self._fn_globals[key]

    def _calls_in(self, node: Node) -> list[Tree]:
        return [n for n in walk(node) if n.data == "call"] if isinstance(node, Tree) else []

    def emit(self, event: Event) -> None:
        """Record an event, or hand it to the caller where it depends on the arguments."""
        if any(t[0] == "param" for t in event.tags) and self._stack:
            self._stack[-1].pending.append(event)
            return
        key = (id(event.where), event.kind)
        if key not in self.events:
            self.events[key] = event
