"""What declarations declare, read from the parse tree: the variables of a declaration (name,
type, initializer), a function's parameters, and the members of the file's structs. Shared by
the semantic model (model.py) and the cheaper typing pass (expression_types.py), which must
agree on every type."""

from __future__ import annotations

from collections.abc import Iterable

from lark import Token, Tree

from ..context import Node
from .syntax import array_text, is_tree, spec_text


def declared_variables(node: Tree) -> tuple[bool, list[tuple[str, str, Node | None]]]:
    """Whether a variable declaration is const, and its (name, type, initializer)s."""
    full_type = node.children[0]
    spec = next(c for c in full_type.children if is_tree(c, "type_specifier"))
    base = spec_text(spec)  # type: ignore[arg-type]
    const = any(
        is_tree(q, "type_qualifier") and "const" in (str(t) for t in q.children)
        for q in full_type.children
    )
    declared: list[tuple[str, str, Node | None]] = []
    for decl in node.children[1:]:
        if not is_tree(decl, "declarator"):
            continue
        name = str(decl.children[0])
        arrays = [array_text(c) for c in decl.children[1:] if is_tree(c, "array_specifier")]
        init = next((c for c in decl.children[1:] if not is_tree(c, "array_specifier")), None)
        declared.append((name, base + "".join(arrays), init))
    return const, declared


def parameter(node: Tree) -> tuple[str, str, str]:
    """A parameter declaration's (qualifiers, type, name); the name is "" when unnamed."""
    qualifier = " ".join(
        str(t) for q in node.children if is_tree(q, "type_qualifier") for t in q.children
    )
    spec = next(c for c in node.children if is_tree(c, "type_specifier"))
    name = next((str(c) for c in node.children if isinstance(c, Token)), "")
    arrays = [array_text(c) for c in node.children if is_tree(c, "array_specifier")]
    return qualifier, spec_text(spec) + "".join(arrays), name  # type: ignore[arg-type]


def signature(definition: Tree) -> tuple[str, str, list[tuple[str, str, str]]]:
    """A function definition's (name, return type, parameters); a lone `void` parameter list
    is no parameter."""
    proto = definition.children[0]
    full_type = proto.children[0]
    plist = proto.children[2] if len(proto.children) > 2 else None
    params = [parameter(p) for p in plist.children] if is_tree(plist, "parameter_list") else []
    params = [p for p in params if p[1] != "void" or p[2]]
    spec = next(c for c in full_type.children if is_tree(c, "type_specifier"))
    return str(proto.children[1]), spec_text(spec), params  # type: ignore[arg-type]


def struct_members(specifiers: Iterable[Tree]) -> dict[str, dict[str, str]]:
    """Each named struct's members and their types, from its struct_specifier nodes (a later
    struct of the same name wins)."""
    structs: dict[str, dict[str, str]] = {}
    for node in specifiers:
        name = next((str(c) for c in node.children if isinstance(c, Token)), None)
        members: dict[str, str] = {}
        for member in node.children:
            if not is_tree(member, "struct_member"):
                continue
            spec = next(c for c in member.children if is_tree(c, "type_specifier"))
            for decl in member.children:
                if is_tree(decl, "struct_declarator"):
                    arrays = [array_text(a) for a in decl.children[1:]]
                    members[str(decl.children[0])] = spec_text(spec) + "".join(arrays)
        if name:
            structs[name] = members
    return structs
