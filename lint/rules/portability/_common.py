"""Helpers shared by the portability rules: ES 1.00 detection, the names a file defines, the
mainImage signature check (P001, P002), prototypes and a map from node to parent."""

from __future__ import annotations

from lark import Token, Tree

from ...analysis.syntax import parameter_parts
from ...context import LintContext, walk_kind


def is_es1(ctx: LintContext) -> bool:
    """A complete `#version 100` (or desktop 1.x) shader, where the ES 1.00 names are right."""
    version = ctx.pre.version if ctx.pre is not None else None
    return bool(version) and version.split()[0] in ("100", "110", "120")  # type: ignore[union-attr]


def defined_names(ctx: LintContext) -> set[str]:
    """Every function and global variable the file defines."""
    names: set[str] = set()
    assert ctx.tree is not None
    for node in ctx.tree.children:
        if not isinstance(node, Tree):
            continue
        proto = node.children[0] if node.data == "function_definition" else node
        if isinstance(proto, Tree) and proto.data == "function_prototype":
            names.add(str(proto.children[1]))
        if node.data == "variable_declaration":
            names.update(str(d.children[0]) for d in node.children[1:] if isinstance(d, Tree))
    return names


def declares_name(node: Tree, name: str) -> bool:
    """Whether a local of that name is declared anywhere under the node."""
    return any(
        any(isinstance(c, Token) and c == name for c in sub.children)
        for sub in walk_kind(node, "declarator", "condition_declaration")
    )


def signature_problem(ret: str, params: list[Tree]) -> str | None:
    """What is wrong with a mainImage signature; None when ShaderToy can call it."""
    parts = [parameter_parts(p) for p in params]
    if len(parts) != 2:
        return f"it takes {len(parts)} parameter{'s' if len(parts) != 1 else ''}, not 2"
    (q0, t0, a0, _), (q1, t1, a1, _) = parts
    if t0 != "vec4" or a0 or q0 not in ("out", "inout"):
        return "its first parameter must be `out vec4` (the pixel's colour)"
    if t1 != "vec2" or a1 or q1 != "in":
        return "its second parameter must be `in vec2` (the pixel's coordinates)"
    if ret != "void":
        return "it must return void"
    return None


def function_prototypes(tree: Tree) -> list[Tree]:
    """The prototypes of every function the file defines or declares."""
    found = []
    for node in tree.children:
        if isinstance(node, Tree) and node.data == "function_definition":
            node = node.children[0]  # type: ignore[assignment]
        if isinstance(node, Tree) and node.data == "function_prototype":
            found.append(node)
    return found
