"""Statements and calls, run over lanes with masks instead of branches.

Divergent control flow runs every path that any lane takes: an `if` runs its branches with
complementary masks, `return`/`break`/`continue` drop lanes from the mask until the function
or loop ends, and a loop repeats while any lane is still in it. Statements are skipped once no
lane is active, so uniform control flow costs what it would on the GPU.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from lark import Tree

from glint.compiler.evaluator.builtins import UNSUPPORTED, call_builtin
from glint.compiler.evaluator.expressions import ExpressionEvaluator, Frame, Loop
from glint.compiler.evaluator.values import (
    AnyValue,
    StructValue,
    Value,
    base_of,
    is_matrix,
    mat_shape,
    np_dtype,
    select,
    stack,
    to_numpy,
    vec_size,
)
from glint.compiler.glsl.ast import (
    Call,
    CompoundStatement,
    DeclarationStatement,
    DoStatement,
    ExpressionStatement,
    FunctionDefinition,
    FunctionPrototype,
    IfStatement,
    JumpStatement,
    VariableDeclaration,
    WhileStatement,
    for_parts,
)
from glint.compiler.glsl.parser import parse_source

MAX_ITERATIONS = 10_000  # a loop still running after this many iterations is an error
_DIRECTIONS = {"in", "out", "inout"}


@dataclass
class Function:
    name: str
    return_type: str
    params: list[tuple[str, str, str]]  # (in | out | inout, type, name)
    body: Tree


class Interpreter(ExpressionEvaluator):
    """One parsed module at one float precision."""

    def __init__(
        self,
        source: str,
        filename: str = "<input>",
        predefined: dict[str, str] | None = None,
        dtype: Any = np.float32,
        externals: dict[str, Any] | None = None,
        external_types: Mapping[str, str] | None = None,
    ) -> None:
        tree, self.pre = parse_source(source, filename, predefined)
        # GLSL types of externals the module declares nowhere (a scene's `map`, `SUN_DIR`); an
        # external without one is typed by the shape of what it gives back
        self.external_types = dict(external_types or {})
        self.text = self.pre.text
        self.ft = np.dtype(dtype).type
        self.structs = {}
        self.functions: dict[str, list[Function]] = {}
        self.prototypes: dict[str, str] = {}  # return types of functions declared, not defined
        self.externals = dict(externals or {})
        self.globals = {}
        self.mask = np.asarray(True)
        self.frame = Frame([self.globals], "void", np.asarray(False))
        for name, ext in self.externals.items():
            if not callable(ext):
                self.globals[name] = self._external_value(name, ext)
        with np.errstate(all="ignore"):
            for node in tree.children:
                self._top_level(node)

    # ---- module --------------------------------------------------------------------------

    def _top_level(self, node: Tree) -> None:
        if node.data == "function_definition":
            definition = FunctionDefinition(node)
            fn = self._function(definition.prototype, definition.body)
            self.functions.setdefault(fn.name, []).append(fn)
        elif node.data == "function_prototype":
            proto = FunctionPrototype(node)
            self.prototypes[proto.name] = self.type_of(proto.return_type.type.syntax)
        elif node.data == "variable_declaration":
            full_type = VariableDeclaration(node).type
            if set(full_type.qualifiers) & {"uniform", "in", "out"}:  # inputs come from externals
                self.type_of(full_type.type.syntax)
                return
            self._s_variable_declaration(node)

    def _function(self, proto: FunctionPrototype, body: Tree) -> Function:
        params: list[tuple[str, str, str]] = []
        for param in proto.parameters:
            spec = param.type.syntax
            name = param.name
            qualifier = param.qualifier
            quals = set(qualifier.words) & _DIRECTIONS if qualifier is not None else set()
            if name is None:  # `float f(void)` or an unnamed parameter
                if self.type_of(spec) == "void":
                    continue
                name = f"_arg{len(params)}"
            params.append((quals.pop() if quals else "in", self.type_of(spec), name))
        return Function(proto.name, self.type_of(proto.return_type.type.syntax), params, body)

    # ---- calls -------------------------------------------------------------------------------

    def call(
        self, name: str, args: Sequence[Any] | dict[str, Any]
    ) -> tuple[AnyValue, dict[str, AnyValue]]:
        """Call `name` from Python: (return value, out/inout parameters by name)."""
        fns = self.functions.get(name)
        if not fns:
            raise KeyError(f"no function '{name}' in the module")
        fn = fns[0] if len(fns) == 1 else self._overload(fns, len(args))
        if isinstance(args, dict):
            missing = [p for _, _, p in fn.params if p not in args]
            if missing:
                raise TypeError(f"{name}: missing arguments {missing}")
            args = [args[p] for _, _, p in fn.params]
        if len(args) != len(fn.params):
            raise TypeError(f"{name} takes {len(fn.params)} arguments, got {len(args)}")
        values = [self.from_python(a, t) for (_, t, _), a in zip(fn.params, args, strict=True)]
        with np.errstate(all="ignore"):
            return self._run(fn, values)

    def _overload(
        self, fns: list[Function], count: int, types: list[str] | None = None
    ) -> Function:
        for fn in fns:
            if len(fn.params) == count and (types is None or [t for _, t, _ in fn.params] == types):
                return fn
        for fn in fns:
            if len(fn.params) == count:
                return fn
        raise KeyError(f"no overload of '{fns[0].name}' takes {count} arguments")

    def _run(self, fn: Function, values: list[AnyValue]) -> tuple[AnyValue, dict[str, AnyValue]]:
        scope: dict[str, AnyValue] = {}
        for (qual, type_, pname), v in zip(fn.params, values, strict=True):
            scope[pname] = self.zero(type_) if qual == "out" else self.coerce(v, type_, fn.body)
        frame = Frame([self.globals, scope], fn.return_type, np.asarray(False))
        saved_frame, saved_mask = self.frame, self.mask
        self.frame = frame
        try:
            self._s_compound_statement(fn.body)
        finally:
            self.frame, self.mask = saved_frame, saved_mask
        result = frame.result if frame.result is not None else self.zero(fn.return_type)
        outs = {p: scope[p] for q, _, p in fn.params if q != "in"}
        return result, outs

    def _e_call(self, node: Tree) -> AnyValue:
        call = Call(node)
        arg_nodes = call.arguments
        name = call.callee_name
        if name is None:
            raise self.error(node, "method calls such as .length() are not supported", True)
        if name in self.functions:
            return self._call_user(name, arg_nodes, node)
        if name in self.externals and callable(self.externals[name]):
            return self._call_external(name, [self.expr(a) for a in arg_nodes], node)
        if name in UNSUPPORTED:
            raise self.error(node, f"'{name}' cannot be evaluated on the CPU", True)
        args = [self.value(a) for a in arg_nodes]
        try:
            return call_builtin(name, args, self.ft)
        except KeyError:
            raise self.error(node, f"unknown function '{name}' (pass it in externals?)") from None
        except (IndexError, ValueError) as exc:
            raise self.error(node, f"bad arguments to {name}: {exc}") from None

    def _call_user(self, name: str, arg_nodes: list[Tree], node: Tree) -> AnyValue:
        fns = self.functions[name]
        args = [
            None if self._is_out(fns, i, len(arg_nodes)) else self.expr(a)
            for i, a in enumerate(arg_nodes)
        ]
        types = [a.type if a is not None else "" for a in args]
        fn = fns[0] if len(fns) == 1 else self._overload(fns, len(args), types)
        values = [
            a if a is not None else self.zero(t)
            for a, (_, t, _) in zip(args, fn.params, strict=True)
        ]
        result, outs = self._run(fn, values)
        for (qual, _, pname), arg in zip(fn.params, arg_nodes, strict=True):
            if qual != "in":  # copy out, in the caller's active lanes
                self.assign(self.lvalue(arg), outs[pname], arg)
        return result

    def _is_out(self, fns: list[Function], i: int, count: int) -> bool:
        fn = next((f for f in fns if len(f.params) == count), fns[0])
        return i < len(fn.params) and fn.params[i][0] == "out"

    def _call_external(self, name: str, args: list[AnyValue], node: Tree) -> AnyValue:
        result = self.externals[name](*[to_numpy(a) for a in args])
        type_ = self.prototypes.get(name) or self.external_types.get(name)
        if type_ is None:  # guess: one more axis than the lanes is a vector
            arr = np.asarray(result)
            lane_dims = max(
                (
                    np.asarray(to_numpy(a)).ndim - (vec_size(a.type) > 1)
                    for a in args
                    if isinstance(a, Value)
                ),
                default=0,
            )
            type_ = f"vec{arr.shape[-1]}" if arr.ndim > lane_dims else "float"
        return self.from_python(result, type_)

    def _external_value(self, name: str, value: Any) -> AnyValue:
        if isinstance(value, Value | StructValue):
            return value
        type_ = self.external_types.get(name)
        arr = np.asarray(value)
        if type_ is None:
            type_ = f"vec{arr.shape[-1]}" if arr.ndim == 1 and 2 <= arr.shape[0] <= 4 else "float"
        return self.from_python(value, type_)

    def from_python(self, value: Any, type_: str) -> AnyValue:
        """numpy arrays or numbers as a value of `type_`: a vecK from an array (..., K) or a
        sequence of K lane arrays; a struct from a dict of its fields."""
        if isinstance(value, Value | StructValue):
            return value
        if type_ in self.structs:
            if not isinstance(value, dict):
                raise TypeError(f"a {type_} is passed as a dict of its fields")
            return StructValue(
                type_, {n: self.from_python(value[n], t) for n, t in self.structs[type_]}
            )
        dtype = np_dtype(base_of(type_), self.ft)
        size = vec_size(type_)
        if size > 1 and isinstance(value, list | tuple) and len(value) == size:
            return Value(type_, stack([np.asarray(v) for v in value], dtype))
        arr = np.asarray(value).astype(dtype)
        want = mat_shape(type_) if is_matrix(type_) else (size,) if size > 1 else ()
        if want and arr.shape[arr.ndim - len(want) :] != want:
            raise TypeError(f"a {type_} needs trailing shape {want}, got {arr.shape}")
        return Value(type_, arr)

    # ---- statements --------------------------------------------------------------------------

    def stmt(self, node: Tree) -> None:
        if not self.mask.any():
            return
        handler = getattr(self, "_s_" + node.data, None)
        if handler is None:
            raise self.error(node, f"'{node.data}' is not supported", True)
        handler(node)

    def _scoped(self, node: Tree) -> None:
        self.frame.scopes.append({})
        try:
            self.stmt(node)
        finally:
            self.frame.scopes.pop()

    def _s_compound_statement(self, node: Tree) -> None:
        self.frame.scopes.append({})
        try:
            for child in CompoundStatement(node).statements:
                self.stmt(child)  # type: ignore[arg-type]
        finally:
            self.frame.scopes.pop()

    def _s_declaration_statement(self, node: Tree) -> None:
        self.stmt(DeclarationStatement(node).declaration)

    def _s_precision_declaration(self, node: Tree) -> None:
        pass

    def _s_empty_statement(self, node: Tree) -> None:
        pass

    def _s_expression_statement(self, node: Tree) -> None:
        self.expr(ExpressionStatement(node).expression)  # type: ignore[arg-type]

    def _s_variable_declaration(self, node: Tree) -> None:
        declaration = VariableDeclaration(node)
        type_ = self.type_of(declaration.type.type.syntax)
        scope = self.frame.scopes[-1]
        for decl in declaration.declarators:
            if decl.array is not None:
                raise self.error(decl.syntax, "arrays are not supported by the evaluator", True)
            init = decl.initializer
            if init is None:
                scope[decl.name] = self.zero(type_)
            else:
                scope[decl.name] = self.coerce(self.expr(init), type_, decl.syntax)  # type: ignore[arg-type]

    def _s_if_statement(self, node: Tree) -> None:
        branch_ = IfStatement(node)
        cond = self.truth(branch_.condition)  # type: ignore[arg-type]
        entry = self.mask
        exits = []
        for lanes_, branch in ((cond, branch_.then_branch), (~cond, branch_.else_branch)):
            self.mask = entry & lanes_
            if branch is not None:
                self._scoped(branch)
            exits.append(self.mask)
        self.mask = exits[0] | exits[1]

    def _s_jump_statement(self, node: Tree) -> None:
        jump = JumpStatement(node)
        kind = jump.keyword
        if kind == "return":
            returned = jump.value
            if returned is not None:
                value = self.coerce(self.expr(returned), self.frame.return_type, node)  # type: ignore[arg-type]
                prev = self.frame.result
                self.frame.result = value if prev is None else select(self.mask, value, prev)
            self.frame.returned = self.frame.returned | self.mask
        elif kind in ("break", "continue"):
            if not self.frame.loops:
                raise self.error(node, f"'{kind}' outside a loop")
            loop = self.frame.loops[-1]
            if kind == "break":
                loop.broken = loop.broken | self.mask
            else:
                loop.continued = loop.continued | self.mask
        else:
            raise self.error(node, f"'{kind}' is not supported", True)
        self.mask = self.mask & False  # these lanes run nothing more in this block

    def _s_for_statement(self, node: Tree) -> None:
        init, cond, incr, body = for_parts(node)
        self.frame.scopes.append({})
        try:
            self.stmt(init)
            self._loop(node, cond, body, incr)  # type: ignore[arg-type]
        finally:
            self.frame.scopes.pop()

    def _s_while_statement(self, node: Tree) -> None:
        loop = WhileStatement(node)
        if loop.declaration is not None:
            raise self.error(node, "declarations in a while condition are not supported", True)
        self._loop(node, loop.condition, loop.body, None)  # type: ignore[arg-type]

    def _s_do_statement(self, node: Tree) -> None:
        loop = DoStatement(node)
        self._loop(node, loop.condition, loop.body, None, test_first=False)  # type: ignore[arg-type]

    def _loop(
        self, node: Tree, cond: Tree | None, body: Tree, incr: Tree | None, test_first: bool = True
    ) -> None:
        entry = self.mask
        loop = Loop(np.asarray(False), np.asarray(False))
        self.frame.loops.append(loop)
        alive = entry
        try:
            for iteration in range(MAX_ITERATIONS + 1):
                if iteration == MAX_ITERATIONS:
                    raise self.error(node, f"loop still running after {MAX_ITERATIONS} iterations")
                if cond is not None and (test_first or iteration > 0):
                    self.mask = alive
                    alive = alive & self.truth(cond)
                if not alive.any():
                    break
                self.mask = alive
                self._scoped(body)
                alive = self.mask | loop.continued  # `continue` lanes go on to the increment
                loop.continued = np.asarray(False)
                if incr is not None and alive.any():
                    self.mask = alive
                    self.expr(incr)
        finally:
            self.frame.loops.pop()
        # lanes that left by the condition or `break` go on; those that returned do not
        self.mask = entry & ~self.frame.returned

    def _s_switch_statement(self, node: Tree) -> None:
        raise self.error(node, "switch statements are not supported", True)
