"""Shapes of the parse tree that the analyses and the rules read: calls and their arguments,
the variable an lvalue writes, type names, prototypes and parameters, operand chains, the names
under an expression, every node's parent, and whether two expressions are written alike."""

from __future__ import annotations

from lark import Token, Tree

from glint.compiler.glsl.ast import (
    Field,
    FullySpecifiedType,
    FunctionPrototype,
    Index,
    Parameter,
    TypeSpecifier,
    Variable,
    binary_parts,
    call_arguments,
    callee_name,
    first_child,
    variable_name,
)
from glint.compiler.glsl.ast import int_value as int_value  # re-exported
from glint.compiler.glsl.binder import type_text
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS
from glint.compiler.glsl.types import swizzle_index as swizzle_index  # re-exported

from ..context import Node, variable_names, walk, walk_kind

# --- calls, lvalues and types ------------------------------------------------------------


def is_tree(node: object, *kinds: str) -> bool:
    return isinstance(node, Tree) and (not kinds or node.data in kinds)


# The helpers below test `isinstance(..., Tree)` and `.data` themselves rather than through
# is_tree: the semantic model calls them by the hundred thousand.


call_args = call_arguments  # the argument expressions of a call or constructor


def root_variable(node: Node) -> str | None:
    """`v` for `v`, `v.x`, `v[i].y`: the variable an lvalue writes."""
    while isinstance(node, Tree) and node.data in ("field", "index"):
        node = first_child(node)
    return variable_name(node)


def spec_text(spec: Tree) -> str:
    """`vec3`, `float[3]` or a struct name for a type_specifier (the binder's type_text)."""
    return type_text(spec)


def same_expression(a: Node, b: Node) -> bool:
    """Whether two expressions are written alike and have no side effects (so x*x >= 0)."""
    if a != b:
        return False
    return not any(
        t.data in ("assignment", "prefix", "postfix") or (t.data == "call" and
                                                         callee_name(t) not in BUILTIN_FUNCTIONS)
        for t in walk(a)
    )  # fmt: skip


def var_key(node: Node) -> tuple[str, str] | None:
    """("y", "y") for a variable, ("s.w", "s") for one component of one: what a relation
    names, and the variable whose value it is about."""
    name = variable_name(node)
    if name is not None:
        return name, name
    field = Field.cast(node)
    if field is not None:
        base = variable_name(field.base)
        if base is not None:
            letter = field.name
            return (f"{base}.{letter}", base) if len(letter) == 1 else None
    return None


# --- declarations -------------------------------------------------------------------------


def type_of_declaration(spec: Tree) -> tuple[str, bool]:
    """(type name, is an array) of a `fully_specified_type` or `type_specifier`."""
    view = (
        FullySpecifiedType(spec).type
        if spec.data == "fully_specified_type"
        else TypeSpecifier(spec)
    )
    is_array = view.array is not None
    if view.struct is None:
        return view.name, is_array
    return "struct", is_array


def parameter_parts(param: Tree) -> tuple[str, str, bool, Token | None]:
    """(qualifier, type, is an array, name) of a `parameter` node."""
    view = Parameter(param)
    type_name, is_array = type_of_declaration(view.type.syntax)
    return view.direction, type_name, is_array or view.array is not None, view.name_token


def prototype_parts(proto: Tree) -> tuple[str, Token, list[Tree]]:
    """(return type, name, parameters) of a `function_prototype`."""
    view = FunctionPrototype(proto)
    ret_type, _ = type_of_declaration(view.return_type.syntax)
    return ret_type, view.name_token, [p.syntax for p in view.parameters]


# --- names and operands ----------------------------------------------------------------


def call_name(node: Node) -> str | None:
    """The called name of a `call` node (`f(x)` -> "f"), None for anything else."""
    return callee_name(node) if is_tree(node, "call") else None  # type: ignore[arg-type]


var_name = variable_name


def last_name(node: Node) -> str | None:
    """`x` -> "x", `s.N` -> "N" (the innermost name a reader sees), else None."""
    field = Field.cast(node)
    return field.name if field is not None else variable_name(node)


def root_var(node: Node) -> str | None:
    """The variable an lvalue writes: `a`, `a.x`, `a[i].y` -> "a"."""
    while isinstance(node, Tree) and node.data in ("field", "index"):
        node = first_child(node)
    return variable_name(node)


def is_simple(node: Node) -> bool:
    """An identifier, or fields/swizzles/constant indices of one: no side effects, cheap to
    repeat, and a postfix expression that needs no parentheses."""
    while isinstance(node, Tree) and node.data in ("field", "index"):
        if node.data == "index" and not is_tree(Index(node).index, "int_literal"):
            return False
        node = first_child(node)
    return var_name(node) is not None


def binary_op(node: Node) -> str | None:
    if isinstance(node, Tree) and node.data == "binary":
        return binary_parts(node)[1]
    return None


def operands(node: Node, op: str) -> list[Node]:
    """The operands of a chain of one associative operator (`a + b + c` -> [a, b, c])."""
    found: list[Node] = []
    stack = [node]  # iterative: long sums must not exhaust the stack
    while stack:
        item = stack.pop()
        if binary_op(item) == op:
            left, _, right = binary_parts(item)  # type: ignore[arg-type]
            stack += [right, left]
        else:
            found.append(item)
    return found


def names_in(node: Node) -> set[str]:
    """Every variable name read or written under the node (call heads excluded)."""
    if not isinstance(node, Tree):
        return set()
    if node.data == "variable":  # itself, even the name of a call (whose call is not under it)
        return {Variable(node).name}
    indexed = variable_names(node)  # a slice of the file's index, without walking the node
    if indexed is not None:
        found = set(indexed)
        found.discard("")
        return found
    heads = {id(first_child(s)) for s in walk(node) if s.data == "call"}
    return {variable_name(s) for s in walk(node) if s.data == "variable" and id(s) not in heads}  # type: ignore[misc]


def calls_in(node: Node) -> list[Tree]:
    return walk_kind(node, "call") if isinstance(node, Tree) else []
