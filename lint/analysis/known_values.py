"""Values the data-flow analysis (flow.py) knows where it stands: for each local variable, the
expression it was last given on the path being analysed, with ranges per component evaluated
from it. They decide conditions the semantic model's ranges alone cannot, because the model
holds a range for every run (a loop widens what it assigns) while a value set just before a
loop holds exactly on its first iteration:

    float t = 0.0, h = 1.0;
    for (int i = 0; i < 64; i++) { if (h < 0.001 || t > 10.0) break; h = map(p, m); ... }

(the first iteration never breaks, so `m` is written), and

    float md = 8.0; vec2 mr;
    for (...) { vec2 r = g + o - f; float d = max(abs(r.x), abs(r.y)); if (d < md) mr = r; }

(with the counters at their start, d is below 8, so the first iteration writes `mr`).

A value is the expression node itself, stored at a declaration or a statement-level `x = e;`
and evaluated when a condition asks. It is dropped when the variable is written again, when its
scope ends, and, for a value stored inside a branch, when the branch ends; the flow analysis
drops everything a loop may write before it analyses the iterations after the first, and after
the body. A value whose expression reads a variable written since it was stored no longer holds
(a clock of writes, checked when it is asked for). An expression or variable without a stored
value is the model's range of that node, which holds on every run. Each question walks the
stored expressions to a fixed depth and a fixed number of nodes, and the flow analysis asks only
at a loop's first test and inside the first pass of a loop, so the cost stays linear.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from lark import Token, Tree

from glint.compiler.glsl.ast import (
    Constructor,
    binary_parts,
    field_name,
    first_child,
    operand,
    operator,
    token_text,
    variable_name,
)

from ..context import Node
from .ranges import Interval, fract_range
from .syntax import call_args, callee_name, int_value, names_in

Comps = tuple[Interval, ...]  # one range per component (a scalar has one)

_DEPTH = 8  # stored values followed through, one inside another
_BUDGET = 200  # nodes evaluated per question, beyond which the model's ranges answer
_COMPARE = ("<", "<=", ">", ">=")
_VECTORS = {f"{p}vec{n}": n for p in ("", "i", "u") for n in (2, 3, 4)}
_SWIZZLES = ("xyzw", "rgba", "stpq")


class KnownValues:
    """The values of locals on the path being analysed (see the module docstring)."""

    def __init__(
        self,
        fallback: Callable[[Node], Comps | None],
        structs: dict[str, tuple[str, ...]],
    ) -> None:
        self.fallback = fallback  # the model's ranges of a node (on every run)
        self.structs = structs  # struct name -> its members, for `Ray(o, d, 0.0).len`
        # name -> (its expression, when it was stored); `when` counts writes
        self.values: dict[str, tuple[Node, int]] = {}
        self.written: dict[str, int] = {}  # name -> when it was last written
        self.clock = 0
        self.log: list[str] = []  # names stored, in order: a branch drops its own at its end
        self.memo: dict[str, Comps | None] = {}  # the stored values evaluated for a question
        # for one question: names given a value (a counter at some iteration), names whose
        # stored value does not hold there (the model's range answers)
        self.given: dict[str, float] = {}
        self.hidden: set[str] | frozenset[str] = frozenset()

    # --- keeping them -------------------------------------------------------------------------

    def store(self, name: str, value: Node) -> None:
        self.drop(name)
        self.values[name] = (value, self.clock)
        self.log.append(name)

    def drop(self, name: str) -> None:
        """`name` is written: its value no longer holds, nor do the values computed from it
        (checked when one is asked for: see `value`)."""
        self.values.pop(name, None)
        self.clock += 1
        self.written[name] = self.clock

    def value(self, name: str) -> Node | None:
        """The stored expression of `name`, if every name it reads still holds the value it
        had when it was stored (and it does not read `name` itself: `t = t + h` means the old
        t, which no longer holds)."""
        entry = self.values.get(name)
        if entry is None:
            return None
        node, when = entry
        reads = names_in(node)
        if name in reads or any(self.written.get(read, -1) > when for read in reads):
            del self.values[name]
            return None
        return node

    def stored_before(self, name: str, clock: int) -> bool:
        """Whether `name`'s stored value (if any) was stored before the clock read `clock`."""
        entry = self.values.get(name)
        return entry is not None and entry[1] <= clock

    def mark(self) -> int:
        return len(self.log)

    def drop_since(self, mark: int) -> None:
        """The end of a branch: what it stored holds only inside it."""
        for name in self.log[mark:]:
            self.drop(name)
        del self.log[mark:]

    def clear(self) -> None:
        self.values.clear()
        self.written.clear()
        self.log.clear()

    # --- asking -------------------------------------------------------------------------------

    def truth(
        self,
        cond: Node,
        given: dict[str, float] | None = None,
        hidden: set[str] | frozenset[str] = frozenset(),
    ) -> bool | None:
        """Whether a comparison holds here, from the stored values of the variables it reads;
        None when they do not decide it (or it reads none). `given`: names taken to have these
        values; `hidden`: names whose stored values are not to be used."""
        if not (isinstance(cond, Tree) and cond.data == "binary"):
            return None
        left, op, right = binary_parts(cond)
        if op not in _COMPARE or not (self.values or given):
            return None
        self.memo = {}
        self.given, self.hidden = given or {}, hidden
        budget = [_BUDGET]
        try:
            a = self.eval(left, 0, budget)
            b = self.eval(right, 0, budget)
        finally:
            self.given, self.hidden = {}, frozenset()
        if a is None or b is None or len(a) != 1 or len(b) != 1:
            return None
        x, y = a[0], b[0]
        if x.lo > x.hi or y.lo > y.hi:
            return None
        if op in (">", ">="):
            x, y, op = y, x, {">": "<", ">=": "<="}[op]
        if op == "<":
            return True if x.hi < y.lo else False if x.lo >= y.hi else None
        return True if x.hi <= y.lo else False if x.lo > y.hi else None

    def eval(self, node: Node, depth: int, budget: list[int]) -> Comps | None:
        """Ranges of the components of an expression where it stands."""
        budget[0] -= 1
        if not isinstance(node, Tree) or budget[0] < 0 or depth > _DEPTH:
            return self.fallback(node) if isinstance(node, Tree) else None
        kind = node.data
        if kind in ("float_literal", "int_literal"):
            return _literal(node)
        if kind == "variable":
            name = variable_name(node)
            if name in self.given:
                return (Interval.point(self.given[name]),)
            if name in self.hidden:
                return self.fallback(node)
            if name not in self.memo:  # `r.x` and `r.y` evaluate r once
                stored = self.value(name)
                if stored is None:
                    return self.fallback(node)
                self.memo[name] = self.eval(stored, depth + 1, budget)
            return self.memo[name]
        elif kind == "field":
            got = self.member(node, depth, budget)
            if got is not None:
                return got
        elif kind == "unary" and operator(node) == "-":
            inner = self.eval(operand(node), depth, budget)
            if inner is not None:
                return tuple(-c for c in inner)
        elif kind == "binary" and operator(node) in ("+", "-", "*"):
            got = self.arithmetic(node, depth, budget)
            if got is not None:
                return got
        elif kind in ("call", "constructor"):
            got = self.call(node, depth, budget)
            if got is not None:
                return got
        return self.fallback(node)

    def member(self, node: Tree, depth: int, budget: list[int]) -> Comps | None:
        """`s.m` of a struct built by its constructor, or a swizzle of a vector."""
        base, name = first_child(node), field_name(node)
        base_name = variable_name(base)
        if base_name is not None and base_name not in self.hidden:
            stored = self.value(base_name)
            if isinstance(stored, Tree) and stored.data == "constructor":
                members = self.structs.get(_called(stored) or "")
                args = call_args(stored)
                if members is not None and name in members and len(args) == len(members):
                    return self.eval(args[members.index(name)], depth + 1, budget)
        whole = self.eval(base, depth, budget)
        if whole is None:
            return None
        for letters in _SWIZZLES:
            if all(c in letters for c in name) and len(name) <= 4:
                picked = [letters.index(c) for c in name]
                if all(i < len(whole) for i in picked) and len(whole) > 1:
                    return tuple(whole[i] for i in picked)
        return None

    def arithmetic(self, node: Tree, depth: int, budget: list[int]) -> Comps | None:
        left, op, right = binary_parts(node)
        a = self.eval(left, depth, budget)
        b = self.eval(right, depth, budget)
        if a is None or b is None or (len(a) != len(b) and 1 not in (len(a), len(b))):
            return None
        n = max(len(a), len(b))
        a, b = a * n if len(a) == 1 else a, b * n if len(b) == 1 else b
        if op == "+":
            return tuple(x + y for x, y in zip(a, b, strict=True))
        if op == "-":
            return tuple(x - y for x, y in zip(a, b, strict=True))
        if _same(left, right):  # x * x is never negative
            return tuple(x.square() for x in a)
        return tuple(x * y for x, y in zip(a, b, strict=True))

    def call(self, node: Tree, depth: int, budget: list[int]) -> Comps | None:
        """Vector constructors and the few builtins that keep a range tight."""
        name = _called(node)
        args = [self.eval(arg, depth, budget) for arg in call_args(node)]
        if name is None or any(a is None for a in args):
            return None
        values: list[Comps] = args  # type: ignore[assignment]
        if name in _VECTORS:
            flat = [c for a in values for c in a]
            width = _VECTORS[name]
            if len(values) == 1 and len(flat) == 1:
                return tuple(flat) * width
            return tuple(flat[:width]) if len(flat) >= width else None
        if name == "float" and len(values) == 1 and len(values[0]) == 1:
            return values[0]
        if name == "abs" and len(values) == 1:
            return tuple(c.abs() for c in values[0])
        if name == "fract" and len(values) == 1:
            return tuple(fract_range(c) for c in values[0])
        if name in ("min", "max") and len(values) == 2:
            a, b = values
            if len(a) != len(b) and len(b) != 1:
                return None
            b = b * len(a) if len(b) == 1 else b
            pick = Interval.min if name == "min" else Interval.max
            return tuple(pick(x, y) for x, y in zip(a, b, strict=True))
        if name == "dot" and len(values) == 2 and len(values[0]) == len(values[1]):
            args_nodes = call_args(node)
            same = _same(args_nodes[0], args_nodes[1])
            terms = [x.square() if same else x * y for x, y in zip(*values, strict=True)]
            total = terms[0]
            for term in terms[1:]:
                total = total + term
            return (total,)
        return None


def _called(node: Tree) -> str | None:
    """The function a call names, or the type a constructor builds (`vec2`, a struct)."""
    if node.data == "call":
        return callee_name(node)
    spec = Constructor(node).type
    head = spec.head if spec.array is None else None  # `float[2](...)` builds an array
    return str(head) if isinstance(head, Token) else None


def _literal(node: Tree) -> Comps | None:
    text = token_text(node).rstrip("fFuU")  # type: ignore[union-attr]
    try:
        value = float(text) if node.data == "float_literal" else int_value(text)
    except ValueError:
        return None
    if value is None or not math.isfinite(float(value)):
        return None
    return (Interval.point(float(value)),)


def _same(a: Node, b: Node) -> bool:
    """The same variable (or swizzle of one) on both sides: `r*r`, `dot(r, r)`."""
    while isinstance(a, Tree) and isinstance(b, Tree) and a.data == b.data == "field":
        if field_name(a) != field_name(b):
            return False
        a, b = first_child(a), first_child(b)
    name = variable_name(a)
    return name is not None and name == variable_name(b)
