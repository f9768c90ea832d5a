"""Shapes of the parse tree that the analyses and the rules read: calls and their arguments,
the variable an lvalue writes, type names, prototypes and parameters, operand chains, the names
under an expression, every node's parent, and whether two expressions are written alike."""

from __future__ import annotations

from lark import Token, Tree

from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

from ..context import Node, variable_names, walk, walk_kind

# --- calls, lvalues and types ------------------------------------------------------------


def is_tree(node: object, *kinds: str) -> bool:
    return isinstance(node, Tree) and (not kinds or node.data in kinds)


# The helpers below test `isinstance(..., Tree)` and `.data` themselves rather than through
# is_tree: the semantic model calls them by the hundred thousand.


def callee_name(call: Tree) -> str | None:
    """`f` for a call `f(...)`; None for a method call such as `v.length()`."""
    head = call.children[0]
    return str(head.children[0]) if isinstance(head, Tree) and head.data == "variable" else None


def call_args(call: Tree) -> list[Node]:
    """The argument expressions of a call or constructor."""
    for child in call.children[1:]:
        if isinstance(child, Tree) and child.data == "arguments":
            return list(child.children)
    return []


def root_variable(node: Node) -> str | None:
    """`v` for `v`, `v.x`, `v[i].y`: the variable an lvalue writes."""
    while isinstance(node, Tree) and node.data in ("field", "index"):
        node = node.children[0]
    return str(node.children[0]) if isinstance(node, Tree) and node.data == "variable" else None


def spec_text(spec: Tree) -> str:
    """`vec3`, `float[3]` or a struct name for a type_specifier."""
    head = spec.children[0]
    if is_tree(head, "struct_specifier"):
        name = next((str(c) for c in head.children if isinstance(c, Token)), "struct")
    else:
        name = str(head)
    arrays = [c for c in spec.children[1:] if is_tree(c, "array_specifier")]
    return name + "".join(array_text(a) for a in arrays)


def array_text(spec: Tree) -> str:
    sizes = [_literal_text(c) for c in spec.children]
    return "".join(f"[{s}]" for s in sizes) if sizes else "[]"


def _literal_text(node: Node) -> str:
    if is_tree(node, "int_literal"):
        return str(node.children[0])  # type: ignore[union-attr]
    return ""


def same_expression(a: Node, b: Node) -> bool:
    """Whether two expressions are written alike and have no side effects (so x*x >= 0)."""
    if a != b:
        return False
    return not any(
        t.data in ("assignment", "prefix", "postfix") or (t.data == "call" and
                                                         callee_name(t) not in BUILTIN_FUNCTIONS)
        for t in walk(a)
    )  # fmt: skip


def int_value(text: str) -> int | None:
    text = text.rstrip("uU")
    try:
        if text.lower().startswith("0x"):
            return int(text, 16)
        if len(text) > 1 and text.startswith("0"):
            return int(text, 8)
        return int(text)
    except ValueError:
        return None


def var_key(node: Node) -> tuple[str, str] | None:
    """("y", "y") for a variable, ("s.w", "s") for one component of one: what a relation
    names, and the variable whose value it is about."""
    if is_tree(node, "variable"):
        name = str(node.children[0])  # type: ignore[union-attr]
        return name, name
    if is_tree(node, "field") and is_tree(node.children[0], "variable"):  # type: ignore
        letter = str(node.children[1])  # type: ignore[union-attr]
        base = str(node.children[0].children[0])  # type: ignore[union-attr]
        return (f"{base}.{letter}", base) if len(letter) == 1 else None
    return None


def swizzle_index(letter: str) -> int:
    for names in ("xyzw", "rgba", "stpq"):
        if letter in names:
            return names.index(letter)
    return 0


# --- declarations -------------------------------------------------------------------------


def type_of_declaration(spec: Tree) -> tuple[str, bool]:
    """(type name, is an array) of a `fully_specified_type` or `type_specifier`."""
    if spec.data == "fully_specified_type":
        spec = spec.children[-1]  # type: ignore[assignment]
    name = spec.children[0]
    is_array = any(isinstance(c, Tree) and c.data == "array_specifier" for c in spec.children)
    if isinstance(name, Token):
        return str(name), is_array
    return "struct", is_array


def parameter_parts(param: Tree) -> tuple[str, str, bool, Token | None]:
    """(qualifier, type, is an array, name) of a `parameter` node."""
    qualifier = ""
    type_name, is_array, name = "", False, None
    for child in param.children:
        if isinstance(child, Tree) and child.data == "type_qualifier":
            words = [str(t) for t in child.children if isinstance(t, Token)]
            qualifier = next((w for w in words if w in ("in", "out", "inout")), "in")
        elif isinstance(child, Tree) and child.data == "type_specifier":
            type_name, is_array = type_of_declaration(child)
        elif isinstance(child, Tree) and child.data == "array_specifier":
            is_array = True
        elif isinstance(child, Token):
            name = child
    return qualifier or "in", type_name, is_array, name


def prototype_parts(proto: Tree) -> tuple[str, Token, list[Tree]]:
    """(return type, name, parameters) of a `function_prototype`."""
    ret, name = proto.children[0], proto.children[1]
    params: list[Tree] = []
    if len(proto.children) > 2 and isinstance(proto.children[2], Tree):
        params = [p for p in proto.children[2].children if isinstance(p, Tree)]
    ret_type, _ = type_of_declaration(ret)  # type: ignore[arg-type]
    return ret_type, name, params  # type: ignore[return-value]


# --- names and operands ----------------------------------------------------------------


def call_name(node: Node) -> str | None:
    """The called name of a `call` node (`f(x)` -> "f"), None for anything else."""
    return callee_name(node) if is_tree(node, "call") else None  # type: ignore[arg-type]


def var_name(node: Node) -> str | None:
    if isinstance(node, Tree) and node.data == "variable":
        return str(node.children[0])
    return None


def last_name(node: Node) -> str | None:
    """`x` -> "x", `s.N` -> "N" (the innermost name a reader sees), else None."""
    if isinstance(node, Tree):
        if node.data == "variable":
            return str(node.children[0])
        if node.data == "field":
            return str(node.children[-1])
    return None


def root_var(node: Node) -> str | None:
    """The variable an lvalue writes: `a`, `a.x`, `a[i].y` -> "a"."""
    while isinstance(node, Tree) and node.data in ("field", "index"):
        node = node.children[0]
    return var_name(node)


def is_simple(node: Node) -> bool:
    """An identifier, or fields/swizzles/constant indices of one: no side effects, cheap to
    repeat, and a postfix expression that needs no parentheses."""
    while isinstance(node, Tree) and node.data in ("field", "index"):
        if node.data == "index" and not (
            isinstance(node.children[1], Tree) and node.children[1].data == "int_literal"
        ):
            return False
        node = node.children[0]
    return var_name(node) is not None


def binary_op(node: Node) -> str | None:
    if isinstance(node, Tree) and node.data == "binary":
        return str(node.children[1])
    return None


def operands(node: Node, op: str) -> list[Node]:
    """The operands of a chain of one associative operator (`a + b + c` -> [a, b, c])."""
    found: list[Node] = []
    stack = [node]  # iterative: long sums must not exhaust the stack
    while stack:
        item = stack.pop()
        if binary_op(item) == op:
            assert isinstance(item, Tree)
            stack += [item.children[2], item.children[0]]
        else:
            found.append(item)
    return found


def names_in(node: Node) -> set[str]:
    """Every variable name read or written under the node (call heads excluded)."""
    if not isinstance(node, Tree):
        return set()
    if node.data == "variable":  # itself, even the name of a call (whose call is not under it)
        return {str(node.children[0])}
    indexed = variable_names(node)  # a slice of the file's index, without walking the node
    if indexed is not None:
        found = set(indexed)
        found.discard("")
        return found
    heads = {id(s.children[0]) for s in walk(node) if s.data == "call"}
    return {str(s.children[0]) for s in walk(node) if s.data == "variable" and id(s) not in heads}


def calls_in(node: Node) -> list[Tree]:
    return walk_kind(node, "call") if isinstance(node, Tree) else []
