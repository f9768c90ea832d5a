"""Expressions over lanes: operators, literals, constructors, swizzles, lvalues.

`self.mask` holds the lanes that are executing; assignments only change those lanes (the
others keep their old values), which is how divergent `if`s and loops run on the CPU.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from lark import Token, Tree

from glint.compiler.evaluator.errors import EvaluationError, UnsupportedError
from glint.compiler.evaluator.ops import TypeMismatch, arithmetic, compare, convert, equal, negate
from glint.compiler.evaluator.values import (
    AnyValue,
    StructValue,
    Value,
    base_of,
    components,
    copy_value,
    is_matrix,
    is_value_type,
    lanes,
    mat_shape,
    np_dtype,
    select,
    stack,
    vec_size,
    vector_type,
)
from glint.compiler.glsl import types as T
from glint.compiler.glsl.ast import (
    BoolLiteral,
    Constructor,
    Field,
    FloatLiteral,
    Index,
    IntLiteral,
    Postfix,
    Prefix,
    Sequence,
    StructSpecifier,
    Ternary,
    TypeSpecifier,
    Unary,
    Variable,
    binary_parts,
)
from glint.compiler.glsl.preprocessor import Preprocessed

Step = tuple[str, Any]  # ("field", name) or ("index", Value)
_ARITH = {"+", "-", "*", "/", "%"}
_COMPARE = {"<", ">", "<=", ">="}
_BITWISE = {"&": np.bitwise_and, "|": np.bitwise_or, "^": np.bitwise_xor,
            "<<": np.left_shift, ">>": np.right_shift}  # fmt: skip


@dataclass
class Loop:
    broken: np.ndarray  # lanes that left by `break`
    continued: np.ndarray  # lanes waiting for the next iteration after `continue`


@dataclass
class Frame:
    """One function call: its scopes, the lanes that returned and what they returned."""

    scopes: list[dict[str, AnyValue]]
    return_type: str
    returned: np.ndarray
    result: AnyValue | None = None
    loops: list[Loop] = field(default_factory=list)


class ExpressionEvaluator:
    ft: Any
    pre: Preprocessed
    structs: dict[str, list[tuple[str, str]]]
    globals: dict[str, AnyValue]
    externals: dict[str, Any]
    frame: Frame
    mask: np.ndarray

    # ---- errors and types ----------------------------------------------------------------

    def where(self, node: Tree | Token) -> str:
        line = node.line if isinstance(node, Token) else getattr(node.meta, "line", 0)
        loc = self.pre.locate(line or 1)
        return f"{loc.file}:{loc.line}"

    def error(self, node: Tree | Token, what: str, unsupported: bool = False) -> EvaluationError:
        cls = UnsupportedError if unsupported else EvaluationError
        return cls(f"{self.where(node)}: {what}")

    def type_of(self, spec: Tree) -> str:
        """The type named by a type_specifier (registering an inline struct)."""
        view = TypeSpecifier(spec)
        if view.array is not None:
            raise self.error(spec, "arrays are not supported by the evaluator", unsupported=True)
        struct = view.struct
        if struct is not None:
            return self.define_struct(struct.syntax)
        text = view.name
        if text == "void" or is_value_type(text) or text in self.structs:
            return text
        raise self.error(spec, f"type '{text}' is not supported", unsupported=True)

    def define_struct(self, node: Tree) -> str:
        struct = StructSpecifier(node)
        name = struct.name
        if name is None:
            raise self.error(node, "anonymous structs are not supported", unsupported=True)
        members: list[tuple[str, str]] = []
        for member in struct.members:
            spec = member.type.syntax
            for decl in member.declarators:
                if decl.array is not None:
                    raise self.error(decl.syntax, "array members are not supported", True)
                members.append((decl.name, self.type_of(spec)))
        self.structs[name] = members
        return name

    def zero(self, type_: str) -> AnyValue:
        if type_ in self.structs:
            return StructValue(type_, {n: self.zero(t) for n, t in self.structs[type_]})
        shape: tuple[int, ...] = ()
        if is_matrix(type_):
            shape = mat_shape(type_)
        elif vec_size(type_) > 1:
            shape = (vec_size(type_),)
        return Value(type_, np.zeros(shape, np_dtype(base_of(type_), self.ft)))

    def coerce(self, value: AnyValue, type_: str, node: Tree) -> AnyValue:
        """A value stored into a variable of `type_` (ints widen to floats)."""
        if isinstance(value, StructValue):
            if value.type != type_:
                raise self.error(node, f"cannot use {value.type} as {type_}")
            return copy_value(value)
        if value.type == type_ and (base_of(type_) != "float" or value.data.dtype == self.ft):
            return value
        same_shape = vec_size(value.type) == vec_size(type_) and is_matrix(value.type) == is_matrix(
            type_
        )
        if type_ in self.structs or not same_shape:
            raise self.error(node, f"cannot use {value.type} as {type_}")
        return convert(value, base_of(type_), self.ft)

    # ---- expressions -------------------------------------------------------------------------

    def expr(self, node: Tree) -> AnyValue:
        handler = getattr(self, "_e_" + node.data, None)
        if handler is None:
            raise self.error(node, f"'{node.data}' expressions are not supported", True)
        try:
            with np.errstate(all="ignore"):
                return handler(node)
        except TypeMismatch as exc:
            raise self.error(node, str(exc)) from None

    def value(self, node: Tree) -> Value:
        v = self.expr(node)
        if not isinstance(v, Value):
            raise self.error(node, f"a {v.type} struct is not allowed here")
        return v

    def truth(self, node: Tree) -> np.ndarray:
        v = self.value(node)
        if v.type != "bool":
            raise self.error(node, f"condition must be a bool, not {v.type}")
        return v.data

    def lookup(self, name: str, node: Tree) -> tuple[dict[str, AnyValue], AnyValue]:
        for scope in reversed(self.frame.scopes):
            if name in scope:
                return scope, scope[name]
        if name in self.globals:
            return self.globals, self.globals[name]
        raise self.error(node, f"'{name}' is not defined (pass it in externals?)")

    def _e_variable(self, node: Tree) -> AnyValue:
        return self.lookup(Variable(node).name, node)[1]

    def _e_int_literal(self, node: Tree) -> Value:
        text = IntLiteral(node).text.rstrip("uU")
        if text[:2].lower() == "0x":
            n = int(text, 16)
        else:
            n = int(text, 8) if len(text) > 1 and text[0] == "0" else int(text)
        return Value("int", np.asarray(n, np.int32))

    def _e_float_literal(self, node: Tree) -> Value:
        return Value("float", np.asarray(FloatLiteral(node).value, self.ft))

    def _e_bool_literal(self, node: Tree) -> Value:
        return Value("bool", np.asarray(BoolLiteral(node).value))

    def _e_sequence(self, node: Tree) -> AnyValue:
        sequence = Sequence(node)
        self.expr(sequence.left)
        return self.expr(sequence.right)

    def _e_binary(self, node: Tree) -> AnyValue:
        left, op, right = binary_parts(node)
        if op in ("&&", "||"):
            return self._logic(op, left, right)
        a, b = self.expr(left), self.expr(right)
        if op in ("==", "!="):
            same = equal(a, b, self.ft)
            return Value("bool", same if op == "==" else ~same)
        if not (isinstance(a, Value) and isinstance(b, Value)):
            raise self.error(node, f"'{op}' on structs")
        if op in _ARITH:
            return arithmetic(op, a, b, self.ft)
        if op in _COMPARE:
            return compare(op, a, b, self.ft)
        if op == "^^":
            return Value("bool", a.data != b.data)
        if op in _BITWISE and base_of(a.type) == base_of(b.type) == "int":
            return Value(a.type if vec_size(a.type) > 1 else b.type, _BITWISE[op](a.data, b.data))
        raise self.error(node, f"operator '{op}' on {a.type} and {b.type}", True)

    def _logic(self, op: str, left: Tree, right: Tree) -> Value:
        """Short-circuit: the right side runs (for its side effects) only in lanes that need it."""
        a = self.truth(left)
        need = self.mask & (a if op == "&&" else ~a)
        if not need.any():
            return Value("bool", a)
        saved = self.mask
        self.mask = need
        try:
            b = self.truth(right)
        finally:
            self.mask = saved
        return Value("bool", (a & b) if op == "&&" else (a | b))

    def _e_unary(self, node: Tree) -> Value:
        unary = Unary(node)
        op, operand = unary.op, self.value(unary.operand)
        if op == "-":
            return negate(operand, self.ft)
        if op == "!" and operand.type == "bool":
            return Value("bool", ~operand.data)
        if op == "~" and base_of(operand.type) == "int":
            return Value(operand.type, ~operand.data)
        if op == "+":
            return operand
        raise self.error(node, f"unary '{op}' on {operand.type}")

    def _e_prefix(self, node: Tree) -> Value:
        prefix = Prefix(node)
        return self._step(prefix.operand, prefix.op, node)[1]  # type: ignore[arg-type]

    def _e_postfix(self, node: Tree) -> Value:
        postfix = Postfix(node)
        return self._step(postfix.operand, postfix.op, node)[0]  # type: ignore[arg-type]

    def _step(self, target: Tree, op: str, node: Tree) -> tuple[Value, Value]:
        """`++`/`--`: (old, new)."""
        lv = self.lvalue(target)
        old = self.read(lv, node)
        assert isinstance(old, Value)
        one = Value("int", np.asarray(1, np.int32))
        new = arithmetic("+" if op == "++" else "-", old, one, self.ft)
        new = convert(new, base_of(old.type), self.ft)
        self.assign(lv, new, node)
        return old, new

    def _e_assignment(self, node: Tree) -> AnyValue:
        target, op, rhs = binary_parts(node)
        lv = self.lvalue(target)  # type: ignore[arg-type]
        new = self.expr(rhs)
        if op != "=":
            old = self.read(lv, node)
            if not (isinstance(old, Value) and isinstance(new, Value)) or op[:-1] not in _ARITH:
                raise self.error(node, f"'{op}' is not supported here", True)
            new = arithmetic(op[:-1], old, new, self.ft)
        return self.assign(lv, new, node)

    def _e_ternary(self, node: Tree) -> AnyValue:
        ternary = Ternary(node)
        cond = self.truth(ternary.condition)
        saved = self.mask
        out: list[AnyValue | None] = []
        for lanes_, branch in ((cond, ternary.if_true), (~cond, ternary.if_false)):
            if (saved & lanes_).any():
                self.mask = saved & lanes_
                try:
                    out.append(self.expr(branch))
                finally:
                    self.mask = saved
            else:
                out.append(None)
        a, b = out
        if a is None or b is None:
            result = a if a is not None else b
            assert result is not None
            return result
        if isinstance(a, Value) and isinstance(b, Value) and a.type != b.type:
            b = self.coerce(b, a.type, node)
        return select(cond, a, b)

    # ---- fields, swizzles, indexing -------------------------------------------------------

    def _e_field(self, node: Tree) -> AnyValue:
        field = Field(node)
        return self.get(self.expr(field.base), ("field", field.name), node)

    def _e_index(self, node: Tree) -> AnyValue:
        index = Index(node)
        base = self.expr(index.base)
        return self.get(base, ("index", self.value(index.index)), node)

    def get(self, value: AnyValue, step: Step, node: Tree) -> AnyValue:
        kind, key = step
        if isinstance(value, StructValue):
            if kind == "field" and key in value.fields:
                return value.fields[key]
            raise self.error(node, f"{value.type} has no field '{key}'")
        if kind == "field":
            idx = T.swizzle_indices(key, T.size(value.type))  # None for a matrix (size 0)
            if idx is None or vec_size(value.type) == 1 and key not in ("x", "r", "s"):
                raise self.error(node, f"no field '{key}' on {value.type}")
            data = value.data if vec_size(value.type) > 1 else value.data[..., None]
            part = data[..., idx]
            if len(idx) == 1:
                part = part[..., 0]
            return Value(vector_type(base_of(value.type), len(idx)), part)
        index = self._index(key, value, node)
        out_type = (
            vector_type("float", mat_shape(value.type)[1])
            if is_matrix(value.type)
            else (base_of(value.type))
        )
        dims = 2 if is_matrix(value.type) else 1
        if isinstance(index, int):
            return Value(out_type, value.data[(..., index) + (slice(None),) * (dims - 1)])
        picked = np.take_along_axis(  # a different component in each lane
            value.data, index.reshape(index.shape + (1,) * dims), axis=-dims
        )
        return Value(out_type, picked[(..., 0) + (slice(None),) * (dims - 1)])

    def _index(self, key: Value, value: Value, node: Tree) -> int | np.ndarray:
        if base_of(key.type) != "int" or vec_size(key.type) != 1:
            raise self.error(node, "an index must be an int")
        size = mat_shape(value.type)[0] if is_matrix(value.type) else vec_size(value.type)
        if size == 1:
            raise self.error(node, f"cannot index a {value.type}")
        if np.any((key.data < 0) | (key.data >= size)):
            raise self.error(node, f"index out of range for {value.type}")
        return int(key.data) if key.data.ndim == 0 else key.data

    # ---- lvalues -----------------------------------------------------------------------------

    def lvalue(self, node: Tree) -> tuple[str, list[Step], Tree]:
        if node.data == "variable":
            return Variable(node).name, [], node
        if node.data == "field":
            field = Field(node)
            name, steps, _ = self.lvalue(field.base)  # type: ignore[arg-type]
            return name, [*steps, ("field", field.name)], node
        if node.data == "index":
            index = Index(node)
            name, steps, _ = self.lvalue(index.base)  # type: ignore[arg-type]
            return name, [*steps, ("index", self.value(index.index))], node
        raise self.error(node, "this expression cannot be assigned to")

    def read(self, lv: tuple[str, list[Step], Tree], node: Tree) -> AnyValue:
        value = self.lookup(lv[0], node)[1]
        for step in lv[1]:
            value = self.get(value, step, node)
        return value

    def assign(self, lv: tuple[str, list[Step], Tree], new: AnyValue, node: Tree) -> AnyValue:
        """Store into the active lanes only; returns the stored value."""
        name, steps, _ = lv
        scope, old = self.lookup(name, node)
        root = self._replace(old, steps, new, node)
        scope[name] = root if self.mask.all() else select(self.mask, root, old)
        return self.read(lv, node)

    def _replace(self, value: AnyValue, steps: list[Step], new: AnyValue, node: Tree) -> AnyValue:
        if not steps:
            return self.coerce(new, value.type, node)
        (kind, key), rest = steps[0], steps[1:]
        if isinstance(value, StructValue):
            if kind != "field" or key not in value.fields:
                raise self.error(node, f"{value.type} has no field '{key}'")
            fields = dict(value.fields)
            fields[key] = self._replace(value.fields[key], rest, new, node)
            return StructValue(value.type, fields)
        sub = self.get(value, (kind, key), node)
        sub_new = self._replace(sub, rest, new, node)
        assert isinstance(sub_new, Value)
        dims = 2 if is_matrix(value.type) else 1
        lane_shape = np.broadcast_shapes(value.data.shape[:-dims], lanes(sub_new))
        data = np.broadcast_to(value.data, lane_shape + value.data.shape[-dims:]).copy()
        if kind == "field":
            idx = list(T.swizzle_indices(key, vec_size(value.type)) or ())
            if len(set(idx)) != len(idx):
                raise self.error(node, f"cannot assign to '{key}': a component repeats")
            for j, k in enumerate(idx):
                data[..., k] = sub_new.data[..., j] if len(idx) > 1 else sub_new.data
            return Value(value.type, data)
        index = self._index(key, value, node)
        tail = (slice(None),) * (dims - 1)
        if isinstance(index, int):
            data[(..., index) + tail] = sub_new.data
            return Value(value.type, data)
        for k in range(data.shape[-dims]):
            hit = index == k
            hit = hit.reshape(hit.shape + (1,) * (dims - 1))
            data[(..., k) + tail] = np.where(hit, sub_new.data, data[(..., k) + tail])
        return Value(value.type, data)

    # ---- constructors ------------------------------------------------------------------------

    def _e_constructor(self, node: Tree) -> AnyValue:
        constructor = Constructor(node)
        type_ = self.type_of(constructor.type.syntax)
        args = [self.expr(a) for a in constructor.arguments]
        return self.construct(type_, args, node)

    def construct(self, type_: str, args: list[AnyValue], node: Tree) -> AnyValue:
        if type_ in self.structs:
            members = self.structs[type_]
            if len(args) != len(members):
                raise self.error(node, f"{type_} has {len(members)} fields, got {len(args)}")
            fields = {n: self.coerce(a, t, node) for (n, t), a in zip(members, args, strict=True)}
            return StructValue(type_, fields)
        values: list[Value] = []
        for a in args:
            if not isinstance(a, Value):
                raise self.error(node, f"a {a.type} struct cannot build a {type_}")
            values.append(a)
        base = base_of(type_)
        dtype = np_dtype(base, self.ft)
        if not values:
            raise self.error(node, f"{type_}() needs arguments")
        parts = [
            convert(Value(base_of(v.type), c), base, self.ft).data
            for v in values
            for c in components(v)
        ]
        if is_matrix(type_):
            cols, rows = mat_shape(type_)
            if len(values) == 1 and vec_size(values[0].type) == 1 and not is_matrix(values[0].type):
                diag = np.eye(cols, rows, dtype=dtype)
                return Value(type_, (parts[0][..., None, None] * diag).astype(dtype))
            if len(parts) != cols * rows:
                raise self.error(node, f"{type_} needs {cols * rows} components", True)
            flat = stack(parts, dtype)
            return Value(type_, flat.reshape(flat.shape[:-1] + (cols, rows)))
        size = vec_size(type_)
        if len(values) == 1 and vec_size(values[0].type) == 1 and not is_matrix(values[0].type):
            parts = parts * size  # vec3(x) repeats x
        if len(parts) < size:
            raise self.error(node, f"not enough components to build a {type_}")
        if size == 1:
            return Value(type_, np.asarray(parts[0]).astype(dtype, copy=False))
        return Value(type_, stack(parts[:size], dtype))
