"""Exact values at named moments: the first path of execution of a shader, evaluated with the
constants it really holds there.

The semantic model (model.py) gives every expression a range that holds on every run, so a
divisor whose range merely touches 0 is a hint at best. Some values are not a hint but a fact at
a moment everyone reaches: on the first frame iTime, iFrame and iTimeDelta are 0; until the first
click iMouse is vec4(0); on the first iteration of a loop the variables it advances still hold
the values they had before it; a call passes the constants written at its site; and a `uniform`
that ShaderToy does not provide is 0 (false). This module runs the shader once along that path,
from mainImage (or main), with each value either an exact constant or unknown, and records every
division by an exact 0 and every builtin called outside its domain on the way (`Event`).

Values: `MV` holds a type, its components (a float, int or bool where exact, a `Sym` where not;
None for matrices, arrays and structs, which are not followed) and the tags of the moments its
exactness depends on (`Tag`). A `Sym` is an unknown with an identity, so that `x + 0.0` is x and
`x - x` is exactly 0 whatever x is. Unknown stays unknown and never yields an event.

Control flow: a branch whose condition is exact is the only one taken (and what it assigns
depends on the condition's moments); otherwise both are run and joined (a component both agree
on stays exact). A loop's body runs once, as its first iteration, with each variable the loop
assigns tagged with its value from before the loop; after the loop those variables are unknown.

Calls: a function of the file is evaluated once per tuple of exact arguments (at most
MAX_VARIANTS tuples per function, then once with unknown arguments), to a depth of MAX_DEPTH.
Inside it, an exact argument carries a `param` tag; an event that depends on one is reported at
the call site, with the call's own tags in its place. So the work stays linear in the size of
the file, times a small constant."""

from __future__ import annotations

import math
import struct
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field

from lark import Token, Tree

from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import (
    DoStatement,
    FullySpecifiedType,
    SwitchStatement,
    TypeSpecifier,
    WhileStatement,
    binary_parts,
    declarators,
    definition_parts,
    field_parts,
    first_child,
    for_parts,
    if_parts,
    index_parts,
    jump_parts,
    leaf_text,
    operand,
    operator,
    ternary_parts,
)
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

from ..context import LintContext, Node, walk
from .declarations import declared_variables, signature
from .syntax import call_args, callee_name, int_value, is_tree, root_variable

# A tag: ("frame", name) the first frame; ("mouse",) before the first click; ("loop", line,
# name, value text) the first iteration of the loop at line; ("uniform", name, line) a uniform
# ShaderToy does not set; ("param", index) an exact argument of the function being evaluated.
Tag = tuple
Tags = frozenset
NO_TAGS: frozenset = frozenset()

MAX_VARIANTS = 6  # argument tuples evaluated per function before it is run with unknowns
MAX_DEPTH = 12  # calls deep

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
DOMAIN_BUILTINS = frozenset(
    {"sqrt", "inversesqrt", "log", "log2", "pow", "acos", "asin", "normalize"}
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


# --- state --------------------------------------------------------------------------------


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


# --- the evaluation -----------------------------------------------------------------------


@dataclass
class _Fn:
    name: str
    node: Tree
    return_type: str
    params: list[tuple[str, str, str]]  # (qualifiers, type, name)
    variants: int = 0


@dataclass
class _Frame:
    """The function being evaluated: its returns and the events that depend on its
    arguments (lifted to the call site by the caller)."""

    fn: _Fn
    returns: list[MV] = field(default_factory=list)
    pending: list[Event] = field(default_factory=list)


class _Jump(Exception):
    pass


class Moments:
    """The events of one file's first path (see the module's docstring)."""

    def __init__(
        self, tree: Tree, bounds: Callable[[Node], tuple[float, float]] | None = None
    ) -> None:
        self.tree = tree
        # (lo, hi) that an expression holds on every run (the semantic model's range): what
        # decides `r2 < rd1` with rd1 = 0 where r2 = dot(z, z) is not known exactly
        self.bounds = bounds
        self.events: dict[tuple[int, str], Event] = {}
        self.functions: dict[str, list[_Fn]] = {}
        self.uniforms: dict[str, int] = {}  # declared uniforms ShaderToy does not set
        self._memo: dict[tuple, tuple[MV, list[Event], frozenset]] = {}
        self._stack: list[_Frame] = []
        self._active: set[int] = set()
        self._writes: dict[int, frozenset[str]] = {}
        self.globals: dict[str, MV] = {}
        self.mutable_globals: set[str] = set()
        self._fn_globals: dict[int, frozenset[str]] = {}
        self._run()

    # --- setup ----------------------------------------------------------------------------

    def _run(self) -> None:
        for child in self.tree.children:
            if is_tree(child, "function_definition"):
                name, ret, params = signature(child)  # type: ignore[arg-type]
                self.functions.setdefault(name, []).append(_Fn(name, child, ret, params))  # type: ignore[arg-type]
        state = State(self.globals)
        self._stack.append(_Frame(_Fn("", self.tree, "void", [])))
        for child in self.tree.children:
            if is_tree(child, "variable_declaration"):
                self._global_declaration(child, state)  # type: ignore[arg-type]
        self.globals.update(state.frames[0])
        self._stack.pop()
        for fns in self.functions.values():
            for fn in fns:
                body = definition_parts(fn.node)[1]
                self.mutable_globals |= self.writes(body) & self.globals.keys()
        entry = self.functions.get("mainImage") or self.functions.get("main") or []
        for fn in entry[:1]:
            args = [unknown(t) for _, t, _ in fn.params]
            self._evaluate(fn, args, entry=True)

    def _global_declaration(self, node: Tree, state: State) -> None:
        words = set(FullySpecifiedType(first_child(node)).qualifiers)  # type: ignore[arg-type]
        if not declarators(node):  # a bare struct declaration
            return
        _, declared = declared_variables(node)
        for name, type_, init in declared:
            if "uniform" in words:
                if name in SHADERTOY_INPUTS:
                    continue  # the shader declares what the host provides
                line = node.meta.line if not node.meta.empty else 0
                self.uniforms[name] = line
                zero = _zero(type_, frozenset({("uniform", name, line)}))
                state.declare(name, zero)
            elif init is not None and not ("in" in words or "out" in words):
                state.declare(name, self._init_value(type_, init, state))
            else:
                state.declare(name, unknown(type_))

    # --- calls ----------------------------------------------------------------------------

    def _evaluate(self, fn: _Fn, args: list[MV], entry: bool = False) -> tuple[MV, list[Event]]:
        key = (id(fn.node), tuple(None if a.comps is None else tuple(c if known(c) else None
                                  for c in a.comps) for a in args))  # fmt: skip
        if key in self._memo:
            ret, pending, _ = self._memo[key]
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
        frame = _Frame(fn)
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
        self._memo[key] = (ret, frame.pending, NO_TAGS)
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
            if _writes(qualifier):
                self._forget(arg, state)
        for g in self._global_writes(fn):
            if state.lookup(g) is not None:
                state.assign(g, unknown(state.lookup(g).type))  # type: ignore[union-attr]
        # each call returns its own unknowns: two calls of one memoised variant are not equal
        comps = tuple(c if known(c) else Sym() for c in ret.comps) if ret.comps else ret.comps
        return MV(ret.type, comps, ret_tags)

    def _global_writes(self, fn: _Fn) -> frozenset[str]:
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

    # --- statements -----------------------------------------------------------------------

    def block(self, statements: Iterable[Node], state: State) -> None:
        for stmt in statements:
            if state.dead:
                return
            self.statement(stmt, state)

    def statement(self, stmt: Node, state: State) -> None:
        if not isinstance(stmt, Tree) or state.dead:
            return
        kind = stmt.data
        if kind == "compound_statement":
            state.push()
            self.block(stmt.children, state)
            state.pop()
        elif kind == "declaration_statement":
            decl = first_child(stmt)  # the declaration
            if is_tree(decl, "variable_declaration") and declarators(decl):  # type: ignore[arg-type]
                for name, type_, init in declared_variables(decl)[1]:  # type: ignore[arg-type]
                    value = self._init_value(type_, init, state) if init is not None else None
                    state.declare(name, value or unknown(type_))
        elif kind == "expression_statement":
            self.expr(first_child(stmt), state)
        elif kind == "if_statement":
            self._if(stmt, state)
        elif kind == "for_statement":
            self._for(stmt, state)
        elif kind == "while_statement":
            loop = WhileStatement(stmt)
            cond = None if loop.declaration is not None else loop.condition
            self._loop(stmt, state, cond, None, loop.body)
        elif kind == "do_statement":
            self._loop(stmt, state, None, None, DoStatement(stmt).body)
        elif kind == "switch_statement":
            self._switch(stmt, state)
        elif kind == "jump_statement":
            word, returned = jump_parts(stmt)
            if word == "return" and returned is not None:
                value = self.expr(returned, state)
                self._stack[-1].returns.append(value.but(union(value.tags, state.control)))
            state.dead = True

    def _init_value(self, type_: str, init: Node, state: State) -> MV:
        value = self.expr(init, state)
        if size_of(type_) is None or value.comps is None:
            return MV(type_)
        return self._convert(type_, value, state)

    def _convert(self, type_: str, value: MV, state: State) -> MV:
        n = size_of(type_)
        if n is None or value.comps is None or len(value.comps) != n:
            return MV(type_, value.comps if value.comps and n == len(value.comps) else None)
        base = base_of(type_)
        comps = tuple(cast(base, c) for c in value.comps)
        return MV(type_, comps, union(value.tags, state.control))

    def _if(self, node: Tree, state: State) -> None:
        cond_node, then, other = if_parts(node)
        cond = self.expr(cond_node, state)
        truth = _truth(cond)
        if truth is not None:
            saved = state.control
            state.control = union(saved, cond.tags)
            if truth:
                self.statement(then, state)
            elif other is not None:
                self.statement(other, state)
            state.control = saved if not state.dead else state.control
            return
        a, b = state.copy(), state.copy()
        self.statement(then, a)
        if other is not None:
            self.statement(other, b)
        state.become(join_states(state, [a, b]))

    def _for(self, node: Tree, state: State) -> None:
        init, cond, update, body = for_parts(node)
        state.push()
        self.statement(init, state)
        self._loop(node, state, cond, update, body)
        state.pop()

    def _loop(self, node: Tree, state: State, cond: Node | None, update: Node | None,
              body: Node) -> None:  # fmt: skip
        """The first iteration of a loop, then what holds after it."""
        written = self.writes(node)
        inner = state.copy()
        if cond is not None and node.data != "do_statement":
            truth = _truth(self.expr(cond, inner))
            if truth is False:  # the body never runs
                return
        line = node.meta.line if not node.meta.empty else 0
        for name in written:
            value = inner.lookup(name)
            if value is not None and value.comps is not None and any(map(known, value.comps)):
                tag = ("loop", line, name, show(value))
                inner.assign(name, value.but(union(value.tags, frozenset({tag}))))
        inner.push()
        self.statement(body, inner)
        for name in written:
            value = state.lookup(name)
            if value is not None:
                state.assign(name, unknown(value.type))

    def _switch(self, node: Tree, state: State) -> None:
        switch = SwitchStatement(node)
        value = self.expr(switch.selector, state)
        written = self.writes(node)
        exact = value.comps[0] if value.comps and known(value.comps[0]) else None
        running: State | None = None
        for stmt in switch.body:
            if is_tree(stmt, "case_label", "default_label"):
                if running is None or running.dead:
                    label = (
                        self.expr(first_child(stmt), state)  # type: ignore[arg-type]
                        if stmt.data == "case_label"  # type: ignore[union-attr]
                        else None
                    )
                    hit = label is None or exact is None or (
                        label.comps is not None and label.comps[0] == exact)  # fmt: skip
                    if hit:
                        running = state.copy()
                        running.push()
                continue
            if running is not None and not running.dead:
                if is_tree(stmt, "jump_statement") and jump_parts(stmt)[0] == "break":  # type: ignore[arg-type]
                    running.dead = True
                    continue
                self.statement(stmt, running)
        for name in written:
            value = state.lookup(name)
            if value is not None:
                state.assign(name, unknown(value.type))

    def writes(self, node: Node) -> frozenset[str]:
        """The variables a statement may write (assignments, ++/--, out arguments)."""
        key = id(node)
        if key not in self._writes:
            names: set[str] = set()
            if isinstance(node, Tree):
                for sub in walk(node):
                    if sub.data == "assignment":
                        names.add(root_variable(first_child(sub)) or "")  # the target
                    elif sub.data in ("postfix", "prefix"):
                        names.add(root_variable(operand(sub)) or "")
                    elif sub.data == "call":
                        names.update(self._out_names(sub))
            names.discard("")
            self._writes[key] = frozenset(names)
        return self._writes[key]

    def _out_names(self, call: Tree) -> set[str]:
        name = callee_name(call)
        args = call_args(call)
        if name in ("modf", "frexp") and len(args) == 2:
            return {root_variable(args[1]) or ""}
        if name is None or name not in self.functions:
            return set()
        out = set()
        for fn in self.functions[name]:
            if len(fn.params) == len(args):
                for (qualifier, _, _), arg in zip(fn.params, args, strict=True):
                    if _writes(qualifier):
                        out.add(root_variable(arg) or "")
        return out

    # --- expressions ----------------------------------------------------------------------

    def expr(self, node: Node, state: State) -> MV:
        if isinstance(node, Token):
            return MV(None)
        kind = node.data
        handler = _HANDLERS.get(kind)
        if handler is None:
            return MV(None)
        return handler(self, node, state)

    def _float_literal(self, node: Tree, state: State) -> MV:
        text = leaf_text(node).rstrip("fF")
        try:
            value = f32(float(text))
        except ValueError:
            value = None
        return MV("float", (Sym() if value is None else value,))

    def _int_literal(self, node: Tree, state: State) -> MV:
        text = leaf_text(node)
        value = int_value(text)
        type_ = "uint" if text[-1:] in "uU" else "int"
        return MV(type_, (Sym() if value is None else value,))

    def _bool_literal(self, node: Tree, state: State) -> MV:
        return MV("bool", (leaf_text(node) == "true",))

    def _variable(self, node: Tree, state: State) -> MV:
        name = leaf_text(node)
        value = state.lookup(name)
        if value is not None:
            return value
        if name in FRAME_ZERO:
            type_ = FRAME_ZERO[name]
            return _zero(type_, frozenset({("frame", name)}))
        if name == "iMouse":
            return _zero("vec4", frozenset({("mouse",)}))
        if name in ("iResolution", "iChannelTime", "iChannelResolution", "iDate"):
            return unknown({"iResolution": "vec3", "iDate": "vec4"}.get(name, "float[4]"))
        return MV(None)

    def _sequence(self, node: Tree, state: State) -> MV:
        value = MV(None)
        for part in node.children:
            value = self.expr(part, state)
        return value

    def _ternary(self, node: Tree, state: State) -> MV:
        cond_node, if_true, if_false = ternary_parts(node)
        cond = self.expr(cond_node, state)
        truth = _truth(cond)
        if truth is not None:
            value = self.expr(if_true if truth else if_false, state)
            return value.but(union(value.tags, cond.tags))
        a, b = state.copy(), state.copy()
        va = self.expr(if_true, a)
        vb = self.expr(if_false, b)
        state.become(join_states(state, [a, b]))
        if va.type != vb.type and va.type and vb.type:
            return MV(va.type)
        return join_values([va, vb])

    def _unary(self, node: Tree, state: State) -> MV:
        op = operator(node)
        v = self.expr(operand(node), state)
        if v.comps is None:
            return MV(v.type)
        if op == "-":
            return _map(v, lambda c: -c if not isinstance(c, bool) else Sym())
        if op == "!":
            return _map(v, lambda c: not c if isinstance(c, bool) else Sym())
        if op == "~":
            return _map(
                v, lambda c: ~c if isinstance(c, int) and not isinstance(c, bool) else Sym()
            )
        return v

    def _prefix(self, node: Tree, state: State) -> MV:
        op, target = operator(node), operand(node)
        old = self.expr(target, state)
        new = _arith("+" if op == "++" else "-", old, MV("int", (1,)))
        new = self._convert(old.type, new, state) if old.type else new  # type: ignore[arg-type]
        self._store(target, new, state)
        return new

    def _postfix(self, node: Tree, state: State) -> MV:
        target, op = operand(node), operator(node)
        old = self.expr(target, state)
        new = _arith("+" if op == "++" else "-", old, MV("int", (1,)))
        new = self._convert(old.type, new, state) if old.type else new  # type: ignore[arg-type]
        self._store(target, new, state)
        return old

    def _binary(self, node: Tree, state: State) -> MV:
        left, op, right = binary_parts(node)
        a = self.expr(left, state)
        if op in ("&&", "||"):
            ta = _truth(a)
            if ta is not None and ta == (op == "||"):  # the right side is not evaluated
                return MV("bool", (ta,), a.tags)
            b = self.expr(right, state)
            tb = _truth(b)
            if ta is not None:
                return b.but(union(a.tags, b.tags))
            if tb is not None and tb == (op == "||"):
                return MV("bool", (tb,), b.tags)
            return MV("bool", (Sym(),))
        b = self.expr(right, state)
        if op in ("/", "%"):
            self._check_divisor(right, b, a, state)
        value = _binary_value(op, a, b)
        if op in _ORDERED and self.bounds is not None and _truth(value) is None:
            value = self._compare_bounds(op, left, a, right, b) or value
        return value

    def _compare_bounds(self, op: str, left: Node, a: MV, right: Node, b: MV) -> MV | None:
        """`x < c` with x unknown but its range on every run on one side of c."""
        if not a.exact() and b.exact() and b.comps and len(b.comps) == 1:
            lo, hi = self.bounds(left)  # type: ignore[misc]
            c = float(b.comps[0])  # type: ignore[arg-type]
        elif not b.exact() and a.exact() and a.comps and len(a.comps) == 1:
            lo, hi = self.bounds(right)  # type: ignore[misc]
            c = float(a.comps[0])  # type: ignore[arg-type]
            op = _FLIP[op]
        else:
            return None
        result = None
        if op == "<":
            result = False if lo >= c else (True if hi < c else None)
        elif op == "<=":
            result = False if lo > c else (True if hi <= c else None)
        elif op == ">":
            result = False if hi <= c else (True if lo > c else None)
        elif op == ">=":
            result = False if hi < c else (True if lo >= c else None)
        return None if result is None else MV("bool", (result,), union(a.tags, b.tags))

    def _check_divisor(self, divisor: Node, value: MV, numerator: MV, state: State) -> None:
        if value.has_zero() and base_of(value.type) != "bool":
            self.emit(Event("divide", divisor, value, numerator, union(value.tags, state.control)))

    def _assignment(self, node: Tree, state: State) -> MV:
        target, op, rhs = binary_parts(node)
        value = self.expr(rhs, state)
        if op != "=":
            old = self.expr(target, state)
            if op == "/=":
                self._check_divisor(rhs, value, old, state)
            value = _binary_value(op[:-1], old, value)
        target_type = self.expr(target, state).type
        if target_type and size_of(target_type) is not None and value.comps is not None:
            value = self._convert(target_type, value, state)
        elif state.control:
            value = value.but(union(value.tags, state.control))
        self._store(target, value, state)
        return value

    def _store(self, target: Node, value: MV, state: State) -> None:
        name = root_variable(target)
        if name is None:
            return
        old = state.lookup(name)
        if old is None:
            return
        if is_tree(target, "variable"):
            if old.type and value.type != old.type:
                value = MV(old.type, value.comps if size_of(old.type) and value.comps and
                           len(value.comps) == size_of(old.type) else None, value.tags)  # fmt: skip
                if value.comps is None and size_of(old.type):
                    value = unknown(old.type)
            state.assign(name, value)
            return
        base = first_child(target)  # type: ignore[arg-type]  # of a field or an index
        if is_tree(base, "variable") and old.comps is not None:
            slots: list[int] | None = None
            if is_tree(target, "field"):
                letters = field_parts(target)[1]  # type: ignore[arg-type]
                slots = list(T.swizzle_indices(letters) or [-1])
            elif is_tree(target, "index"):
                i = self.expr(index_parts(target)[1], state)  # type: ignore[arg-type]
                if i.comps and known(i.comps[0]) and isinstance(i.comps[0], int):
                    slots = [int(i.comps[0])]
            if slots and all(0 <= s < len(old.comps) for s in slots):
                comps = list(old.comps)
                new = value.comps if value.comps is not None else None
                for k, s in enumerate(slots):
                    if new is not None and len(new) == len(slots):
                        comps[s] = cast(base_of(old.type), new[k])
                    elif new is not None and len(new) == 1:
                        comps[s] = cast(base_of(old.type), new[0])
                    else:
                        comps[s] = Sym()
                state.assign(name, MV(old.type, tuple(comps), union(old.tags, value.tags)))
                return
        state.assign(name, unknown(old.type))

    def _forget(self, target: Node, state: State) -> None:
        name = root_variable(target)
        if name is not None and (old := state.lookup(name)) is not None:
            state.assign(name, unknown(old.type))

    def _field(self, node: Tree, state: State) -> MV:
        base, letters = field_parts(node)
        v = self.expr(base, state)
        if v.comps is None or size_of(v.type) is None:
            return MV(None)
        slots = list(T.swizzle_indices(letters) or [-1])  # -1: no swizzle
        if not all(0 <= s < len(v.comps) for s in slots) or len(slots) > 4:
            return MV(None)
        comps = tuple(v.comps[s] for s in slots)
        return MV(T.swizzle(v.type, letters), comps, v.tags)

    def _index(self, node: Tree, state: State) -> MV:
        base, index = index_parts(node)
        v = self.expr(base, state)
        i = self.expr(index, state)
        if v.comps is not None and size_of(v.type) and i.comps and known(i.comps[0]):
            k = i.comps[0]
            if isinstance(k, int) and 0 <= k < len(v.comps):
                return MV(T.element(v.type), (v.comps[k],), union(v.tags, i.tags))
        return unknown(T.element(v.type)) if T.element(v.type) else MV(None)

    def _constructor(self, node: Tree, state: State) -> MV:
        spec = TypeSpecifier(first_child(node))  # type: ignore[arg-type]
        type_ = str(spec.head)
        is_array = spec.array is not None
        args = [self.expr(a, state) for a in call_args(node)]
        n = size_of(type_)
        if is_array or n is None:
            return MV(type_ + ("[]" if is_array else ""))
        return _construct(type_, n, args)

    def _call(self, node: Tree, state: State) -> MV:
        name = callee_name(node)
        arg_nodes = call_args(node)
        if name is None:  # a method: v.length()
            head = first_child(node)  # the callee
            if is_tree(head, "field"):
                base, method = field_parts(head)  # type: ignore[arg-type]
                if method == "length":
                    self.expr(base, state)
            return unknown("int")
        args = [self.expr(a, state) for a in arg_nodes]
        if name in self.functions:
            return self._call_user(node, name, args, state)
        if name in BUILTIN_FUNCTIONS:
            self._check_builtin(node, name, arg_nodes, args, state)
            return _builtin(name, args)
        if size_of(name) is not None:  # a constructor the parser saw as a call
            return _construct(name, size_of(name), args)  # type: ignore[arg-type]
        return MV(name if name[:1].isupper() else None)

    def _check_builtin(self, call: Tree, name: str, nodes: list[Node], args: list[MV],
                       state: State) -> None:  # fmt: skip
        control = state.control
        if name == "mod" and len(args) == 2 and args[1].has_zero():
            self.emit(Event("mod", nodes[1], args[1], args[0], union(args[1].tags, control)))
        elif name == "atan" and len(args) == 2:
            y, x = args
            if y.comps and x.comps and any(
                known(a) and known(b) and a == 0 and b == 0
                for a, b in zip(_broadcast(y.comps, x.comps), _broadcast(x.comps, y.comps),
                                strict=False)):  # fmt: skip
                self.emit(Event("atan", call, x, y, union(y.tags, x.tags, control)))
        elif name in DOMAIN_BUILTINS and args and args[0].comps is not None:
            x = args[0]
            comps = [c for c in x.comps if known(c)]  # type: ignore[union-attr]
            bad = False
            other = args[1] if len(args) > 1 else None
            if name == "sqrt":
                bad = any(c < 0 for c in comps)
            elif name in ("log", "log2", "inversesqrt"):
                bad = any(c <= 0 for c in comps)
            elif name in ("acos", "asin"):
                bad = any(abs(c) > 1 for c in comps)
            elif name == "normalize":
                bad = x.exact() and all(c == 0 for c in comps)
            elif name == "pow" and other is not None and other.comps is not None:
                ys = _broadcast(other.comps, x.comps)  # type: ignore[arg-type]
                for c, y in zip(_broadcast(x.comps, other.comps), ys, strict=False):  # type: ignore[arg-type]
                    if known(c) and (c < 0 or (c == 0 and known(y) and y <= 0)):
                        bad = True
            if bad:
                tags = union(x.tags, other.tags if name == "pow" and other else NO_TAGS, control)
                self.emit(Event(name, nodes[0], x, other, tags))


_HANDLERS: dict[str, Callable[[Moments, Tree, State], MV]] = {
    "float_literal": Moments._float_literal,
    "int_literal": Moments._int_literal,
    "bool_literal": Moments._bool_literal,
    "variable": Moments._variable,
    "sequence": Moments._sequence,
    "ternary": Moments._ternary,
    "unary": Moments._unary,
    "prefix": Moments._prefix,
    "postfix": Moments._postfix,
    "binary": Moments._binary,
    "assignment": Moments._assignment,
    "field": Moments._field,
    "index": Moments._index,
    "constructor": Moments._constructor,
    "call": Moments._call,
}


# --- values -------------------------------------------------------------------------------


def _writes(qualifier: str) -> bool:
    """Whether a parameter of these qualifiers is written back to its argument."""
    return any(word in ("out", "inout") for word in qualifier.split())


def _zero(type_: str, tags: frozenset) -> MV:
    n = size_of(type_)
    if n is None:
        return MV(type_, None, tags)
    base = base_of(type_)
    zero: Comp = 0.0 if base == "float" else (0 if base == "int" else False)
    return MV(type_, (zero,) * n, tags)


def _truth(v: MV) -> bool | None:
    if v.comps and len(v.comps) == 1 and known(v.comps[0]):
        return bool(v.comps[0])
    return None


def _map(v: MV, fn: Callable[[Comp], Comp]) -> MV:
    assert v.comps is not None
    base = base_of(v.type)
    comps = tuple(cast(base, fn(c)) if known(c) else Sym() for c in v.comps)
    return MV(v.type, comps, v.tags)


def _broadcast(a: tuple[Comp, ...], b: tuple[Comp, ...]) -> tuple[Comp, ...]:
    return a * len(b) if len(a) == 1 and len(b) > 1 else a


def _construct(type_: str, n: int, args: list[MV]) -> MV:
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


def _result_type(a: MV, b: MV) -> str | None:
    ta, tb = a.type, b.type
    if ta and ta.startswith("mat") or tb and tb.startswith("mat"):
        return None
    na, nb = size_of(ta), size_of(tb)
    if na is None or nb is None:
        return None
    base = "float" if "float" in (T.element_type(ta), T.element_type(tb)) else T.element_type(ta)
    return vector_type(base, max(na, nb))


_ORDERED = frozenset({"<", "<=", ">", ">="})
_FLIP = {"<": ">", "<=": ">=", ">": "<", ">=": "<="}


def _binary_value(op: str, a: MV, b: MV) -> MV:
    if op in ("<", ">", "<=", ">=", "==", "!=", "^^"):
        return _compare(op, a, b)
    return _arith(op, a, b)


def _compare(op: str, a: MV, b: MV) -> MV:
    tags = union(a.tags, b.tags)
    if not (a.exact() and b.exact()) or a.comps is None or b.comps is None:
        return MV("bool", (Sym(),))
    x, y = a.comps, b.comps
    if op == "==":
        return MV("bool", (x == y,), tags)
    if op == "!=":
        return MV("bool", (x != y,), tags)
    if len(x) != 1 or len(y) != 1:
        return MV("bool", (Sym(),))
    p, q = x[0], y[0]
    result = {
        "<": lambda: p < q,  # type: ignore[operator]
        ">": lambda: p > q,  # type: ignore[operator]
        "<=": lambda: p <= q,  # type: ignore[operator]
        ">=": lambda: p >= q,  # type: ignore[operator]
        "^^": lambda: bool(p) != bool(q),
    }[op]()
    return MV("bool", (result,), tags)


def _arith(op: str, a: MV, b: MV) -> MV:
    type_ = _result_type(a, b)
    if type_ is None or a.comps is None or b.comps is None:
        n = size_of(type_)
        if type_ is None:
            # a matrix times a vector is a vector of its size; anything else is not followed
            vec = next((v.type for v in (a, b) if v.type and v.type.startswith("vec")), None)
            mat = any(v.type and v.type.startswith("mat") for v in (a, b))
            return unknown(vec) if mat and vec else MV(None)
        return unknown(type_) if n else MV(type_)
    x, y = _broadcast(a.comps, b.comps), _broadcast(b.comps, a.comps)
    if len(x) != len(y):
        return unknown(type_)
    base = base_of(type_)
    comps: list[Comp] = []
    zero_tags: frozenset | None = None
    for p, q in zip(x, y, strict=True):
        comps.append(_op(op, p, q, base))
        if op == "*" and known(comps[-1]) and comps[-1] == 0 and not (known(p) and known(q)):
            zero_tags = b.tags if known(q) else a.tags
    tags = union(a.tags, b.tags)
    if zero_tags is not None and len(comps) == 1:  # x * 0.0 is 0 whatever x is
        tags = zero_tags
    return MV(type_, tuple(comps), tags)


def _op(op: str, p: Comp, q: Comp, base: str) -> Comp:
    kp, kq = known(p), known(q)
    if not (kp and kq):
        # identities that hold for any value: x + 0, x - 0, x * 1, x / 1, x - x, x * 0
        if op in ("+", "-") and kq and q == 0:
            return p
        if op == "+" and kp and p == 0:
            return q
        if op in ("*", "/") and kq and q == 1:
            return p
        if op == "*" and kp and p == 1:
            return q
        if op == "-" and p is q:
            return 0.0 if base == "float" else 0
        if op == "*" and ((kp and p == 0) or (kq and q == 0)) and base == "int":
            return 0
        return Sym()
    try:
        if op == "+":
            r = p + q  # type: ignore[operator]
        elif op == "-":
            r = p - q  # type: ignore[operator]
        elif op == "*":
            r = p * q  # type: ignore[operator]
        elif op == "/":
            if q == 0:
                return Sym()
            if base == "int":
                r = abs(int(p)) // abs(int(q)) * (1 if (p < 0) == (q < 0) else -1)  # type: ignore[operator]
            else:
                r = p / q  # type: ignore[operator]
        elif op == "%" and base == "int":
            if q == 0:
                return Sym()
            r = math.fmod(int(p), int(q))  # type: ignore[arg-type]
        elif base == "int" and op in ("<<", ">>", "&", "|", "^"):
            r = {"<<": lambda: p << q, ">>": lambda: p >> q, "&": lambda: p & q,  # type: ignore[operator]
                 "|": lambda: p | q, "^": lambda: p ^ q}[op]()  # type: ignore[operator]  # fmt: skip
        else:
            return Sym()
    except (ArithmeticError, ValueError, TypeError):
        return Sym()
    return cast(base, r)


# --- builtins -----------------------------------------------------------------------------


def _float1(fn: Callable[[float], float]) -> Callable[[float], Comp]:
    def run(x: float) -> Comp:
        try:
            return fn(x)
        except (ArithmeticError, ValueError):
            return Sym()

    return run


def _fract(x: float) -> float:
    return x - math.floor(x)


def _mod(x: float, y: float) -> Comp:
    if y == 0:
        return Sym()
    return x - y * math.floor(x / y)


def _clamp(x: float, lo: float, hi: float) -> float:
    return min(max(x, lo), hi)


def _mix(x: float, y: float, a: float) -> float:
    return x * (1 - a) + y * a


def _step(edge: float, x: float) -> float:
    return 0.0 if x < edge else 1.0


def _smoothstep(e0: float, e1: float, x: float) -> Comp:
    if e0 == e1:
        return Sym()
    t = _clamp((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3 - 2 * t)


def _sign(x: float) -> float:
    return 1.0 if x > 0 else (-1.0 if x < 0 else 0.0)


def _pow(x: float, y: float) -> Comp:
    if x < 0 or (x == 0 and y <= 0):
        return Sym()
    return x**y


_UNARY: dict[str, Callable[[float], Comp]] = {
    "sin": _float1(math.sin),
    "cos": _float1(math.cos),
    "tan": _float1(math.tan),
    "asin": _float1(math.asin),
    "acos": _float1(math.acos),
    "sinh": _float1(math.sinh),
    "cosh": _float1(math.cosh),
    "tanh": _float1(math.tanh),
    "exp": _float1(math.exp),
    "exp2": _float1(lambda x: 2.0**x),
    "log": _float1(math.log),
    "log2": _float1(math.log2),
    "sqrt": _float1(math.sqrt),
    "inversesqrt": _float1(lambda x: 1 / math.sqrt(x)),
    "abs": abs,
    "sign": _sign,
    "floor": _float1(math.floor),
    "ceil": _float1(math.ceil),
    "trunc": _float1(math.trunc),
    "round": _float1(lambda x: math.floor(x + 0.5)),
    "fract": _float1(_fract),
    "radians": lambda x: x * math.pi / 180,
    "degrees": lambda x: x * 180 / math.pi,
}
_COMPONENTWISE: dict[str, Callable[..., Comp]] = {
    "mod": _mod,
    "min": min,
    "max": max,
    "clamp": _clamp,
    "mix": _mix,
    "step": _step,
    "smoothstep": _smoothstep,
    "pow": _pow,
}
# The type of a builtin's result where it is not the type of its first argument.
_SCALAR_RESULT = frozenset({"length", "distance", "dot"})
_VEC4_RESULT = frozenset(
    {"texture", "texture2D", "textureLod", "texelFetch", "textureGrad", "textureCube",
     "textureProj", "textureOffset", "textureProjLod", "texelFetchOffset", "textureLodOffset"}
)  # fmt: skip


def _builtin(name: str, args: list[MV]) -> MV:
    if name in _VEC4_RESULT:
        return unknown("vec4")
    if not args:
        return MV(None)
    tags = union(*(a.tags for a in args))
    first = args[0]
    if name in _SCALAR_RESULT:
        return _reduce(name, args, tags)
    if name == "cross" and len(args) == 2:
        return _cross(args[0], args[1], tags)
    if name == "normalize":
        return unknown(first.type)
    if name in ("atan",) and len(args) == 2:
        return _componentwise(
            lambda y, x: Sym() if x == 0 and y == 0 else math.atan2(y, x), args, tags
        )
    if name == "atan":
        return _componentwise(_float1(math.atan), args, tags)
    if name in _UNARY and len(args) == 1:
        return _componentwise(_UNARY[name], args, tags)
    if name in _COMPONENTWISE:
        return _componentwise(_COMPONENTWISE[name], args, tags, mix_bool=name == "mix")
    if name in ("isnan", "isinf", "lessThan", "greaterThan", "equal", "notEqual",
                "lessThanEqual", "greaterThanEqual", "any", "all", "not"):  # fmt: skip
        n = size_of(first.type) or 1
        return unknown("bool" if name in ("any", "all", "isnan", "isinf") and n == 1 or
                       name in ("any", "all") else vector_type("bool", n))  # fmt: skip
    if size_of(first.type) is not None and name not in ("modf", "frexp"):
        return unknown(first.type)
    return MV(None)


def _componentwise(fn: Callable[..., Comp], args: list[MV], tags: frozenset,
                   mix_bool: bool = False) -> MV:  # fmt: skip
    sizes = [size_of(a.type) for a in args]
    if any(s is None for s in sizes) or any(a.comps is None for a in args):
        n = max((s or 0) for s in sizes) if all(sizes) else 0
        return unknown(vector_type("float", n)) if n else MV(None)
    n = max(sizes)  # type: ignore[type-var]
    base = "int" if all(base_of(a.type) == "int" for a in args) else "float"
    if mix_bool:
        base = base_of(args[0].type) if base_of(args[0].type) != "bool" else "float"
    type_ = vector_type(base, n)  # type: ignore[arg-type]
    lanes = [a.comps * n if len(a.comps) == 1 else a.comps for a in args]  # type: ignore[operator]
    if any(len(lane) != n for lane in lanes):
        return unknown(type_)
    comps: list[Comp] = []
    for i in range(n):  # type: ignore[arg-type]
        xs = [lane[i] for lane in lanes]
        if all(known(x) for x in xs):
            try:
                value = fn(*(float(x) if base == "float" else x for x in xs))
            except (ArithmeticError, ValueError, TypeError):
                value = Sym()
            comps.append(cast(base, value))
        else:
            comps.append(Sym())
    return MV(type_, tuple(comps), tags)


def _reduce(name: str, args: list[MV], tags: frozenset) -> MV:
    if any(a.comps is None or not a.exact() for a in args):
        return unknown("float")
    if name == "length":
        value = math.sqrt(sum(float(c) ** 2 for c in args[0].comps))  # type: ignore[union-attr]
    elif len(args) != 2 or len(args[0].comps) != len(args[1].comps):  # type: ignore[arg-type]
        return unknown("float")
    elif name == "distance":
        value = math.sqrt(sum((float(p) - float(q)) ** 2 for p, q in  # type: ignore[arg-type]
                              zip(args[0].comps, args[1].comps, strict=True)))  # type: ignore[arg-type]  # fmt: skip
    else:
        value = sum(float(p) * float(q) for p, q in zip(args[0].comps, args[1].comps, strict=True))  # type: ignore[arg-type]
    return MV("float", (cast("float", value),), tags)


def _cross(a: MV, b: MV, tags: frozenset) -> MV:
    if not (a.exact() and b.exact()) or len(a.comps or ()) != 3 or len(b.comps or ()) != 3:
        return unknown("vec3")
    x1, y1, z1 = (float(c) for c in a.comps)  # type: ignore[union-attr]
    x2, y2, z2 = (float(c) for c in b.comps)  # type: ignore[union-attr]
    comps = (y1 * z2 - z1 * y2, z1 * x2 - x1 * z2, x1 * y2 - y1 * x2)
    return MV("vec3", tuple(cast("float", c) for c in comps), tags)


# --- the API ------------------------------------------------------------------------------


def moments(ctx: LintContext) -> Moments | None:
    """The first-path events of the file (computed once per file); None without a tree or
    where the file nests deeper than the evaluation can follow."""
    return ctx.memo(_first_path)


def _first_path(ctx: LintContext) -> Moments | None:
    if ctx.tree is None:
        return None
    try:
        return Moments(ctx.tree, _bounds(ctx))
    except RecursionError:
        return None


def _bounds(ctx: LintContext) -> Callable[[Node], tuple[float, float]]:
    from .model import semantic_model  # the model is built only where a comparison asks

    def bounds(node: Node) -> tuple[float, float]:
        r = semantic_model(ctx).range_of(node)
        return r.lo, r.hi

    return bounds
