"""Which values of a loop body (or of a function body called many times) are the same on every
pass: a data-flow closure over the writes of the region. A variable written in the region but
declared outside it carries a value from one pass to the next and varies; so do the parameters
of a function across its calls, and globals that some function called from the region writes.
Everything whose value is computed from varying names, or whose write is guarded by a condition
that reads one, varies too; the rest is computed alike on every pass.

Also a rough cost of the work under a node (ALU operations, a texture fetch as 20, a loop as
its trip count times its body, a call of the file's own function as its body), and whether the
work is of a kind compilers do not move out of loops (a texture fetch, a loop)."""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Iterable
from dataclasses import dataclass, field

from lark import Tree

from glint.compiler.glsl.ast import (
    ConditionDeclaration,
    Declarator,
    ForStatement,
    SwitchStatement,
    binary_parts,
    declarator_initializer,
    if_parts,
    jump_parts,
    loop_condition,
    loop_parts,
    operand,
    ternary_parts,
    variable_name,
)
from glint.compiler.glsl.types import CONSTRUCTIBLE

from ..context import LintContext, Node, walk
from .functions import Function
from .syntax import call_args, call_name, names_in, root_var

LOOPS = ("for_statement", "while_statement", "do_statement")

# Token for the effect of a call whose function writes globals: never the same on every pass.
IMPURE = "<impure>"

# Builtins with a cost above one ALU operation (rough issue slots on current GPUs).
_TRANSCENDENTAL = {
    "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh", "acosh",
    "atanh", "pow", "exp", "exp2", "log", "log2",
}  # fmt: skip
_ROOTS = {"sqrt", "inversesqrt", "length", "distance", "normalize", "reflect", "refract"}
_FETCH_COST = 20  # a texture fetch: memory latency that the ALU rarely hides in a loop
_UNKNOWN_CALL_COST = 8  # a function of another tab (Common): a hash or a noise, typically

# The trip count of a loop whose bound the code does not state (a march).
UNKNOWN_TRIPS = 64


def is_fetch(name: str | None) -> bool:
    """A texture fetch builtin (texture, textureLod, texelFetch, texture2D, ...)."""
    return bool(name) and (
        (name.startswith("texture") and not name.startswith(("textureSize", "textureQuery")))
        or name.startswith("texel")  # type: ignore[union-attr]
    )


def _builtin_cost(name: str) -> int:
    if is_fetch(name):
        return _FETCH_COST
    if name in _TRANSCENDENTAL:
        return 4
    if name in _ROOTS:
        return 3
    if name in ("inverse", "determinant"):
        return 20
    return 1


@dataclass
class Program:
    """Per-file facts about the file's functions: cost, whether they fetch or loop, and which
    globals they read and write, callees included."""

    ctx: LintContext
    overloads: dict[str, list[Function]]  # every definition of each name
    globals: set[str]  # non-constant, non-uniform globals
    trips: object  # callable (loop, fn) -> int
    _cost: dict[str, int] = field(default_factory=dict)
    _sticky: dict[str, bool] = field(default_factory=dict)
    _reads: dict[str, frozenset[str]] = field(default_factory=dict)
    _writes: dict[str, frozenset[str]] = field(default_factory=dict)

    @property
    def defined(self) -> dict[str, list[Function]]:
        return self.overloads

    # --- per function, callees included (memoised; GLSL has no recursion, guarded anyway) --

    def function_cost(self, name: str) -> int:
        if name not in self.defined:
            return _UNKNOWN_CALL_COST
        if name not in self._cost:
            self._cost[name] = _UNKNOWN_CALL_COST  # a recursion guard
            self._cost[name] = max(self.cost(fn.body, fn) for fn in self.defined[name])
        return self._cost[name]

    def function_sticky(self, name: str) -> bool:
        """Whether the function fetches a texture or loops (itself or in a callee)."""
        if name not in self.defined:
            return False
        if name not in self._sticky:
            self._sticky[name] = False
            self._sticky[name] = any(self.sticky(fn.body) for fn in self.defined[name])
        return self._sticky[name]

    def global_reads(self, name: str) -> frozenset[str]:
        return self._closure(name, self._reads, lambda fn: names_in(fn.body))

    def global_writes(self, name: str) -> frozenset[str]:
        return self._closure(name, self._writes, lambda fn: fn.written)

    def _closure(self, name: str, memo: dict[str, frozenset[str]], own: object) -> frozenset[str]:
        if name not in self.defined:
            return frozenset()
        if name not in memo:
            memo[name] = frozenset()
            found: set[str] = set()
            for fn in self.defined[name]:  # overloads: what any of them does
                mine = set(own(fn)) - set(fn.locals) - set(fn.params)  # type: ignore[operator]
                found |= mine & self.globals
                for call in walk(fn.body):
                    if call.data == "call" and (callee := call_name(call)) in self.defined:
                        found |= self._closure(callee, memo, own)  # type: ignore[arg-type]
            memo[name] = frozenset(found)
        return memo[name]

    # --- per node ---------------------------------------------------------------------------

    def cost(self, node: Node, fn: Function | None) -> int:
        """Operations the node runs, loops multiplied by their trip counts."""
        total = 0
        stack: list[tuple[Node, int]] = [(node, 1)]
        while stack:
            item, times = stack.pop()
            if not isinstance(item, Tree):
                continue
            kind = item.data
            if kind == "call":
                name = call_name(item)
                if name in self.defined:
                    total += times * self.function_cost(name)
                elif name is not None and name[:1].islower() and name not in CONSTRUCTIBLE:
                    total += times * (_builtin_cost(name) if _is_builtin(name)
                                      else _UNKNOWN_CALL_COST)  # fmt: skip
                stack += [(c, times) for c in call_args(item)]
                continue
            if kind in LOOPS:
                trips = self.trips(item, fn) if fn is not None else UNKNOWN_TRIPS  # type: ignore[operator]
                if kind == "for_statement":
                    stack.append((ForStatement(item).init, times))  # runs once
                stack += [(c, times * max(1, trips)) for c in loop_parts(item)]
                continue
            if kind in ("binary", "unary", "prefix", "postfix", "assignment", "ternary"):
                total += times
            stack += [(c, times) for c in item.children]
        return total

    def sticky(self, node: Node) -> bool:
        """Whether the node fetches a texture or loops, itself or in a function it calls:
        work that compilers do not move out of a loop."""
        for sub in walk(node):
            if sub.data in LOOPS:
                return True
            if sub.data == "call":
                name = call_name(sub)
                if is_fetch(name) and name not in self.defined:
                    return True
                if name in self.defined and self.function_sticky(name):  # type: ignore[arg-type]
                    return True
        return False

    def reads(self, node: Node) -> set[str]:
        """The names the node's value depends on: its variables and the globals its calls read
        (IMPURE when a call writes globals)."""
        found = names_in(node)
        if isinstance(node, Tree):
            for call in walk(node):
                if call.data == "call" and (name := call_name(call)) in self.defined:
                    found |= self.global_reads(name)  # type: ignore[arg-type]
                    if self.global_writes(name):  # type: ignore[arg-type]
                        found.add(IMPURE)
        return found


def _is_builtin(name: str) -> bool:
    from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

    return name in BUILTIN_FUNCTIONS


@dataclass
class Write:
    """One write of a function: its target, what its value depends on (reads: names, and the
    guard that decides whether it runs), where it is, and whether it declares the target.
    Guards are writes too, of pseudo-names `#<id>`: an if, switch or ternary's guard reads its
    condition and the enclosing guard; a loop's guard reads its condition, the enclosing guard
    and the guards of the ifs that break out of it (its number of passes depends on them)."""

    target: str
    reads: frozenset[str]
    pos: int
    declares: bool = False


@dataclass
class Flow:
    """Every write of a function in source order, with the global writes of its calls."""

    writes: list[Write]
    positions: list[int]  # of the writes, for bisect
    call_writes: list[tuple[int, frozenset[str]]]  # (position, globals the call writes)
    loop_guard: dict[int, str]  # id(loop) -> its guard's pseudo-name
    exits: list[int]  # positions of the returns and discards

    def within(self, start: int, end: int) -> list[Write]:
        return self.writes[bisect_left(self.positions, start) : bisect_left(self.positions, end)]

    def globals_written_within(self, start: int, end: int) -> set[str]:
        found: set[str] = set()
        first = bisect_left(self.call_writes, (start, frozenset()))
        for pos, names in self.call_writes[first:]:
            if pos >= end:
                break
            found |= names
        return found

    def exits_within(self, start: int, end: int) -> bool:
        """A return or discard in the span: code there cannot be moved as a whole."""
        index = bisect_left(self.exits, start)
        return index < len(self.exits) and self.exits[index] < end


def flow_of(prog: Program, body: Tree) -> Flow:
    """The writes of a function body, found in one pass."""
    writes: list[Write] = []
    call_writes: list[tuple[int, frozenset[str]]] = []
    exits: list[int] = []
    loop_guard: dict[int, str] = {}
    loop_write: dict[str, int] = {}  # a loop guard's name -> index of its write
    # (node, enclosing guard, guard of the innermost loop, guards of the ifs since that loop)
    stack: list[tuple[Node, str, str, tuple[str, ...]]] = [(body, "", "", ())]

    def guard(node: Tree, reads: set[str], parent: str) -> str:
        name = f"#{id(node)}"
        writes.append(Write(name, frozenset(reads | ({parent} if parent else set())),
                            node.meta.start_pos))  # fmt: skip
        return name

    while stack:
        item, ctl, loop, ifs = stack.pop()
        if not isinstance(item, Tree):
            continue
        kind = item.data
        if kind in ("if_statement", "switch_statement", "ternary"):
            condition, branches = _branches(item)
            g = guard(item, prog.reads(condition), ctl)
            inner = ifs + (g,) if kind == "if_statement" else ifs
            stack += [(c, g, loop, inner) for c in reversed(branches)]
            stack.append((condition, ctl, loop, ifs))
            continue
        if kind in LOOPS:
            condition = loop_condition(item)
            g = guard(item, prog.reads(condition) if condition is not None else set(), ctl)
            loop_guard[id(item)] = g
            loop_write[g] = len(writes) - 1
            stack += [(c, g, g, ()) for c in reversed(loop_parts(item))]
            if kind == "for_statement":
                stack.append((ForStatement(item).init, ctl, loop, ifs))
            continue
        if kind == "jump_statement" and jump_parts(item)[0] in ("return", "discard"):
            exits.append(item.meta.start_pos)
        elif kind == "jump_statement" and jump_parts(item)[0] in ("break", "continue"):
            if loop and ifs:  # the loop's passes depend on the conditions of this exit
                index = loop_write[loop]
                old = writes[index]
                writes[index] = Write(old.target, old.reads | frozenset(ifs), old.pos)
            continue
        pos = item.meta.start_pos if not item.meta.empty else 0
        guard_set = frozenset({ctl}) if ctl else frozenset()
        if kind == "declarator":
            init = declarator_initializer(item)
            reads = prog.reads(init) if isinstance(init, Tree) else set()
            writes.append(Write(Declarator(item).name, frozenset(reads) | guard_set, pos, True))
        elif kind == "condition_declaration":
            declared = ConditionDeclaration(item)
            reads = prog.reads(declared.initializer)
            writes.append(Write(declared.name, frozenset(reads) | guard_set, pos, True))
        elif kind == "assignment":
            lvalue, op, value = binary_parts(item)
            target = root_var(lvalue)
            if target:
                reads = prog.reads(value) | (names_in(lvalue) - {target})
                partial = variable_name(lvalue) is None  # a component or an element
                if op != "=" or partial:
                    reads.add(target)
                writes.append(Write(target, frozenset(reads) | guard_set, pos))
        elif kind in ("prefix", "postfix"):
            target = root_var(operand(item))
            if target:
                writes.append(Write(target, frozenset({target}) | guard_set, pos))
        elif kind == "call" and (name := call_name(item)) in prog.defined:
            call_writes.append((pos, prog.global_writes(name)))  # type: ignore[arg-type]
            args = call_args(item)
            reads = prog.reads(item)
            for fn in prog.defined[name]:  # type: ignore[index]
                for i, param in enumerate(fn.param_order):
                    out = "out" in fn.params[param][0] and i < len(args)
                    if out and (target := root_var(args[i])):
                        writes.append(Write(target, frozenset(reads | {target}) | guard_set, pos))
        stack += [(c, ctl, loop, ifs) for c in reversed(item.children)]
    order = sorted(range(len(writes)), key=lambda i: writes[i].pos)
    ordered = [writes[i] for i in order]
    call_writes.sort(key=lambda item: item[0])
    return Flow(ordered, [w.pos for w in ordered], call_writes, loop_guard, sorted(exits))


def _branches(node: Tree) -> tuple[Node, list[Node]]:
    """(condition, the parts it chooses between) of an if, a switch or a ternary."""
    if node.data == "if_statement":
        condition, then, other = if_parts(node)
        return condition, [then] if other is None else [then, other]
    if node.data == "ternary":
        condition, if_true, if_false = ternary_parts(node)
        return condition, [if_true, if_false]
    switch = SwitchStatement(node)
    return switch.selector, switch.body


def varying(seed: Iterable[str], writes: list[Write]) -> set[str]:
    """The closure of the seed over the writes: a write that reads a varying name (a guard
    included) makes its target vary (linear: each write fires once)."""
    result = set(seed)
    by_name: dict[str, list[int]] = {}
    for index, write in enumerate(writes):
        for name in write.reads:
            by_name.setdefault(name, []).append(index)
    todo = list(result)
    fired: set[int] = set()
    while todo:
        name = todo.pop()
        for index in by_name.get(name, ()):
            if index in fired:
                continue
            fired.add(index)
            target = writes[index].target
            if target not in result:
                result.add(target)
                todo.append(target)
    return result


def region_parts(loop: Tree) -> list[Node]:
    """The parts of a loop that run on every pass: all but a for's init."""
    return loop_parts(loop)


def declared_in(node: Node) -> set[str]:
    """Names declared under the node (for messages: what a piece reads from outside it)."""
    found: set[str] = set()
    for sub in walk(node):
        if sub.data == "declarator":
            found.add(Declarator(sub).name)
        elif sub.data == "condition_declaration":
            found.add(ConditionDeclaration(sub).name)
    return found
