"""The functions of a file with their locals: each local's type and initializer, which
variables the function writes after declaring them (assignments, ++/--, out arguments), the
one value of a local that is never written again, and which functions mainImage runs."""

from __future__ import annotations

from dataclasses import dataclass, field

from lark import Token, Tree

from glint.compiler.glsl.ast import (
    ConditionDeclaration,
    FunctionDefinition,
    FunctionPrototype,
    VariableDeclaration,
    first_child,
    operand,
)

from ..context import LintContext, Node, walk
from .syntax import call_args, call_name, calls_in, root_var, var_name


@dataclass
class Function:
    """A function definition with its parameters and locals by name, and what it writes (the
    semantic model's view of a function, with the values it returns, is values.Function)."""

    name: str
    node: Tree  # function_definition
    body: Tree  # compound_statement
    params: dict[str, tuple[str, str]]  # name -> (qualifier, type)
    param_order: list[str]
    locals: dict[str, str] = field(default_factory=dict)  # name -> type
    init: dict[str, Node] = field(default_factory=dict)  # name -> initializer (first decl)
    declared_twice: set[str] = field(default_factory=set)
    written: set[str] = field(default_factory=set)  # assigned after declaration, ++, out args

    def type_of(self, name: str) -> str | None:
        if name in self.locals:
            return self.locals[name]
        if name in self.params:
            return self.params[name][1]
        return None

    def value_of(self, name: str) -> Node | None:
        """The initializer of a local that is never written again (its one value)."""
        if name in self.declared_twice or name in self.written:
            return None
        return self.init.get(name)


def _type_text(node: Node) -> str:
    return " ".join(str(t) for t in _tokens(node))


def _tokens(node: Node) -> list[Token]:
    if isinstance(node, Token):
        return [node]
    out: list[Token] = []
    for child in node.children:
        out += _tokens(child)
    return out


def _prototype(proto: Tree) -> tuple[str, dict[str, tuple[str, str]], list[str]]:
    view = FunctionPrototype(proto)
    params: dict[str, tuple[str, str]] = {}
    order: list[str] = []
    for param in view.parameters:
        pname = param.name
        if pname:
            qualifier = param.qualifier
            qual = _type_text(qualifier.syntax) if qualifier is not None else ""
            params[pname] = (qual, _type_text(param.type.syntax))
            order.append(pname)
    return view.name, params, order


def functions(ctx: LintContext) -> list[Function]:
    """Every function definition of the file, analysed once per file."""
    cached = ctx.cache.get("functions")
    if cached is not None:
        return cached  # type: ignore[no-any-return]
    result: list[Function] = []
    if ctx.tree is not None:
        defs = [n for n in ctx.tree.children if isinstance(n, Tree)
                and n.data == "function_definition"]  # fmt: skip
        out_params = {}
        for node in defs:
            name, params, order = _prototype(FunctionDefinition(node).prototype.syntax)
            out_params[name] = [i for i, p in enumerate(order) if "out" in params[p][0]]
        for node in defs:
            definition = FunctionDefinition(node)
            name, params, order = _prototype(definition.prototype.syntax)
            fn = Function(name, node, definition.body, params, order)
            _collect(fn, out_params)
            result.append(fn)
    ctx.cache["functions"] = result
    return result


def function_map(ctx: LintContext) -> dict[str, Function]:
    return {f.name: f for f in functions(ctx)}


def _collect(fn: Function, out_params: dict[str, list[int]]) -> None:
    for node in walk(fn.body):
        if node.data == "variable_declaration":
            decl = VariableDeclaration(node)
            typ = _type_text(decl.type.type.syntax)
            for declarator in decl.declarators:
                name = declarator.name
                if name in fn.locals or name in fn.params:
                    fn.declared_twice.add(name)
                fn.locals[name] = typ
                init = declarator.initializer
                if isinstance(init, Tree):
                    fn.init.setdefault(name, init)
        elif node.data == "condition_declaration":
            fn.declared_twice.add(ConditionDeclaration(node).name)
        fn.written |= writes_of(node, out_params)


def writes_of(node: Tree, out_params: dict[str, list[int]]) -> set[str]:
    """Variables the node itself writes: assignment targets, ++/--, out/inout arguments."""
    if node.data == "assignment":
        name = root_var(first_child(node))
        return {name} if name else set()
    if node.data in ("prefix", "postfix"):
        name = root_var(operand(node))
        return {name} if name else set()
    if node.data == "call":
        callee = call_name(node)
        if callee in out_params:
            args = call_args(node)
            return {n for i in out_params[callee] if i < len(args) and (n := root_var(args[i]))}
    return set()


def out_param_map(ctx: LintContext) -> dict[str, list[int]]:
    return {f.name: [i for i, p in enumerate(f.param_order) if "out" in f.params[p][0]]
            for f in functions(ctx)}  # fmt: skip


def resolve(node: Node, fn: Function | None, depth: int = 4) -> Node:
    """Follow a local that has one value to that value (a few steps at most)."""
    while depth > 0 and fn is not None:
        name = var_name(node)
        value = fn.value_of(name) if name else None
        if value is None:
            break
        node, depth = value, depth - 1
    return node


def callable_from_main(ctx: LintContext) -> set[str] | None:
    """Names of the functions mainImage calls, directly or through others (None without one)."""
    defined = function_map(ctx)
    if "mainImage" not in defined:
        return None
    seen = {"mainImage"}
    todo = ["mainImage"]
    while todo:
        fn = defined[todo.pop()]
        for call in calls_in(fn.body):
            name = call_name(call)
            if name in defined and name not in seen:
                seen.add(name)
                todo.append(name)
    return seen
