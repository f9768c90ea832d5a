"""What a GLSL module defines and what it needs from elsewhere.

The catalog check compares a snippet's declared `provides`/`requires` with this, and dead-code
elimination walks `deps` from the entry points. Macros are expanded before parsing, so a macro
of the module shows up through the preprocessor's record of which macros each line expanded,
while a macro defined in *another* snippet stays an identifier and so becomes `free`.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Iterator, Mapping
from dataclasses import dataclass, field

from lark import Token, Tree

from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS, is_builtin
from glint.compiler.glsl.parser import parse_source
from glint.compiler.glsl.pptokens import significant, tokenize
from glint.compiler.glsl.preprocessor import Macro, Preprocessed


@dataclass(frozen=True)
class Param:
    qualifier: str  # e.g. "out", "in", "const in", "" when none
    type: str  # e.g. "vec3", "float[2]"
    name: str  # "" for an unnamed parameter


@dataclass
class FunctionDef:
    name: str
    return_type: str
    params: list[Param]
    prototype: str  # canonical one-line text: "float D_GGX(float NoH, float a)"
    line: int  # first line in the original file
    calls: set[str] = field(default_factory=set)  # user-level functions called
    uses: set[str] = field(default_factory=set)  # free non-call identifiers (incl. macros, types)
    end_line: int = 0  # last line in the original file


@dataclass
class ModuleSymbols:
    functions: list[FunctionDef]
    structs: list[str]
    globals: list[str]
    macros: list[str]
    defined: set[str]
    calls: set[str]
    free: set[str]
    deps: dict[str, set[str]] = field(default_factory=dict)  # name -> names it needs


def analyze(
    source: str,
    filename: str = "<input>",
    predefined: dict[str, str] | None = None,
    provided: Collection[str] = (),
) -> ModuleSymbols:
    """Symbols of one module (a snippet or a whole shader). `provided`: names the target
    defines (ShaderToy's uniforms), which are then never free."""
    tree, pre = parse_source(source, filename, predefined)
    return symbols_of(tree, pre, provided)


def symbols_of(tree: Tree, pre: Preprocessed, provided: Collection[str] = ()) -> ModuleSymbols:
    """Symbols of a tree already parsed from `pre`. The front end knows GLSL's own names
    only; what a target adds comes in `provided`."""
    return _Collector(pre, frozenset(provided)).module(tree)


def reachable(symbols: ModuleSymbols, roots: set[str]) -> set[str]:
    """Every name reached from `roots` through function, global and macro dependencies."""
    return reach(symbols.deps, roots)


def reach(deps: Mapping[str, Collection[str]], roots: set[str]) -> set[str]:
    """Every name reached from `roots` through `deps` (what each name names): one module's
    graph, or the graphs of several read apart and joined by name."""
    seen: set[str] = set()
    todo = list(roots)
    while todo:
        name = todo.pop()
        if name not in seen:
            seen.add(name)
            todo.extend(deps.get(name, ()))
    return seen


class _Scope:
    """Names declared in nested blocks of a function body."""

    def __init__(self, provided: frozenset[str] = frozenset()) -> None:
        self.frames: list[set[str] | frozenset[str]] = [provided, set()]

    def __contains__(self, name: str) -> bool:
        return any(name in frame for frame in self.frames)

    def declare(self, name: str) -> None:
        self.frames[-1].add(name)  # type: ignore[union-attr]


@dataclass
class _Refs:
    calls: set[str] = field(default_factory=set)
    uses: set[str] = field(default_factory=set)


class _Collector:
    def __init__(self, pre: Preprocessed, provided: frozenset[str]) -> None:
        self.pre = pre
        self.provided = provided
        self.functions: list[FunctionDef] = []
        self.structs: list[str] = []
        self.globals: list[str] = []
        self.deps: dict[str, set[str]] = {}

    def module(self, tree: Tree) -> ModuleSymbols:
        global_refs = _Refs()
        for node in tree.children:
            if not isinstance(node, Tree):
                continue
            if node.data == "function_definition":
                self._function(node)
            elif node.data == "variable_declaration":
                self._global_declaration(node, global_refs)
            elif node.data == "block_declaration":
                self._block(node)
        macros = self._macros()
        defined = {f.name for f in self.functions} | set(self.structs) | set(self.globals)
        defined |= set(macros)
        calls = set(global_refs.calls).union(*(f.calls for f in self.functions))
        needed = set(calls).union(*self.deps.values())
        free = {name for name in needed - defined - self.provided if not is_builtin(name)}
        return ModuleSymbols(
            functions=self.functions,
            structs=self.structs,
            globals=self.globals,
            macros=macros,
            defined=defined,
            calls=calls,
            free=free,
            deps=self.deps,
        )

    # -- top level ------------------------------------------------------------------------

    def _function(self, node: Tree) -> None:
        proto, body = node.children
        ret_spec, name, params = _prototype_parts(proto)
        scope = _Scope(self.provided)
        refs = _Refs()
        _walk(ret_spec, scope, refs)
        param_list = [_param(p) for p in params]
        for p, tree in zip(param_list, params, strict=True):
            _walk(tree, scope, refs)  # array sizes and struct types of parameters
            if p.name:
                scope.declare(p.name)
        _walk(body, scope, refs)
        refs.uses |= self._expanded(node)
        shown = [p for p in param_list if p.type != "void" or p.name]
        text = ", ".join(" ".join(w for w in (p.qualifier, _decl_text(p)) if w) for p in shown)
        ret_type = _type_text(ret_spec)
        fn = FunctionDef(
            name=name,
            return_type=ret_type,
            params=shown,
            prototype=f"{ret_type} {name}({text})",
            line=self.pre.locate(node.meta.line).line,
            calls=refs.calls,
            uses=refs.uses,
            end_line=self.pre.locate(node.meta.end_line).line,
        )
        self.functions.append(fn)
        self.deps.setdefault(name, set()).update(fn.calls | fn.uses)

    def _global_declaration(self, node: Tree, global_refs: _Refs) -> None:
        type_refs = _Refs()
        struct = _inline_struct(node.children[0])
        if struct is not None:
            struct_name = _first_token(struct, "IDENTIFIER")
            _walk(struct, _Scope(self.provided), type_refs)
            if struct_name is not None:
                self.structs.append(struct_name)
                self.deps[struct_name] = set(type_refs.uses)
                type_refs = _Refs(uses={struct_name})
        else:
            _walk(node.children[0], _Scope(self.provided), type_refs)
        for decl in _children(node, "declarator"):
            refs = _Refs(set(type_refs.calls), set(type_refs.uses))
            for part in decl.children[1:]:
                _walk(part, _Scope(self.provided), refs)
            refs.uses |= self._expanded(decl)
            name = str(decl.children[0])
            self.globals.append(name)
            self.deps[name] = refs.calls | refs.uses
            global_refs.calls |= refs.calls

    def _block(self, node: Tree) -> None:
        """An interface block: its instance name, or else its members, become globals."""
        names = [c for c in node.children if isinstance(c, Token) and c.type == "IDENTIFIER"]
        if len(names) > 1:
            self.globals.append(str(names[1]))
            return
        for member in _children(node, "struct_member"):
            for decl in _children(member, "struct_declarator"):
                self.globals.append(str(decl.children[0]))

    def _macros(self) -> list[str]:
        own = [m for m in self.pre.defines.values() if m.file != "<predefined>"]
        for macro in own:
            self.deps[macro.name] = _macro_refs(macro) - self.provided
        return [m.name for m in own]

    def _expanded(self, node: Tree) -> set[str]:
        """Macros the preprocessor expanded on the lines this node spans."""
        meta = node.meta
        if getattr(meta, "empty", True):
            return set()
        names: set[str] = set()
        for line in range(meta.line, meta.end_line + 1):
            names |= self.pre.expansions.get(line, set())
        # macros the caller predefined are given, like builtins, not dependencies
        defines = self.pre.defines
        return {n for n in names if n not in defines or defines[n].file != "<predefined>"}


# -- tree helpers ---------------------------------------------------------------------------


def _children(node: Tree, data: str) -> Iterator[Tree]:
    return (c for c in node.children if isinstance(c, Tree) and c.data == data)


def _inline_struct(full_type: Tree) -> Tree | None:
    """The `struct ... { }` written in a declaration's type, if any."""
    spec = next(_children(full_type, "type_specifier"))
    head = spec.children[0]
    return head if isinstance(head, Tree) and head.data == "struct_specifier" else None


def _first_token(node: Tree, kind: str) -> str | None:
    return next((str(c) for c in node.children if isinstance(c, Token) and c.type == kind), None)


def _prototype_parts(proto: Tree) -> tuple[Tree, str, list[Tree]]:
    full_type = proto.children[0]
    name = str(proto.children[1])
    plist = proto.children[2] if len(proto.children) > 2 else None
    params = list(plist.children) if isinstance(plist, Tree) else []
    return full_type, name, params


def _words(node: Tree | Token) -> str:
    """Source-like text of a type-ish subtree, tokens joined by single spaces."""
    if isinstance(node, Token):
        return str(node)
    return " ".join(_words(c) for c in node.children)


def _array_text(node: Tree | None) -> str:
    if node is None:
        return ""
    return "[" + "][".join(_words(c) for c in node.children) + "]" if node.children else "[]"


def _type_text(full_type: Tree) -> str:
    """`highp vec3`, `float[2]`, `S` for a fully specified type or a type specifier."""
    parts: list[str] = []
    for child in full_type.children:
        if isinstance(child, Tree) and child.data == "type_qualifier":
            parts.append(_words(child))
        elif isinstance(child, Tree) and child.data == "type_specifier":
            parts.append(_spec_text(child))
    return " ".join(parts)


def _spec_text(spec: Tree) -> str:
    head = spec.children[0]
    if isinstance(head, Tree):  # an inline struct
        head = _first_token(head, "IDENTIFIER") or "struct"
    arrays = [c for c in spec.children[1:] if isinstance(c, Tree)]
    return str(head) + _array_text(arrays[0] if arrays else None)


def _param(node: Tree) -> Param:
    qualifier = next((_words(c) for c in _children(node, "type_qualifier")), "")
    spec = next(_children(node, "type_specifier"))
    name = _first_token(node, "IDENTIFIER") or ""
    arrays = list(_children(node, "array_specifier"))
    return Param(qualifier, _spec_text(spec) + _array_text(arrays[0] if arrays else None), name)


def _decl_text(p: Param) -> str:
    """`float b[2]` style for a parameter: the array size written after the name."""
    if not p.name:
        return p.type
    base, bracket, rest = p.type.partition("[")
    return f"{base} {p.name}" + (bracket + rest if bracket else "")


# -- the scoped walk over bodies -------------------------------------------------------------

_SCOPED = frozenset({"compound_statement", "for_statement", "while_statement"})


def _walk(node: Tree | Token, scope: _Scope, refs: _Refs) -> None:
    """Collect calls and free uses below `node`, honouring declarations and block scopes."""
    if isinstance(node, Token):
        if node.type == "TYPE_NAME" and str(node) not in scope:
            refs.uses.add(str(node))
        return
    kind = node.data
    if kind in _SCOPED:
        scope.frames.append(set())
        _walk_all(node.children, scope, refs)
        scope.frames.pop()
    elif kind == "variable":
        name = str(node.children[0])
        if name not in scope and not is_builtin(name):
            refs.uses.add(name)
    elif kind == "call":
        callee = node.children[0]
        if isinstance(callee, Tree) and callee.data == "variable":
            name = str(callee.children[0])
            if name not in BUILTIN_FUNCTIONS and name not in scope:
                refs.calls.add(name)
        elif isinstance(callee, Tree) and callee.data == "field":  # a.length()
            _walk(callee.children[0], scope, refs)
        _walk_all(node.children[1:], scope, refs)
    elif kind == "field":
        _walk(node.children[0], scope, refs)
    elif kind == "variable_declaration":
        _walk_all(node.children[:1], scope, refs)
        struct = _inline_struct(node.children[0])
        if struct is not None and (local := _first_token(struct, "IDENTIFIER")):
            scope.declare(local)
        for decl in node.children[1:]:
            _walk_all(decl.children[1:], scope, refs)  # the name is in scope after its initializer
            scope.declare(str(decl.children[0]))
    elif kind == "condition_declaration":
        _walk_all([node.children[0], node.children[2]], scope, refs)
        scope.declare(str(node.children[1]))
    else:
        _walk_all(node.children, scope, refs)


def _walk_all(nodes: Iterable[Tree | Token], scope: _Scope, refs: _Refs) -> None:
    for child in nodes:
        _walk(child, scope, refs)


def _macro_refs(macro: Macro) -> set[str]:
    """User-level names a macro body refers to: not its parameters, fields or builtins."""
    names: set[str] = set()
    previous = ""
    for tok in significant(tokenize(macro.body)):
        name = tok.text
        if (
            tok.kind == "ident"
            and previous != "."
            and name not in (macro.params or ())
            and not is_builtin(name)
        ):
            names.add(name)
        previous = name
    return names
