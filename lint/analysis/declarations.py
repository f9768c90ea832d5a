"""What declarations declare, read from the parse tree: the variables of a declaration (name,
type, initializer), a function's parameters, and the members of the file's structs. Shared by
the semantic model (model.py) and the cheaper typing pass (expression_types.py), which must
agree on every type."""

from __future__ import annotations

from collections.abc import Iterable

from lark import Tree

from glint.compiler.glsl.ast import (
    FunctionDefinition,
    Parameter,
    StructSpecifier,
    VariableDeclaration,
)
from glint.compiler.glsl.binder import array_text

from ..context import Node
from .syntax import spec_text


def declared_variables(node: Tree) -> tuple[bool, list[tuple[str, str, Node | None]]]:
    """Whether a variable declaration is const, and its (name, type, initializer)s."""
    decl_view = VariableDeclaration(node)
    full_type = decl_view.type
    base = spec_text(full_type.type.syntax)
    declared: list[tuple[str, str, Node | None]] = []
    for declarator in decl_view.declarators:
        array = declarator.array
        arrays = array_text(array) if array is not None else ""
        declared.append((declarator.name, base + arrays, declarator.initializer))
    return full_type.is_const, declared


def parameter(node: Tree) -> tuple[str, str, str]:
    """A parameter declaration's (qualifiers, type, name); the name is "" when unnamed."""
    param = Parameter(node)
    qualifier = param.qualifier
    words = " ".join(qualifier.words) if qualifier is not None else ""
    array = param.array
    arrays = array_text(array) if array is not None else ""
    return words, spec_text(param.type.syntax) + arrays, param.name or ""


def signature(definition: Tree) -> tuple[str, str, list[tuple[str, str, str]]]:
    """A function definition's (name, return type, parameters); a lone `void` parameter list
    is no parameter."""
    proto = FunctionDefinition(definition).prototype
    params = [parameter(p.syntax) for p in proto.parameters]
    params = [p for p in params if p[1] != "void" or p[2]]
    return proto.name, spec_text(proto.return_type.type.syntax), params


def struct_members(specifiers: Iterable[Tree]) -> dict[str, dict[str, str]]:
    """Each named struct's members and their types, from its struct_specifier nodes (a later
    struct of the same name wins)."""
    structs: dict[str, dict[str, str]] = {}
    for node in specifiers:
        struct = StructSpecifier(node)
        members: dict[str, str] = {}
        for member in struct.members:
            base = spec_text(member.type.syntax)
            for decl in member.declarators:
                array = decl.array
                members[decl.name] = base + (array_text(array) if array is not None else "")
        name = struct.name
        if name:
            structs[name] = members
    return structs
