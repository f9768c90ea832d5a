"""The GLSL type of any expression of a file, without the semantic model's ranges.

Most rules ask only what type an expression has (is this an int, is that a colour); the
semantic model (model.py) answers that too, but only after its rounds of range analysis over
every function, which is most of a lint run's time. Types do not depend on control flow: a
variable has the type it is declared with, in the scope that declares it. So one walk over
the declarations in source order places every expression in its lexical scope, and a type is
worked out when asked, from the same typing rules the model's evaluator applies (types.py).

The two must agree on every expression: tests/lint/test_expression_types.py compares them on
every expression of the corpus."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from lark import Tree

from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import (
    Assignment,
    Constructor,
    Field,
    FunctionDefinition,
    IfStatement,
    JumpStatement,
    SwitchStatement,
    Ternary,
    Unary,
    WhileStatement,
    binary_parts,
    first_child,
    for_parts,
    operand,
    token_text,
    variable_name,
)
from glint.compiler.glsl.ast import (
    Sequence as CommaExpression,
)
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS
from glint.compiler.target.shadertoy import shadertoy_types

from ..context import LintContext, Node, walk, walk_kind
from .declarations import declared_variables, signature, struct_members
from .syntax import call_args, callee_name, is_tree, spec_text

# A frame of a scope: each name with the (position, type) of each declaration of it. A
# declaration is visible to the expressions after it: those with a later position.
Frame = dict[str, list[tuple[int, str | None]]]
Scope = tuple[tuple[Frame, ...], float]  # the frames in scope (outermost first), a position


class ExpressionTypes:
    """Types of the expressions of one parsed file."""

    def __init__(self, tree: Tree, channels: Sequence[str] = ()) -> None:
        self.tree = tree
        # each definition's parameters (qualifiers, type, name), by function name
        self.parameters: dict[str, list[list[tuple[str, str, str]]]] = {}
        self.structs = struct_members(walk_kind(tree, "struct_specifier"))
        self._functions: dict[tuple[str, int], str] = {}  # the first definition's return type
        self._scope_of: dict[int, Scope] = {}
        self._types: dict[int, str | None] = {}
        self._position = 0
        shadertoy: Frame = {name: [(-1, ty)] for name, ty in shadertoy_types(channels).items()}
        self._globals: list[Frame] = [shadertoy]
        for node in tree.children:
            if not isinstance(node, Tree):
                continue
            if node.data == "function_definition":
                self._function(node)
            elif node.data == "variable_declaration":
                self._declaration(node, self._globals)
        # an expression outside every statement (an array size) sees every global
        self._outside: Scope = ((shadertoy,), math.inf)

    def type_of(self, expr: Node) -> str | None:
        """The GLSL type of an expression ("float", "vec3", a struct name), None if unknown."""
        if not isinstance(expr, Tree):
            return None
        key = id(expr)
        if key in self._types:
            return self._types[key]
        handler = _HANDLERS.get(expr.data)
        found = handler(self, expr) if handler is not None else None
        self._types[key] = found
        return found

    # --- placing expressions in their scopes -----------------------------------------------

    def _function(self, node: Tree) -> None:
        name, return_type, params = signature(node)
        self._functions.setdefault((name, len(params)), return_type)
        self.parameters.setdefault(name, []).append(params)
        frame: Frame = {}
        for _, ptype, pname in params:
            if pname:
                frame.setdefault(pname, []).append((self._position, ptype))
        self._position += 1
        self._statement(FunctionDefinition(node).body, [*self._globals, frame])

    def _declaration(self, node: Tree, frames: list[Frame]) -> None:
        for name, dtype, init in declared_variables(node)[1]:
            if init is not None:
                self._place(init, frames)
            frames[-1].setdefault(name, []).append((self._position, dtype))
            self._position += 1

    def _place(self, expr: Node, frames: list[Frame]) -> None:
        """Every node of the expression is evaluated in the scope as it is here."""
        if not isinstance(expr, Tree):
            return
        scope = (tuple(frames), self._position)
        self._position += 1
        self._scope_of.update(dict.fromkeys(map(id, walk(expr)), scope))

    def _statement(self, stmt: Node, frames: list[Frame]) -> None:
        # The statements the model's forward pass records (statements.py), with their scopes.
        if not isinstance(stmt, Tree):
            return
        kind = stmt.data
        if kind == "compound_statement":
            inner = [*frames, {}]
            for child in stmt.children:
                self._statement(child, inner)
        elif kind == "declaration_statement":
            decl = first_child(stmt)
            if is_tree(decl, "variable_declaration"):
                self._declaration(decl, frames)  # type: ignore[arg-type]
        elif kind == "expression_statement":
            self._place(first_child(stmt), frames)
        elif kind == "jump_statement":
            jump = JumpStatement(stmt)
            value = jump.value
            if jump.keyword == "return" and value is not None:
                self._place(value, frames)
        elif kind == "if_statement":
            branch = IfStatement(stmt)
            self._place(branch.condition, frames)
            self._statement(branch.then_branch, frames)
            other = branch.else_branch
            if other is not None:
                self._statement(other, frames)
        elif kind == "for_statement":
            inner = [*frames, {}]
            init, cond, update, body = for_parts(stmt)
            self._statement(init, inner)
            for part in (cond, update):
                if part is not None:
                    self._place(part, inner)
            self._statement(body, inner)
        elif kind == "while_statement":
            inner = [*frames, {}]
            loop = WhileStatement(stmt)
            declared = loop.declaration
            if declared is not None:
                spec = declared.type.type.syntax
                inner[-1][declared.name] = [(self._position, spec_text(spec))]
                self._position += 1
            else:
                self._place(loop.condition, inner)
            self._statement(loop.body, inner)
        elif kind == "do_statement":
            body, cond = stmt.children
            self._statement(body, frames)
            self._place(cond, frames)
        elif kind == "switch_statement":
            switch = SwitchStatement(stmt)
            self._place(switch.selector, frames)
            inner = [*frames, {}]
            for child in switch.body:
                self._statement(child, inner)

    def _variable_type(self, node: Tree) -> str | None:
        frames, position = self._scope_of.get(id(node), self._outside)
        name = variable_name(node)
        for frame in reversed(frames):
            declared = frame.get(name)
            if declared:
                for at, ty in reversed(declared):
                    if at < position:
                        return ty
        return None

    # --- typing rules (the evaluator's, expressions.py) --------------------------------------

    def _unary(self, node: Tree) -> str | None:
        unary = Unary(node)
        return T.unary(unary.op, self.type_of(unary.operand))

    def _binary(self, node: Tree) -> str | None:
        left, op, right = binary_parts(node)
        return T.binary(op, self.type_of(left), self.type_of(right))

    def _ternary(self, node: Tree) -> str | None:
        ternary = Ternary(node)
        return self.type_of(ternary.if_true) or self.type_of(ternary.if_false)

    def _assignment(self, node: Tree) -> str | None:
        assignment = Assignment(node)
        target = self.type_of(assignment.target)
        return target or self.type_of(assignment.value) if assignment.op == "=" else target

    def _field(self, node: Tree) -> str | None:
        field = Field(node)
        base, name = self.type_of(field.base), field.name
        swizzled = T.swizzle(base, name)
        if swizzled is not None:
            return swizzled
        return self.structs.get(base or "", {}).get(name)

    def _call(self, node: Tree) -> str | None:
        args = call_args(node)
        types = [self.type_of(a) for a in args]
        method = Field.cast(first_child(node))
        if method is not None and method.name == "length":
            return "int"
        name = callee_name(node)
        if name is None:
            return None
        key = (name, len(args))
        if key in self._functions:
            return self._functions[key]
        return T.builtin_return(name, types) if name in BUILTIN_FUNCTIONS else None


def _literal(ty: str) -> Callable[[ExpressionTypes, Tree], str | None]:
    return lambda _, node: ty


_HANDLERS: dict[str, Callable[[ExpressionTypes, Tree], str | None]] = {
    "float_literal": _literal("float"),
    "int_literal": lambda _, n: "uint" if str(token_text(n))[-1] in "uU" else "int",
    "bool_literal": _literal("bool"),
    "variable": ExpressionTypes._variable_type,
    "unary": ExpressionTypes._unary,
    "prefix": lambda types, n: types.type_of(operand(n)),
    "postfix": lambda types, n: types.type_of(operand(n)),
    "binary": ExpressionTypes._binary,
    "ternary": ExpressionTypes._ternary,
    "assignment": ExpressionTypes._assignment,
    "sequence": lambda types, n: types.type_of(CommaExpression(n).right),
    "field": ExpressionTypes._field,
    "index": lambda types, n: T.element(types.type_of(first_child(n))),
    "constructor": lambda _, n: spec_text(Constructor(n).type.syntax),
    "call": ExpressionTypes._call,
}


def expression_types(ctx: LintContext) -> ExpressionTypes:
    """The file's expression types, made on first use and cached in `ctx.cache`. Only for a
    parsed file (rules with `needs_tree`)."""
    found = ctx.cache.get("expression_types")
    if found is None:
        if ctx.tree is None:
            raise ValueError("expression_types needs a parsed file")
        found = ctx.cache["expression_types"] = ExpressionTypes(ctx.tree, ctx.tab.channels)
    return found
