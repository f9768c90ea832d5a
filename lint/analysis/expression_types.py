"""The GLSL type of any expression of a file, without the semantic model's ranges.

Most rules ask only what type an expression has (is this an int, is that a colour); the
semantic model (model.py) answers that too, but only after its rounds of range analysis over
every function, which is most of a lint run's time. Types do not depend on control flow: a
variable has the type it is declared with, in the scope that declares it, which the binder
(compiler/glsl/binder.py) resolved; a type is worked out when asked, from the same typing
rules the model's evaluator applies (types.py).

The two must agree on every expression: tests/lint/test_expression_types.py compares them on
every expression of the corpus."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from lark import Tree

from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import (
    Assignment,
    ConditionDeclaration,
    Constructor,
    Field,
    Ternary,
    Unary,
    binary_parts,
    first_child,
    operand,
    token_text,
    variable_name,
)
from glint.compiler.glsl.ast import (
    Sequence as CommaExpression,
)
from glint.compiler.glsl.binder import VARIABLE_KINDS, Bindings, bind
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS
from glint.compiler.target.shadertoy import shadertoy_types

from ..context import LintContext, Node, walk, walk_kind
from .declarations import signature, struct_members
from .syntax import call_args, callee_name, spec_text


class ExpressionTypes:
    """Types of the expressions of one parsed file."""

    def __init__(
        self, tree: Tree, channels: Sequence[str] = (), bindings: Bindings | None = None
    ) -> None:
        self.tree = tree
        # what each name means: the binder's (compiler/glsl/binder.py), made here when the
        # caller has none
        self.bindings = bindings or bind(tree, shadertoy_types(channels))
        # each definition's parameters (qualifiers, type, name), by function name
        self.parameters: dict[str, list[list[tuple[str, str, str]]]] = {}
        self.structs = struct_members(walk_kind(tree, "struct_specifier"))
        self._functions: dict[tuple[str, int], str] = {}  # the first definition's return type
        self._types: dict[int, str | None] = {}
        # The semantic model does not evaluate a while-condition's declaration (statements.py):
        # there a name means what it means at file level, for the two to agree.
        self._file_level = {
            id(n)
            for decl in walk_kind(tree, "condition_declaration")
            for n in walk(ConditionDeclaration(decl).initializer)
        }
        for node in tree.children:
            if isinstance(node, Tree) and node.data == "function_definition":
                name, return_type, params = signature(node)
                self._functions.setdefault((name, len(params)), return_type)
                self.parameters.setdefault(name, []).append(params)

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

    def _variable_type(self, node: Tree) -> str | None:
        if id(node) in self._file_level:
            symbol = self.bindings.file.lookup(str(variable_name(node)))
            return symbol.type if symbol is not None and symbol.kind in VARIABLE_KINDS else None
        symbol = self.bindings.symbol_of(node)
        return symbol.type if symbol is not None else None

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
    """The file's expression types, made once per file. Only for a parsed file (rules with
    `needs_tree`)."""
    return ctx.memo(_expression_types)


def _expression_types(ctx: LintContext) -> ExpressionTypes:
    if ctx.tree is None:
        raise ValueError("expression_types needs a parsed file")
    return ExpressionTypes(ctx.tree, ctx.tab.channels, ctx.bindings)
