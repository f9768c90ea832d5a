"""The statement walker of the first path: declarations, branches (one taken where the condition
is exact, else both joined), the first iteration of each loop, switch cases and returns. A mixin
of `Moments`."""

from __future__ import annotations

from collections.abc import Iterable

from lark import Tree

from glint.compiler.glsl.ast import (
    DoStatement,
    SwitchStatement,
    WhileStatement,
    declarators,
    first_child,
    for_parts,
    if_parts,
    jump_parts,
    operand,
)

from ...context import Node, walk
from ..declarations import declared_variables
from ..syntax import call_args, callee_name, is_tree, root_variable
from .calls import Fn, writes_back
from .state import State, join_states
from .values import MV, base_of, cast, known, show, size_of, truth_of, union, unknown


class StatementWalker:
    """Runs statements along the first path; `expr` (ExpressionWalker), `emit` and the calls'
    tables (CallEvaluator) come from the other mixins of `Moments`."""

    _writes: dict[int, frozenset[str]]  # memo of `writes`, by node id
    functions: dict[str, list[Fn]]

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
        truth = truth_of(cond)
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
            truth = truth_of(self.expr(cond, inner))
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
                    if writes_back(qualifier):
                        out.add(root_variable(arg) or "")
        return out
