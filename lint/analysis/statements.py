"""The semantic model's forward pass over one function's statements: declarations and
assignments update the variables in scope, branches are narrowed by their condition and joined,
loops are run until the facts at their head stop changing, and the return statements are joined
into what the function returns."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Protocol

from lark import Tree

from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import (
    ConditionDeclaration,
    DoStatement,
    SwitchStatement,
    WhileStatement,
    binary_parts,
    declarator_initializer,
    declarators,
    field_parts,
    first_child,
    for_parts,
    if_parts,
    jump_parts,
    operand,
    variable_name,
)
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

from ..context import Node
from . import witness as W
from .expressions import ASSIGN_OPS, Evaluator, ModelView
from .ranges import Interval
from .scopes import Scopes, join_scopes, widen
from .syntax import call_args, callee_name, is_tree, root_variable, spec_text, swizzle_index
from .values import Env, Function, Value


class ModelForPass(ModelView, Protocol):
    """What the forward pass asks of the semantic model (model.Model), besides what the
    evaluator does: the functions analysed so far, to declare variables and to record where an
    expression is evaluated. A protocol, so that this module does not import the model, which
    imports it."""

    functions: dict[str, list[Function]]

    def declaration(self, node: Tree, scopes: Scopes, is_global: bool = False) -> None: ...

    def record(self, expr: Node, env: Env, seen: dict[int, Value] | None = None) -> None: ...

    def names_of(self, expr: Node) -> frozenset[str]: ...

    def writers(self, expr: Tree) -> tuple[Tree, ...]: ...


@dataclass
class _Loop:
    switch: bool = False  # a switch takes `break` but not `continue`
    breaks: list[Scopes] = field(default_factory=list)
    continues: list[Scopes] = field(default_factory=list)


# The nodes that may write a variable (written_targets).
WRITING = frozenset({"assignment", "postfix", "prefix", "call"})


def written_targets(node: Tree, model: ModelForPass | None) -> Iterable[Node]:
    """Lvalues one node writes: an assignment's target, `x++`, out arguments of a call."""
    if node.data == "assignment":
        yield first_child(node)  # the target
    elif node.data == "postfix" or node.data == "prefix":
        yield operand(node)
    elif node.data == "call":
        yield from _out_arguments(node, model)


def _out_arguments(call: Tree, model: ModelForPass | None) -> Iterable[Node]:
    name = callee_name(call)
    args = call_args(call)
    if name == "modf" and len(args) == 2:
        yield args[1]
        return
    if name is None or name in BUILTIN_FUNCTIONS:
        return
    fns = model.functions.get(name, []) if model is not None else []
    if model is not None and not fns:
        fns = []
    if not fns:  # not analysed yet (or unknown): any argument may be written
        yield from (a for a in args if root_variable(a) is not None)
        return
    for fn in fns:
        if len(fn.params) != len(args):
            continue
        for (qualifier, _, _), arg in zip(fn.params, args, strict=True):
            if "out" in qualifier.split() or "inout" in qualifier.split():
                yield arg


class ForwardPass:
    """The forward pass over one function's statements."""

    def __init__(self, model: ModelForPass, fn: Function) -> None:
        self.model = model
        self.fn = fn
        self.loops: list[_Loop] = []
        self.returns: list[Value] = []

    # --- statements ------------------------------------------------------------------------

    def block(self, statements: Iterable[Node], scopes: Scopes) -> None:
        # iterative over the list: long functions must not deepen the stack
        for stmt in statements:
            self.statement(stmt, scopes)

    def result(self) -> Value | None:
        """What the function returns: the join of its return statements."""
        if not self.returns:
            return None
        result = self.returns[0]
        for r in self.returns[1:]:
            result = result.join(r)
        return result.but(type=self.fn.return_type)

    def statement(self, stmt: Node, scopes: Scopes) -> None:
        if not isinstance(stmt, Tree):
            return
        handler = getattr(self, "_" + stmt.data, None)
        if handler is not None:
            handler(stmt, scopes)

    def _compound_statement(self, node: Tree, scopes: Scopes) -> None:
        scopes.push()
        self.block(node.children, scopes)
        scopes.pop()

    def _declaration_statement(self, node: Tree, scopes: Scopes) -> None:
        decl = first_child(node)  # the declaration
        if is_tree(decl, "variable_declaration"):
            self.model.declaration(decl, scopes)  # type: ignore[arg-type]
            for d in declarators(decl):  # type: ignore[arg-type]
                init = declarator_initializer(d)
                if init is not None:
                    self.effects(init, scopes, nested_only=True)

    def _expression_statement(self, node: Tree, scopes: Scopes) -> None:
        self.expression(first_child(node), scopes)

    def _jump_statement(self, node: Tree, scopes: Scopes) -> None:
        kind, expr = jump_parts(node)
        if kind == "return" and expr is not None:
            recorded = self.expression(expr, scopes)
            if not scopes.dead:
                env = scopes.env_for(expr, self.model.names_of(expr))
                seen = recorded[1] if _same_env(env, recorded[0]) else None
                self.returns.append(Evaluator(self.model, env, seen=seen).eval(expr))
        elif kind == "break" and self.loops:
            self.loops[-1].breaks.append(scopes.copy())
        elif kind == "continue":
            loop = next((lp for lp in reversed(self.loops) if not lp.switch), None)
            if loop is not None:
                loop.continues.append(scopes.copy())
        scopes.dead = True

    def _if_statement(self, node: Tree, scopes: Scopes) -> None:
        # `else if` is an if nested in the else branch. Following the chain here and joining
        # all its branches once gives the same state as joining level by level (the join is a
        # hull: associative and idempotent), without joining a variable assigned deep in a long
        # chain again at every level on the way out (quadratic in the chain's length).
        branches = []
        current = scopes
        while True:
            cond, then, other = if_parts(node)
            self.expression(cond, current)
            state = self.narrowed(current, cond, True)
            self.statement(then, state)
            branches.append(state)
            state = self.narrowed(current, cond, False)
            if is_tree(other, "if_statement"):
                current, node = state, other  # type: ignore[assignment]
                continue
            if other is not None:
                self.statement(other, state)
            branches.append(state)
            break
        scopes.become(join_scopes(branches))

    def _for_statement(self, node: Tree, scopes: Scopes) -> None:
        init, cond, update, body = for_parts(node)
        scopes.push()
        self.statement(init, scopes)
        self.loop(scopes, cond, update, body)
        scopes.pop()

    def _while_statement(self, node: Tree, scopes: Scopes) -> None:
        loop = WhileStatement(node)
        cond, body = loop.condition, loop.body
        scopes.push()
        declared = ConditionDeclaration.cast(cond)
        if declared is not None:
            scopes.declare(declared.name, Value(spec_text(declared.type.type.syntax)))
            cond = None
        self.loop(scopes, cond, None, body)
        scopes.pop()

    def _do_statement(self, node: Tree, scopes: Scopes) -> None:
        loop = DoStatement(node)
        self.loop(scopes, loop.condition, None, loop.body, test_first=False)

    def _switch_statement(self, node: Tree, scopes: Scopes) -> None:
        switch = SwitchStatement(node)
        selector, body = switch.selector, switch.body
        self.expression(selector, scopes)
        entry = scopes.copy()
        entry.push()
        current = entry.copy()
        current.dead = True  # nothing before the first label runs
        self.loops.append(_Loop(switch=True))
        has_default = False
        for stmt in body:
            if is_tree(stmt, "case_label", "default_label"):
                has_default |= stmt.data == "default_label"  # type: ignore[union-attr]
                current = join_scopes([current, entry])  # jumped to, or fallen into
                continue
            self.statement(stmt, current)
        exits = self.loops.pop()
        out = join_scopes([current, *exits.breaks] + ([] if has_default else [entry]))
        out.frames = out.frames[: len(scopes.frames)]
        scopes.become(out)

    def loop(self, scopes: Scopes, cond: Node | None, update: Node | None, body: Node,
             test_first: bool = True) -> None:  # fmt: skip
        """Widen what the loop assigns, run the body until its facts stop changing, then
        leave with the condition false (or through a break)."""
        assigned = {
            name
            for part in (cond, update, body)
            if isinstance(part, Tree)
            for n in self.model.writers(part)
            for t in written_targets(n, self.model)
            if (name := root_variable(t)) is not None
        }
        # Nested loops would multiply the passes: deep inside, one pass that knows nothing of
        # what the loop assigns (sound at once, no fixpoint needed). Elsewhere the passes stop
        # when the loop-head state is stable, and fall back to that one pass if it is not.
        deep = sum(not lp.switch for lp in self.loops) >= 3
        entry = widen(scopes, assigned)
        state, converged = entry, False
        for _ in range(0 if deep else 4):
            inner, exits = self._pass(state, cond, update, body, test_first)
            new_state = widen(join_scopes([entry, inner]), assigned)
            converged = new_state.flat() == state.flat()
            if converged:
                break
            state = new_state
        if not converged:
            state = widen(scopes, assigned, keep_flags=False)
            _, exits = self._pass(state, cond, update, body, test_first)
        leave = self.narrowed(state, cond, False) if cond is not None else state.copy()
        if cond is None:
            leave.dead = True  # `for (;;)` ends only through a break
        scopes.become(join_scopes([leave, *exits.breaks]))

    def _pass(self, state: Scopes, cond: Node | None, update: Node | None, body: Node,
              test_first: bool) -> tuple[Scopes, _Loop]:  # fmt: skip
        """One run of the loop from `state`: the state after it, and its breaks/continues."""
        self.loops.append(_Loop())
        inner = state.copy()
        if cond is not None and test_first:
            self.expression(cond, inner)
            inner = self.narrowed(inner, cond, True)
        self.statement(body, inner)
        exits = self.loops.pop()
        inner = join_scopes([inner, *exits.continues])
        if update is not None:
            self.expression(update, inner)
        if cond is not None and not test_first:
            self.expression(cond, inner)
        return inner, exits

    def narrowed(self, scopes: Scopes, cond: Node | None, truth: bool) -> Scopes:
        out = scopes.copy()
        if cond is None or out.dead:
            return out
        env = out.env_for(cond, self.model.names_of(cond))
        refined = self.model.refine(env, cond, truth)
        if refined is not env:
            for name, value in refined.items():
                if env.get(name) is not value:
                    out.assign(name, value)
        return out

    # --- expressions -----------------------------------------------------------------------

    def expression(self, expr: Node, scopes: Scopes) -> tuple[Env, dict[int, Value]]:
        """Record the expression where it is evaluated and apply its effects. Returns the
        environment it was recorded in, with the values already evaluated there."""
        env = scopes.env_for(expr, self.model.names_of(expr))
        seen: dict[int, Value] = {}
        self.model.record(expr, env, seen)
        self.effects(expr, scopes, recorded=(expr, env, seen))
        return env, seen

    def effects(
        self,
        expr: Node,
        scopes: Scopes,
        nested_only: bool = False,
        recorded: tuple[Node, Env, dict[int, Value]] | None = None,
    ) -> Value | None:
        """Apply what an expression writes: top-level assignments exactly (`x = e`, `x += e`,
        a sequence of them), any other write makes its variable unknown. `recorded`: an
        expression `record` went through, its environment and the values found there.

        Returns the value of an assignment (of a sequence: of its last part) where it was
        evaluated, for the assignment it is the right side of: `x = y = e` evaluates `e` once,
        not once per `=` (a chain of thousands of them was quadratic)."""
        if not isinstance(expr, Tree):
            return None
        if not nested_only and expr.data == "sequence":
            value = None
            for part in expr.children:
                value = self.effects(part, scopes)
            return value
        if not nested_only and expr.data == "assignment":
            target, op, rhs = binary_parts(expr)
            value = self.effects(rhs, scopes)
            return self._assign(target, op, expr, scopes, recorded, value)
        for node in self.model.writers(expr):
            for target in written_targets(node, self.model):
                name = root_variable(target)
                old = scopes.lookup(name) if name else None
                if name and old is not None:
                    scopes.assign(name, old.unknown())
        return None

    def _assign(self, target: Node, op: str, expr: Tree, scopes: Scopes,
                recorded: tuple[Node, Env, dict[int, Value]] | None,
                rhs_value: Value | None) -> Value | None:  # fmt: skip
        name = root_variable(target)
        old = scopes.lookup(name) if name else None
        if rhs_value is not None:
            # The right side is an assignment applied just before: its value is known, and only
            # the target is left to read.
            env = scopes.env_for(target, self.model.names_of(target))
            seen = {id(binary_parts(expr)[2]): rhs_value}
        elif name is None or old is None:
            return None
        else:
            env = scopes.env_for(expr, self.model.names_of(expr))
            seen = None
            if recorded is not None and recorded[0] is expr and _same_env(env, recorded[1]):
                seen = recorded[2]  # nothing before this changed what the expression reads
        got = Evaluator(self.model, env, seen=seen).eval(expr)
        if name is None or old is None:
            return got
        if op not in ("=", *ASSIGN_OPS):
            scopes.assign(name, old.unknown())
        elif is_tree(target, "variable"):
            scopes.assign(name, got.but(type=old.type))
        elif (kept := _component_part(target, op, old, got)) is not None:
            scopes.assign(name, kept)
        else:  # one component or element: each is now the old value or the new one
            scopes.assign(name, Value(old.type, old.range.hull(got.range)))
        return got


def _same_env(a: Env, b: Env) -> bool:
    """Whether two environments hold the very same values (so evaluate alike)."""
    return a.keys() == b.keys() and all(a[name] is b[name] for name in a)


def _swizzled(target: Node, old: Value) -> list[int] | None:
    """The components `v.xz` names, for a swizzle of a vector variable without repeats."""
    if not is_tree(target, "field"):
        return None
    base, letters = field_parts(target)  # type: ignore[arg-type]
    if variable_name(base) is None:
        return None
    n = T.size(old.type)
    indices = [swizzle_index(c) for c in letters]
    if n < 2 or len(set(indices)) != len(indices) or max(indices) >= n:
        return None
    return indices


def _kept_witness(old: Value, indices: list[int], got: Value, n: int) -> W.Witness | None:
    """The witness after `v.xz = ...`: the components not written keep theirs (`rd.y` of a
    view ray stays negative at the bottom-left pixel when `rd.xz` turns), the written ones take
    the new value's."""
    if old.wit is None and got.wit is None:
        return None
    parts = W.pairs(old.wit, old.parts(n))
    new = W.pairs(got.wit, got.parts(len(indices)))
    for i, p in zip(indices, new, strict=True):
        parts[i] = p
    why = (got.wit or old.wit).why  # type: ignore[union-attr]
    return W.make(parts, why, old.parts(n))


def _component_part(target: Node, op: str, old: Value, got: Value) -> Value | None:
    """`v.xz` written: by a rotation, or by any value."""
    if op == "*=" and got.origin == "rotated":
        return _rotated_part(target, old, got)
    return _assigned_part(target, old, got)


def _rotated_part(target: Node, old: Value, got: Value) -> Value | None:
    """`v.xy *= rot`: the rotated components take the new ranges, and the length of v is kept
    (a unit vector stays one: a camera turned by a rotation matrix)."""
    indices = _swizzled(target, old)
    if indices is None:
        return None
    n = T.size(old.type)
    parts = old.parts(n)
    for i, c in zip(indices, got.parts(len(indices)), strict=True):
        parts[i] = c.meet(Interval(-1.0, 1.0)) if old.unit else c
    rotated = Value(old.type, unit=old.unit, comps=tuple(parts))
    return rotated.but(wit=_kept_witness(old, indices, got.but(wit=None), n))


def _assigned_part(target: Node, old: Value, got: Value) -> Value | None:
    """`v.x *= k`: the components written take the new value's ranges and witnesses, the
    others keep theirs."""
    indices = _swizzled(target, old)
    if indices is None or T.size(got.type) != len(indices):
        return None
    n = T.size(old.type)
    parts = old.parts(n)
    for i, c in zip(indices, got.parts(len(indices)), strict=True):
        parts[i] = c
    value = Value(old.type, comps=tuple(parts))
    return value.but(wit=_kept_witness(old, indices, got, n))
