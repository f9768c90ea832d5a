"""Helpers shared by the portability rules: ES 1.00 detection, the names a file defines, the
mainImage signature check (P001, P002), prototypes and a map from node to parent."""

from __future__ import annotations

from lark import Tree

from glint.compiler.glsl.ast import (
    ConditionDeclaration,
    Declarator,
    FunctionDefinition,
    FunctionPrototype,
    VariableDeclaration,
)

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
        definition = FunctionDefinition.cast(node)
        proto = FunctionPrototype.cast(definition.prototype.syntax if definition else node)
        if proto is not None:
            names.add(proto.name)
        if node.data == "variable_declaration":
            names.update(d.name for d in VariableDeclaration(node).declarators)
    return names


def declares_name(node: Tree, name: str) -> bool:
    """Whether a local of that name is declared anywhere under the node."""
    return any(
        (Declarator(sub) if sub.data == "declarator" else ConditionDeclaration(sub)).name == name
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
            node = FunctionDefinition(node).prototype.syntax
        if isinstance(node, Tree) and node.data == "function_prototype":
            found.append(node)
    return found
