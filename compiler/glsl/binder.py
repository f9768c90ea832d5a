"""The binder: one pass over a parsed file that names what every identifier means.

It gives, as typed objects (as ruff's `SemanticModel` does for Python):

- every declaration as a `Symbol` (a global, local, parameter, function, struct or struct
  field) with its type (in `types.py`'s spelling: `vec3`, `float[3]`, a struct's name), its
  qualifiers, the node and token that declare it, and the `Scope` it lives in;
- the scopes, nested, each with the node that opens it;
- every use of a variable's name resolved to its symbol (`Bindings.symbol_of`), reads and
  writes told apart: an assignment's target, `++`/`--`, an `out` or `inout` argument (a
  compound assignment, `++` and `inout` both read and write);
- the call graph: each function's callees and callers (prototypes merged with their
  definitions, overloads told apart by arity and then by argument types), what the entry
  point reaches, and which functions are recursive;
- a summary per defined function: which `out`/`inout` parameters are written on every path
  to its exits, and whether the end of its body is reachable (a non-void function then
  returns nothing).

Names are resolved as GLSL scopes them: a declaration is visible after its declarator (so
`float x = x;` reads an outer `x`), a `for` or `while` opens a scope for what its head
declares, a compound statement opens one, and the function's parameters live in the scope
of its body. The walk is linear in the size of the tree; expressions are walked without
recursion (a long chain of `+` nests as deep as it is long).
"""

from __future__ import annotations

import gc
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from typing import Literal

from lark import Token, Tree

from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import (
    ArraySpecifier,
    BlockDeclaration,
    ConditionDeclaration,
    FunctionDefinition,
    FunctionPrototype,
    Parameter,
    StructSpecifier,
    TypeSpecifier,
    VariableDeclaration,
    callee_name,
    for_parts,
    token_text,
)
from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

Node = Tree | Token

SymbolKind = Literal["global", "local", "parameter", "function", "struct", "field", "builtin"]
ScopeKind = Literal["builtin", "file", "function", "block", "loop", "switch", "struct"]

# The kinds of symbol a variable's name can mean.
VARIABLE_KINDS = frozenset({"global", "local", "parameter", "builtin"})

# Builtin functions of GLSL ES 3.00 with `out` parameters, their directions by position.
BUILTIN_DIRECTIONS: dict[str, tuple[str, ...]] = {"modf": ("in", "out")}

ENTRY_POINTS = ("mainImage", "main")


# --- what the binder gives -------------------------------------------------------------------


@dataclass(eq=False, slots=True)
class Scope:
    """A region of the file where names are declared: the file, a function (its parameters
    and the top level of its body), a block, a loop's head, a switch, a struct's members."""

    kind: ScopeKind
    node: Tree | None  # the node that opens it (None for the builtin and file scopes' start)
    parent: Scope | None
    symbols: dict[str, list[Symbol]] = field(default_factory=dict)  # by name, in order
    children: list[Scope] = field(default_factory=list)

    def lookup(self, name: str) -> Symbol | None:
        """The latest declaration of `name` visible here (this scope, then its parents)."""
        scope: Scope | None = self
        while scope is not None:
            found = scope.symbols.get(name)
            if found:
                return found[-1]
            scope = scope.parent
        return None

    def declare(self, symbol: Symbol) -> None:
        self.symbols.setdefault(symbol.name, []).append(symbol)

    def __iter__(self) -> Iterator[Symbol]:
        for declared in self.symbols.values():
            yield from declared

    def __repr__(self) -> str:
        opened = self.node.data if self.node is not None else "-"
        return f"Scope({self.kind}, {opened}, {sorted(self.symbols)})"


@dataclass(eq=False, slots=True)
class Use:
    """A name in an expression, with what it means. A write that also reads the old value
    (`x += 1.`, `x++`, an `inout` argument) has both flags; a partial write (`v.x = 1.`,
    `a[i] = 0.`) is a write that leaves the rest as it was, and reads nothing."""

    node: Tree  # the `variable` node
    symbol: Symbol | None  # None: a name the file does not declare
    read: bool
    write: bool
    function: Function | None  # the function the use is in (None at file level)

    @property
    def name(self) -> str:
        return str(self.node.children[0])


@dataclass(eq=False, slots=True)
class Symbol:
    """A declared name."""

    name: str
    kind: SymbolKind
    type: str | None  # `types.py`'s spelling; a function's return type; None for a struct
    scope: Scope
    node: Tree | None = None  # declarator, parameter, struct_specifier, struct_declarator ...
    token: Token | None = None  # the name where it is declared
    qualifiers: tuple[str, ...] = ()  # `const`, `uniform`, `in`, `out`, `inout`, `highp` ...
    initializer: Node | None = None
    uses: list[Use] = field(default_factory=list)
    function: Function | None = None  # a parameter's or local's function; a function's own

    @property
    def is_const(self) -> bool:
        return "const" in self.qualifiers

    @property
    def direction(self) -> str:
        """A parameter's `in`, `out` or `inout` ("in" for anything else)."""
        for word in ("inout", "out"):
            if word in self.qualifiers:
                return word
        return "in"

    @property
    def is_output(self) -> bool:
        """An `out` or `inout` parameter."""
        return self.kind == "parameter" and self.direction != "in"

    @property
    def reads(self) -> list[Use]:
        return [u for u in self.uses if u.read]

    @property
    def writes(self) -> list[Use]:
        return [u for u in self.uses if u.write]

    def __repr__(self) -> str:
        return f"Symbol({self.kind} {self.type} {self.name})"


@dataclass(eq=False, slots=True)
class CallSite:
    """A call of a function: the callee as resolved (None for a builtin, a name the file
    does not define, or overloads the binder cannot choose between), and the function it is
    in (None at file level)."""

    node: Tree
    name: str
    callee: Function | None
    caller: Function | None
    # the functions it may call: the callee, else every overload of the name that could be
    # meant (of its arity, or all of them): the call graph's edges
    targets: list[Function] = field(default_factory=list)


@dataclass(eq=False)
class Function:
    """A function of the file: its prototypes and its definition merged, one per overload."""

    name: str
    return_type: str
    parameters: list[Symbol]  # in order, unnamed ones too (name ""); `f(void)` has none
    symbol: Symbol
    definition: Tree | None = None  # function_definition, None when only declared
    prototypes: list[Tree] = field(default_factory=list)  # function_prototype nodes
    scope: Scope | None = None  # its parameters and body's top level (with a definition)
    locals: list[Symbol] = field(default_factory=list)  # in declaration order
    calls: list[CallSite] = field(default_factory=list)  # the calls in its body
    callees: set[Function] = field(default_factory=set)
    callers: set[Function] = field(default_factory=set)
    uses: list[Use] = field(default_factory=list)  # every use of a name in its body
    _resolved: dict[int, Use] | None = field(default=None, repr=False)
    _summary: Summary | None = field(default=None, repr=False)

    @property
    def summary(self) -> Summary | None:
        """What the body does on every path (None without a definition); made when asked."""
        if self._summary is None and self.definition is not None and self._resolved is not None:
            body = FunctionDefinition(self.definition).body
            self._summary = _summarise(self, self._resolved, body)
        return self._summary

    @property
    def parameter_types(self) -> tuple[str | None, ...]:
        return tuple(p.type for p in self.parameters)

    @property
    def arity(self) -> int:
        return len(self.parameters)

    @property
    def outputs(self) -> list[Symbol]:
        """The `out` and `inout` parameters."""
        return [p for p in self.parameters if p.is_output]

    @property
    def written_names(self) -> set[str]:
        """The names the body writes (any symbol, a global's and an undeclared one too)."""
        return {u.name for u in self.uses if u.write}

    def __repr__(self) -> str:
        return f"Function({self.return_type} {self.name}{self.parameter_types})"


@dataclass(eq=False, slots=True)
class Summary:
    """What a function's body does on every path, read from its statements alone (no values:
    every loop may run zero times unless it has no condition, every `if` either way)."""

    # the `out`/`inout` parameters written in full before every exit (each return and the end)
    written_on_every_path: frozenset[Symbol]
    # whether the end of the body is reachable: a non-void function then returns nothing
    end_reachable: bool
    returns: list[Tree]  # the `return` statements


@dataclass(eq=False)
class Bindings:
    """The binder's results for one file."""

    tree: Tree
    builtins: Scope
    file: Scope
    scopes: list[Scope]
    symbols: list[Symbol]  # every declaration, in source order (builtins left out)
    functions: list[Function]  # one per overload, in order of first declaration
    # the functions with a body, in source order (a second body of one overload, an error,
    # is a function of its own here)
    defined: list[Function]
    calls: list[CallSite]
    uses: list[Use]
    _resolved: dict[int, Use]
    _scope_at: dict[int, Scope]
    _defining: dict[int, Function]

    def symbol_of(self, node: Node) -> Symbol | None:
        """The symbol a `variable` node names (None when the file does not declare it and
        the target does not provide it, or for a node that is no use of a name)."""
        use = self._resolved.get(id(node))
        return use.symbol if use is not None else None

    def use_of(self, node: Node) -> Use | None:
        return self._resolved.get(id(node))

    def scope_of(self, node: Node) -> Scope | None:
        """The scope a scope-opening node (function_definition, compound_statement, a loop,
        switch_statement, struct_specifier) opens."""
        return self._scope_at.get(id(node))

    def functions_named(self, name: str) -> list[Function]:
        return [f for f in self.functions if f.name == name]

    def function_of(self, definition: Tree) -> Function | None:
        """The function a function_definition defines."""
        return self._defining.get(id(definition))

    @property
    def entry(self) -> Function | None:
        """The defined `mainImage`, else the defined `main`."""
        for name in ENTRY_POINTS:
            for fn in self.functions:
                if fn.name == name and fn.definition is not None:
                    return fn
        return None

    def reachable(self, roots: list[Function] | None = None) -> set[Function]:
        """The functions the roots (the entry point) call, directly or not, the roots too."""
        if roots is None:
            entry = self.entry
            roots = [entry] if entry is not None else []
        seen = set(roots)
        todo = list(roots)
        while todo:
            for callee in todo.pop().callees:
                if callee not in seen:
                    seen.add(callee)
                    todo.append(callee)
        return seen

    @property
    def recursive(self) -> set[Function]:
        """The functions on a cycle of calls (GLSL forbids them; a file may still try)."""
        return {f for f in self.functions if f in self.reachable(list(f.callees))}


# --- types as `types.py` spells them ---------------------------------------------------------


def array_text(spec: Tree) -> str:
    """`[3]`, `[2][4]`; a size that is not a literal integer is left empty (`[]`)."""
    sizes = [
        token_text(c) if isinstance(c, Tree) and c.data == "int_literal" else ""
        for c in ArraySpecifier(spec).sizes
    ]
    return "".join(f"[{s}]" for s in sizes) if sizes else "[]"


def type_text(spec: Tree, array: Tree | None = None) -> str:
    """A type_specifier's type, with a declarator's array part (`float a[3]`) after it."""
    view = TypeSpecifier(spec)
    inner = view.array
    text = view.name + (array_text(inner) if inner is not None else "")
    return text + array_text(array) if array is not None else text


# --- the pass --------------------------------------------------------------------------------

_ASSIGN_READS = frozenset({"+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "^=", "|="})


def bind(tree: Tree, provided: Mapping[str, str] | None = None) -> Bindings:
    """Bind a parsed file. `provided`: the names the target declares (ShaderToy's uniforms,
    `gl_FragCoord`) with their types."""
    # The results are cycles (a scope and its symbols, a symbol and its uses), all alive
    # until the file is done: the cycle collector, run again and again as they are made,
    # would walk every tree alive for nothing (it doubled the pass's time on the corpus).
    paused = gc.isenabled()
    gc.disable()
    try:
        return _Binder(tree, provided or {}).run()
    finally:
        if paused:
            gc.enable()


class _Binder:
    def __init__(self, tree: Tree, provided: Mapping[str, str]) -> None:
        self.tree = tree
        self.builtins = Scope("builtin", None, None)
        for name, ty in provided.items():
            self.builtins.declare(Symbol(name, "builtin", ty, self.builtins))
        self.file = Scope("file", tree, self.builtins)
        self.builtins.children.append(self.file)
        self.scopes: list[Scope] = [self.builtins, self.file]
        self.symbols: list[Symbol] = []
        self.functions: list[Function] = []
        self.overloads: dict[str, list[Function]] = {}
        self.calls: list[CallSite] = []
        self.uses: list[Use] = []
        self.resolved: dict[int, Use] = {}
        self.scope_at: dict[int, Scope] = {id(tree): self.file}
        self.structs: dict[str, dict[str, str]] = {}
        self.function: Function | None = None  # the function being walked
        self.defined: list[Function] = []

    def run(self) -> Bindings:
        # Functions first, so a call binds to a function declared after it (as the old
        # by-name lookups did) and a prototype merges with its definition.
        for node in self.tree.children:
            if isinstance(node, Tree):
                if node.data == "function_definition":
                    self._declare_function(FunctionDefinition(node).prototype.syntax, node)
                elif node.data == "function_prototype":
                    self._declare_function(node, None)
        for node in self.tree.children:
            if isinstance(node, Tree):
                self._external(node)
        for call in self.calls:
            if call.caller is not None:
                for target in call.targets:
                    call.caller.callees.add(target)
                    target.callers.add(call.caller)
        return Bindings(
            self.tree,
            self.builtins,
            self.file,
            self.scopes,
            self.symbols,
            self.functions,
            self.defined,
            self.calls,
            self.uses,
            self.resolved,
            self.scope_at,
            {id(f.definition): f for f in self.defined},
        )

    # --- scopes and declarations ---------------------------------------------------------

    def _open(self, kind: ScopeKind, node: Tree, parent: Scope) -> Scope:
        scope = Scope(kind, node, parent)
        parent.children.append(scope)
        self.scopes.append(scope)
        self.scope_at[id(node)] = scope
        return scope

    def _declare(self, symbol: Symbol) -> Symbol:
        symbol.scope.declare(symbol)
        self.symbols.append(symbol)
        symbol.function = self.function
        if self.function is not None and symbol.kind == "local":
            self.function.locals.append(symbol)
        return symbol

    def _declare_function(self, proto: Tree, definition: Tree | None) -> None:
        view = FunctionPrototype(proto)
        name = view.name
        params = _parameters(view, Scope("function", definition or proto, self.file))
        ptypes = tuple(p.type for p in params)
        for fn in self.overloads.get(name, ()):
            if fn.parameter_types == ptypes:
                break
        else:
            rtype = type_text(view.return_type.type.syntax)
            qualifiers = tuple(view.return_type.qualifiers)
            symbol = Symbol(name, "function", rtype, self.file, proto, view.name_token, qualifiers)
            fn = Function(name, rtype, params, symbol)
            symbol.function = fn
            self.file.declare(symbol)
            self.symbols.append(symbol)
            self.functions.append(fn)
            self.overloads.setdefault(name, []).append(fn)
        fn.prototypes.append(proto)
        if definition is not None and fn.definition is None:
            fn.definition = definition
            fn.parameters = params  # the definition's names are the ones the body reads

    def _external(self, node: Tree) -> None:
        kind = node.data
        if kind == "function_definition":
            self._function_body(node)
        elif kind == "function_prototype":
            self._prototype_types(node, self.file)
        elif kind == "variable_declaration":
            self._variables(node, self.file, "global")
        elif kind == "block_declaration":
            self._block(node)
        elif kind == "precision_declaration" or kind == "qualifier_declaration":
            pass

    def _prototype_types(self, proto: Tree, scope: Scope) -> None:
        """Structs declared in a prototype's types, and the uses in its array sizes."""
        view = FunctionPrototype(proto)
        self._type(view.return_type.type.syntax, scope)
        for param in view.parameters:
            self._type(param.type.syntax, scope)
            if param.array is not None:
                self._expression(param.array, scope)

    def _type(self, spec: Tree, scope: Scope) -> None:
        """A struct a type specifier declares in place, and the uses in its array sizes."""
        view = TypeSpecifier(spec)
        struct = view.struct
        if struct is not None:
            self._struct(struct, scope)
        if view.array is not None:
            self._expression(view.array, scope)

    def _struct(self, struct: StructSpecifier, scope: Scope) -> None:
        members = self._open("struct", struct.syntax, scope)
        fields: dict[str, str] = {}
        for member in struct.members:
            self._type(member.type.syntax, scope)
            qualifier = member.qualifier
            words = tuple(qualifier.words) if qualifier is not None else ()
            for decl in member.declarators:
                mtype = type_text(member.type.syntax, decl.array)
                fields[decl.name] = mtype
                self._declare(Symbol(decl.name, "field", mtype, members, decl.syntax,
                                     decl.name_token, words))  # fmt: skip
                if decl.array is not None:
                    self._expression(decl.array, scope)
        name = struct.name
        if name:
            self.structs[name] = fields
            self._declare(Symbol(name, "struct", name, scope, struct.syntax,
                                 _first_token(struct.syntax)))  # fmt: skip

    def _variables(self, node: Tree, scope: Scope, kind: SymbolKind) -> None:
        decl = VariableDeclaration(node)
        full = decl.type
        self._type(full.type.syntax, scope)
        words = tuple(full.qualifiers)
        for declarator in decl.declarators:
            if declarator.array is not None:
                self._expression(declarator.array, scope)
            init = declarator.initializer
            if init is not None:
                self._expression(
                    init, scope
                )  # before the name is visible: `x = x` reads an outer x
            vtype = type_text(full.type.syntax, declarator.array)
            self._declare(Symbol(declarator.name, kind, vtype, scope, declarator.syntax,
                                 declarator.name_token, words, init))  # fmt: skip

    def _block(self, node: Tree) -> None:
        """`uniform B { vec3 a; } b;`: the instance is a global, else each member is one."""
        block = BlockDeclaration(node)
        words = tuple(block.qualifier.words)
        instance = block.instance_name
        if instance is not None:
            token = next(t for t in node.children[2:] if isinstance(t, Token))
            symbol = Symbol(instance, "global", block.block_name, self.file, node, token, words)
            self._declare(symbol)
            return
        for member in block.members:
            for decl in member.declarators:
                mtype = type_text(member.type.syntax, decl.array)
                self._declare(Symbol(decl.name, "global", mtype, self.file, decl.syntax,
                                     decl.name_token, words))  # fmt: skip

    # --- functions and statements ------------------------------------------------------------

    def _function_body(self, node: Tree) -> None:
        definition = FunctionDefinition(node)
        proto = definition.prototype.syntax
        self._prototype_types(proto, self.file)
        name = definition.name
        fn = next((f for f in self.overloads.get(name, ()) if f.definition is node), None)
        scope = self._open("function", node, self.file)
        if fn is None:
            # a second definition of one overload (an error): bind its body on its own
            rtype = type_text(definition.prototype.return_type.type.syntax)
            symbol = Symbol(name, "function", rtype, self.file, proto)
            fn = Function(
                name, rtype, _parameters(definition.prototype, scope), symbol, node, [proto]
            )
            symbol.function = fn
        fn.scope = scope
        self.defined.append(fn)
        self.function = fn
        for param in fn.parameters:
            param.scope = scope
            param.function = fn
            if param.name:
                scope.declare(param)
            self.symbols.append(param)
        body = definition.body
        self.scope_at[id(body)] = scope
        for stmt in body.children:
            self._statement(stmt, scope)
        fn._resolved = self.resolved
        self.function = None

    def _statement(self, stmt: Node, scope: Scope) -> None:
        if not isinstance(stmt, Tree):
            return
        kind = stmt.data
        if kind == "compound_statement":
            inner = self._open("block", stmt, scope)
            for child in stmt.children:
                self._statement(child, inner)
        elif kind == "declaration_statement":
            decl = stmt.children[0]
            if isinstance(decl, Tree):
                if decl.data == "variable_declaration":
                    self._variables(decl, scope, "local")
                elif decl.data == "function_prototype":
                    self._prototype_types(decl, scope)
                elif decl.data == "block_declaration":
                    self._block(decl)
        elif kind == "for_statement":
            inner = self._open("loop", stmt, scope)
            init, cond, update, body = for_parts(stmt)
            self._statement(init, inner)
            for part in (cond, update):
                if part is not None:
                    self._expression(part, inner)
            self._statement(body, inner)
        elif kind == "while_statement":
            inner = self._open("loop", stmt, scope)
            cond, body = stmt.children
            declared = ConditionDeclaration.cast(cond)
            if declared is not None:
                spec = declared.type.type.syntax
                self._type(spec, inner)
                self._expression(declared.initializer, inner)
                words = tuple(declared.type.qualifiers)
                symbol = Symbol(declared.name, "local", type_text(spec), inner, declared.syntax,
                                declared.name_token, words, declared.initializer)  # fmt: skip
                self._declare(symbol)
            else:
                self._expression(cond, inner)
            self._statement(body, inner)
        elif kind == "switch_statement":
            self._expression(stmt.children[0], scope)
            inner = self._open("switch", stmt, scope)
            for child in stmt.children[1:]:
                self._statement(child, inner)
        elif kind == "if_statement":
            self._expression(stmt.children[0], scope)
            for branch in stmt.children[1:]:
                self._statement(branch, scope)
        elif kind == "do_statement":
            body, cond = stmt.children
            self._statement(body, scope)
            self._expression(cond, scope)
        elif kind == "jump_statement" or kind == "expression_statement" or kind == "case_label":
            for child in stmt.children:
                if isinstance(child, Tree):
                    self._expression(child, scope)
        elif kind == "empty_statement" or kind == "default_label":
            pass
        else:  # a bare expression where a statement goes (a hand-built tree)
            self._expression(stmt, scope)

    # --- expressions -----------------------------------------------------------------------

    def _expression(self, expr: Node, scope: Scope) -> None:
        """Bind every name in the expression, in source order. Without recursion: the stack
        holds (node, read, write), children pushed last first."""
        stack: list[tuple[Node, bool, bool]] = [(expr, True, False)]
        while stack:
            node, read, write = stack.pop()
            if not isinstance(node, Tree):
                continue
            kind = node.data
            if kind == "variable":
                self._use(node, scope, read, write)
            elif kind == "assignment":
                target, op, value = node.children
                stack.append((value, True, False))
                stack.append((target, str(op) in _ASSIGN_READS, True))
            elif kind == "prefix" or kind == "postfix":
                target = node.children[1] if kind == "prefix" else node.children[0]
                stack.append((target, True, True))
            elif kind == "field":
                base, _name = node.children
                # `v.x = 1.` writes part of v and reads none of it
                stack.append((base, read, write))
            elif kind == "index":
                base, index = node.children
                stack.append((index, True, False))
                stack.append((base, read, write))
            elif kind == "call":
                self._call(node, scope, stack)
            elif kind == "constructor":
                spec = node.children[0]
                if isinstance(spec, Tree):
                    self._type(spec, scope)
                for child in reversed(node.children[1:]):
                    stack.append((child, True, False))
            else:
                for child in reversed(node.children):
                    if isinstance(child, Tree):
                        stack.append((child, True, False))

    def _use(self, node: Tree, scope: Scope, read: bool, write: bool) -> None:
        symbol = scope.lookup(str(node.children[0]))
        if symbol is not None and symbol.kind not in VARIABLE_KINDS:
            symbol = None  # a function's or struct's name used as a value (an error)
        use = Use(node, symbol, read, write, self.function)
        self.uses.append(use)
        self.resolved[id(node)] = use
        if symbol is not None:
            symbol.uses.append(use)
        if self.function is not None:
            self.function.uses.append(use)

    def _call(self, node: Tree, scope: Scope, stack: list[tuple[Node, bool, bool]]) -> None:
        head = node.children[0]
        args = _arguments(node)
        name = callee_name(node)
        if name is None:  # a method, `a.length()`: the object is read
            for arg in reversed(args):
                stack.append((arg, True, False))
            stack.append((head, True, False))
            return
        callee = self._resolve_call(name, args, scope) if name in self.overloads else None
        site = CallSite(node, name, callee, self.function)
        self.calls.append(site)
        if callee is not None:
            site.targets.append(callee)
        elif name in self.overloads:
            same = [f for f in self.overloads[name] if f.arity == len(args)]
            site.targets.extend(same or self.overloads[name])
        if callee is not None:
            directions = [p.direction for p in callee.parameters]
        elif name in self.overloads:
            # no overload fits: an argument is written where any same-named one writes it
            directions = _widest(self.overloads[name], len(args))
        else:
            directions = list(BUILTIN_DIRECTIONS.get(name, ()))
        for i in reversed(range(len(args))):
            direction = directions[i] if i < len(directions) else "in"
            stack.append((args[i], direction != "out", direction != "in"))

    def _resolve_call(self, name: str, args: list[Node], scope: Scope) -> Function | None:
        candidates = [f for f in self.overloads[name] if f.arity == len(args)]
        if len(candidates) <= 1:
            return candidates[0] if candidates else None
        types = tuple(_TypeOf(self, scope).of(a) for a in args)
        for fn in candidates:
            if fn.parameter_types == types:
                return fn
        # an implicit conversion (int to float) or a type the light typing does not know
        fits = [
            f
            for f in candidates
            if all(t is None or _converts(t, p) for t, p in zip(types, f.parameter_types))  # noqa: B905
        ]
        return fits[0] if len(fits) == 1 else None


def _widest(overloads: list[Function], count: int) -> list[str]:
    found = ["in"] * count
    for fn in overloads:
        for i, p in enumerate(fn.parameters[:count]):
            if p.direction != "in":
                found[i] = "inout" if found[i] != p.direction and found[i] != "in" else p.direction
    return found


def _converts(actual: str, wanted: str | None) -> bool:
    """GLSL ES 3.00 has no implicit conversions; desktop GL converts int to float."""
    if wanted is None or actual == wanted:
        return True
    a, w = T.components(actual), T.components(wanted)
    return a is not None and w is not None and a[1] == w[1] and w[0] == "float"


class _TypeOf:
    """Just enough typing to tell overloads apart: names, literals, constructors, swizzles,
    operators and calls (`expression_types` in the linter types every expression)."""

    def __init__(self, binder: _Binder, scope: Scope) -> None:
        self.binder, self.scope = binder, scope

    def of(self, node: Node, depth: int = 0) -> str | None:
        if not isinstance(node, Tree) or depth > 20:
            return None
        kind = node.data
        if kind == "float_literal":
            return "float"
        if kind == "int_literal":
            return "uint" if str(node.children[0])[-1] in "uU" else "int"
        if kind == "bool_literal":
            return "bool"
        if kind == "variable":
            use = self.binder.resolved.get(id(node))
            symbol = use.symbol if use is not None else self.scope.lookup(str(node.children[0]))
            return symbol.type if symbol is not None and symbol.kind in VARIABLE_KINDS else None
        if kind == "constructor":
            return type_text(node.children[0])  # type: ignore[arg-type]
        if kind == "field":
            base = self.of(node.children[0], depth + 1)
            name = str(node.children[1])
            return T.swizzle(base, name) or self.binder.structs.get(base or "", {}).get(name)
        if kind == "index":
            return T.element(self.of(node.children[0], depth + 1))
        if kind == "binary":
            left, op, right = node.children
            return T.binary(str(op), self.of(left, depth + 1), self.of(right, depth + 1))
        if kind == "unary":
            return T.unary(str(node.children[0]), self.of(node.children[1], depth + 1))
        if kind in ("prefix", "postfix", "assignment"):
            return self.of(node.children[1 if kind == "prefix" else 0], depth + 1)
        if kind == "ternary":
            return self.of(node.children[1], depth + 1) or self.of(node.children[2], depth + 1)
        if kind == "sequence":
            return self.of(node.children[1], depth + 1)
        if kind == "call":
            name = callee_name(node)
            args = _arguments(node)
            if name is None:
                return "int"  # `.length()`
            if name in self.binder.overloads:
                fn = self.binder._resolve_call(name, args, self.scope)
                return fn.return_type if fn is not None else None
            if name in BUILTIN_FUNCTIONS:
                return T.builtin_return(name, [self.of(a, depth + 1) for a in args])
        return None


def _arguments(call: Tree) -> list[Node]:
    kids = call.children
    if len(kids) > 1 and isinstance(kids[1], Tree) and kids[1].data == "arguments":
        return list(kids[1].children)
    return []


def _parameters(view: FunctionPrototype, scope: Scope) -> list[Symbol]:
    params: list[Symbol] = []
    for param in view.parameters:
        ptype = _parameter_type(param)
        if ptype == "void" and not param.name:
            continue  # `f(void)`
        qualifier = param.qualifier
        words = tuple(qualifier.words) if qualifier is not None else ()
        params.append(Symbol(param.name or "", "parameter", ptype, scope, param.syntax,
                             param.name_token, words))  # fmt: skip
    return params


def _parameter_type(param: Parameter) -> str:
    return type_text(param.type.syntax, param.array)


def _first_token(node: Tree) -> Token | None:
    return next((c for c in node.children if isinstance(c, Token)), None)


# --- per-function summaries -------------------------------------------------------------------

# The components of the outputs written: (id of the parameter, component). A vector is
# tracked per component (through swizzles); anything else as a whole, and a write through an
# index or a struct member counts as a write of the whole (silence rather than a guess).
_Written = frozenset[tuple[int, int]]


class _Summariser:
    """A walk over a function's statements: which outputs are written in full on every path,
    where the paths end. A state is what is written (None: no path gets here)."""

    def __init__(self, outputs: list[Symbol], resolved: dict[int, Use]) -> None:
        self.outputs = {id(p): p for p in outputs}
        self.width = {id(p): _width(p.type) for p in outputs}
        self.resolved = resolved
        self.exits: list[_Written] = []
        self.returns: list[Tree] = []
        self.breaks: list[list[_Written]] = []  # per enclosing loop or switch

    def full(self, symbol: Symbol) -> frozenset[tuple[int, int]]:
        return frozenset((id(symbol), i) for i in range(self.width[id(symbol)]))

    def block(self, stmts: list[Node], state: _Written | None) -> _Written | None:
        for stmt in stmts:
            state = self.statement(stmt, state)
        return state

    def statement(self, stmt: Node, state: _Written | None) -> _Written | None:
        if not isinstance(stmt, Tree):
            return state
        if state is None:
            # unreachable code writes nothing that counts; its returns are still returns
            self._dead(stmt)
            return None
        kind = stmt.data
        if kind == "compound_statement":
            return self.block(stmt.children, state)
        if kind == "jump_statement":
            word = str(stmt.children[0])
            state = state | self.writes(stmt)
            if word == "return":
                self.returns.append(stmt)
                self.exits.append(state)
            elif word == "break" and self.breaks:
                self.breaks[-1].append(state)
            return None  # `discard` ends the invocation: nothing is written back
        if kind == "if_statement":
            cond, *branches = stmt.children
            state = state | self.writes(cond)
            then = self.statement(branches[0], state)
            other = self.statement(branches[1], state) if len(branches) > 1 else state
            return _join(then, other)
        if kind in ("for_statement", "while_statement"):
            update: Node | None = None
            if kind == "for_statement":
                init, cond, update, body = for_parts(stmt)
                state = self.statement(init, state)
                if state is None:
                    return None
            else:
                cond, body = stmt.children
                if isinstance(cond, Tree) and cond.data == "condition_declaration":
                    cond = cond.children[2]
            forever = cond is None or _is_true(cond)
            if cond is not None:
                state = state | self.writes(cond)
            self.breaks.append([])
            self.statement(body, state)
            breaks = self.breaks.pop()
            if forever:  # left only by a break (or a return)
                return _join(*breaks)
            return state  # the body may not run: what it writes is not certain
        if kind == "do_statement":
            body, cond = stmt.children
            self.breaks.append([])
            end = self.statement(body, state)  # a `continue` goes to the test: counted as end
            if end is not None:
                end = end | self.writes(cond)
            breaks = self.breaks.pop()
            if _is_true(cond):
                return _join(*breaks)
            return _join(end, *breaks)
        if kind == "switch_statement":
            selector, *body = stmt.children
            entry = state | self.writes(selector)
            self.breaks.append([])
            current: _Written | None = None
            has_default = False
            for child in body:
                if isinstance(child, Tree) and child.data in ("case_label", "default_label"):
                    has_default = has_default or child.data == "default_label"
                    current = _join(current, entry)  # entered here, or fallen through
                current = self.statement(child, current)
            breaks = self.breaks.pop()
            return _join(*breaks, current, *([] if has_default else [entry]))
        # an expression or declaration statement, a case label
        return state | self.writes(stmt)

    def _dead(self, stmt: Tree) -> None:
        for node in _subtrees(stmt):
            if node.data == "jump_statement" and str(node.children[0]) == "return":
                self.returns.append(node)

    def writes(self, node: Node) -> _Written:
        """The output components an expression certainly writes (not in the right of `&&`
        or `||` or in a ternary's branches, which may not run)."""
        if not self.outputs or not isinstance(node, Tree):
            return frozenset()
        found: set[tuple[int, int]] = set()
        stack: list[Node] = [node]
        while stack:
            item = stack.pop()
            if not isinstance(item, Tree):
                continue
            kind = item.data
            if kind == "ternary" or kind == "binary" and str(item.children[1]) in ("&&", "||"):
                stack.append(item.children[0])
            elif kind in ("variable", "field", "index"):
                self._lvalue(item, found, stack)
            else:
                stack.extend(item.children)
        return frozenset(found)

    def _lvalue(self, node: Tree, found: set[tuple[int, int]], stack: list[Node]) -> None:
        """A name, maybe under swizzles, members and indices: the components it writes."""
        swizzle: tuple[int, ...] | None = None
        root: Node = node
        while isinstance(root, Tree) and root.data in ("field", "index"):
            if root.data == "index":
                stack.append(root.children[1])
                swizzle = None  # through an index: the whole
            else:
                name = str(root.children[1])
                picked = T.swizzle_indices(name)
                # `v.zx.y` is `v.x`: a swizzle of a swizzle picks from the inner one
                swizzle = (tuple(picked[i] for i in swizzle if i < len(picked))
                           if swizzle is not None and picked is not None else picked)  # fmt: skip
            root = root.children[0]
        if isinstance(root, Tree) and root.data != "variable":
            stack.append(root)  # `f(o).x`: the call may write through its arguments
            return
        use = self.resolved.get(id(root)) if isinstance(root, Tree) else None
        if use is None or not use.write or use.symbol is None:
            return
        key = id(use.symbol)
        if key not in self.outputs:
            return
        width = self.width[key]
        if root is node or swizzle is None or width == 1:
            found.update((key, i) for i in range(width))
        else:
            found.update((key, i) for i in swizzle if i < width)


def _width(type_: str | None) -> int:
    parts = T.components(type_) if type_ is not None else None
    return parts[1] if parts is not None and T.is_vector(type_) else 1


def _join(*states: _Written | None) -> _Written | None:
    live = [s for s in states if s is not None]
    if not live:
        return None
    out = live[0]
    for s in live[1:]:
        out = out & s
    return out


def _is_true(node: Node) -> bool:
    return (
        isinstance(node, Tree) and node.data == "bool_literal" and str(node.children[0]) == "true"
    )


def _subtrees(node: Tree) -> Iterator[Tree]:
    stack: list[Node] = [node]
    while stack:
        item = stack.pop()
        if isinstance(item, Tree):
            yield item
            stack.extend(item.children)


def _summarise(fn: Function, resolved: dict[int, Use], body: Tree) -> Summary:
    outputs = fn.outputs
    walker = _Summariser(outputs, resolved)
    end = walker.block(body.children, frozenset())
    exits = [*walker.exits, end] if end is not None else walker.exits
    written = frozenset(p for p in outputs if all(walker.full(p) <= e for e in exits))
    return Summary(written, end is not None, walker.returns)
