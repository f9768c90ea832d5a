"""Helpers shared by the performance rules: when a replacement needs parentheses (PF001, PF003)
and the names of GLSL's builtin functions."""

from __future__ import annotations

from lark import Tree

from glint.compiler.glsl.ast import binary_parts, first_child

from ...context import Node

# Parents in which `a * b` needs no parentheses: it is a whole argument, initializer, right
# side or statement, or an operand of + / - (which bind more loosely than *).
_OPEN_PARENTS = {"arguments", "declarator", "jump_statement", "expression_statement", "ternary"}


# The kinds of node in which `writes_of` (analysis/functions.py) finds writes: the others need
# not be looked at when collecting what a part of the code writes.
WRITERS = ("assignment", "prefix", "postfix", "call")


def needs_parens(node: Node, parent: Tree | None) -> bool:
    if parent is None or parent.data in _OPEN_PARENTS:
        return False
    if parent.data in ("assignment", "index"):
        return first_child(parent) is node  # the target, or the indexed base
    if parent.data == "binary":
        left, op, _ = binary_parts(parent)
        # a*a + b, b - a*a, a*a * b and a*a / b group as written (left associative)
        return not (op in ("+", "-") or (op in ("*", "/") and left is node))
    return True


BUILTINS: set[str] = set()


def load_builtins() -> None:
    from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

    BUILTINS.update(BUILTIN_FUNCTIONS)


load_builtins()
