"""The functions of a file with their locals: each local's type and initializer, which
variables the function writes after declaring them (assignments, ++/--, out arguments), the
one value of a local that is never written again, and which functions mainImage runs. A view
by name of what the binder (compiler/glsl/binder.py) resolved, for the rules that think in
names."""

from __future__ import annotations

from dataclasses import dataclass, field

from lark import Tree

from glint.compiler.glsl.ast import FunctionDefinition, first_child, operand
from glint.compiler.glsl.types import array_base

from ..context import LintContext, Node
from .syntax import call_args, call_name, root_var, var_name


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


def functions(ctx: LintContext) -> list[Function]:
    """Every function definition of the file, analysed once per file."""
    return ctx.memo(_functions)


def _functions(ctx: LintContext) -> list[Function]:
    """The binder's functions (binder.py), seen by name: each definition's parameters and
    locals, and the names its body writes."""
    if ctx.tree is None:
        return []
    result: list[Function] = []
    for bound in ctx.bindings.defined:
        params = {
            p.name: (" ".join(p.qualifiers), _base(p.type)) for p in bound.parameters if p.name
        }
        order = [p.name for p in bound.parameters if p.name]
        body = FunctionDefinition(bound.definition).body  # type: ignore[arg-type]
        fn = Function(bound.name, bound.definition, body, params, order)  # type: ignore[arg-type]
        for local in bound.locals:
            name = local.name
            if local.node is not None and local.node.data == "condition_declaration":
                fn.declared_twice.add(name)  # a while's own variable: not a local's one value
                continue
            if name in fn.locals or name in fn.params:
                fn.declared_twice.add(name)
            fn.locals[name] = _base(local.type)
            if isinstance(local.initializer, Tree):
                fn.init.setdefault(name, local.initializer)
        fn.written = bound.written_names
        result.append(fn)
    return result


def _base(type_: str | None) -> str:
    """The declared type, an array's element type for an array (`vec3 c[4]` -> vec3): what
    the rules compare a name's type with is what the name's elements hold."""
    return array_base(type_) if type_ else ""


def function_map(ctx: LintContext) -> dict[str, Function]:
    return {f.name: f for f in functions(ctx)}


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
    """Names of the functions mainImage calls, directly or through others (None without one):
    the binder's call graph."""
    if ctx.tree is None:
        return None
    bindings = ctx.bindings
    roots = [f for f in bindings.defined if f.name == "mainImage"]
    if not roots:
        return None
    return {f.name for f in bindings.reachable(roots) if f.definition is not None}


def function_at(fns: list[Function], node: Node) -> Function | None:
    """The function whose definition holds the node (by position), None at file scope."""
    start = getattr(getattr(node, "meta", None), "start_pos", None)
    if start is None:
        return None
    for fn in fns:
        meta = fn.node.meta
        if not meta.empty and meta.start_pos <= start < meta.end_pos:
            return fn
    return None
