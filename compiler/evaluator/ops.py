"""Arithmetic with GLSL's typing: scalar/vector broadcasting, matrix products, int division.

Every float result is cast back to the evaluation dtype, so float16 rounds (and overflows to
inf) after each operation as mediump hardware would.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from glint.compiler.evaluator.values import (
    AnyValue,
    StructValue,
    Value,
    base_of,
    is_matrix,
    mat_shape,
    np_dtype,
    vec_size,
    vector_type,
)


class TypeMismatch(ValueError):
    """Operand types GLSL would reject; the interpreter adds the source line."""


def convert(value: Value, base: str, ft: Any) -> Value:
    """The same shape of value with another component type (`float(i)`, `vec3(ivec3)`)."""
    old = base_of(value.type)
    if old == base and (base != "float" or value.data.dtype == ft):
        return value
    data = value.data
    if base == "bool":
        out = data != 0
    elif base == "int":
        out = (np.trunc(data) if old == "float" else data).astype(np.int32)
    else:
        out = data.astype(ft)
    if is_matrix(value.type):
        return Value(value.type, out)
    return Value(vector_type(base, vec_size(value.type)), out)


def common_base(values: list[Value]) -> str:
    bases = {base_of(v.type) for v in values}
    if "float" in bases:
        return "float"
    return "int" if "int" in bases else "bool"


def align(values: list[Value], ft: Any, base: str | None = None) -> tuple[str, list[np.ndarray]]:
    """Scalars broadcast against vectors; vectors must agree in size."""
    base = base or common_base(values)
    sizes = {vec_size(v.type) for v in values} - {1}
    if len(sizes) > 1:
        raise TypeMismatch("vectors of different sizes: " + ", ".join(v.type for v in values))
    size = sizes.pop() if sizes else 1
    arrays = []
    for v in values:
        data = convert(v, base, ft).data
        arrays.append(data[..., None] if size > 1 and vec_size(v.type) == 1 else data)
    return vector_type(base, size), arrays


def _finish(type_: str, data: Any, ft: Any) -> Value:
    return Value(type_, np.asarray(data).astype(np_dtype(base_of(type_), ft), copy=False))


def _apply(op: str, x: np.ndarray, y: np.ndarray, base: str) -> Any:
    if op == "+":
        return x + y
    if op == "-":
        return x - y
    if op == "*":
        return x * y
    if op == "/":
        if base == "int":  # GLSL int division truncates toward zero
            return np.trunc(x / np.where(y == 0, 1, y)).astype(np.int32)
        return x / y
    if op == "%":
        if base != "int":
            raise TypeMismatch("'%' needs integers; use mod() for floats")
        return np.fmod(x, np.where(y == 0, 1, y))
    raise TypeMismatch(f"operator '{op}' is not arithmetic")


def arithmetic(op: str, a: Value, b: Value, ft: Any) -> Value:
    """`a op b` for + - * / % over scalars, vectors and matrices."""
    if "bool" in (base_of(a.type), base_of(b.type)):
        raise TypeMismatch(f"'{op}' on {a.type} and {b.type}")
    with np.errstate(all="ignore"):
        if op == "*" and is_matrix(a.type) and vec_size(b.type) > 1:
            return _mat_times_vec(a, convert(b, "float", ft), ft)
        if op == "*" and is_matrix(b.type) and vec_size(a.type) > 1:
            return _vec_times_mat(convert(a, "float", ft), b, ft)
        if op == "*" and is_matrix(a.type) and is_matrix(b.type):
            return _mat_times_mat(a, convert(b, "float", ft), ft)
        if is_matrix(a.type) or is_matrix(b.type):
            mat = a if is_matrix(a.type) else b
            x, y = (convert(v, "float", ft).data for v in (a, b))
            x = x if is_matrix(a.type) else x[..., None, None]
            y = y if is_matrix(b.type) else y[..., None, None]
            return _finish(mat.type, _apply(op, x, y, "float"), ft)
        type_, (x, y) = align([a, b], ft)
        return _finish(type_, _apply(op, x, y, base_of(type_)), ft)


def _mat_times_vec(m: Value, v: Value, ft: Any) -> Value:
    cols, rows = m.data.shape[-2:]
    if vec_size(v.type) != cols:
        raise TypeMismatch(f"{m.type} * {v.type}")
    acc = (m.data[..., 0, :] * v.data[..., 0:1]).astype(ft)
    for c in range(1, cols):  # column by column, rounding each step like the GPU would
        acc = (acc + (m.data[..., c, :] * v.data[..., c : c + 1]).astype(ft)).astype(ft)
    return _finish(vector_type("float", rows), acc, ft)


def _mat_times_mat(a: Value, b: Value, ft: Any) -> Value:
    rows = mat_shape(a.type)[1]
    cols_b, rows_b = mat_shape(b.type)
    cols = [
        _mat_times_vec(a, Value(vector_type("float", rows_b), b.data[..., j, :]), ft).data
        for j in range(cols_b)
    ]
    type_ = f"mat{cols_b}" if cols_b == rows else f"mat{cols_b}x{rows}"
    return _finish(type_, np.stack(np.broadcast_arrays(*cols), axis=-2), ft)


def _vec_times_mat(v: Value, m: Value, ft: Any) -> Value:
    cols, rows = mat_shape(m.type)
    if vec_size(v.type) != rows:
        raise TypeMismatch(f"{v.type} * {m.type}")
    out = [dot_arrays(v.data, m.data[..., c, :], ft) for c in range(cols)]
    return _finish(vector_type("float", cols), np.stack(np.broadcast_arrays(*out), -1), ft)


def dot_arrays(x: np.ndarray, y: np.ndarray, ft: Any) -> np.ndarray:
    """Sum of products over the last axis, accumulated in the evaluation dtype."""
    acc = (x[..., 0] * y[..., 0]).astype(ft)
    for k in range(1, max(x.shape[-1], y.shape[-1])):
        acc = (acc + (x[..., k] * y[..., k]).astype(ft)).astype(ft)
    return acc


def negate(a: Value, ft: Any) -> Value:
    if base_of(a.type) == "bool":
        raise TypeMismatch(f"unary '-' on {a.type}")
    return _finish(a.type, -a.data, ft)


def compare(op: str, a: Value, b: Value, ft: Any) -> Value:
    """`< > <= >=` on scalars; lane-wise bool."""
    if vec_size(a.type) > 1 or vec_size(b.type) > 1:
        raise TypeMismatch(f"'{op}' on {a.type} and {b.type}; use lessThan() etc. for vectors")
    _, (x, y) = align([a, b], ft)
    out = {"<": np.less, ">": np.greater, "<=": np.less_equal, ">=": np.greater_equal}[op](x, y)
    return Value("bool", out)


def equal(a: AnyValue, b: AnyValue, ft: Any) -> np.ndarray:
    """`==` over whole values (every component and field), lane-wise."""
    if isinstance(a, StructValue) and isinstance(b, StructValue):
        out: np.ndarray = np.asarray(True)
        for k in a.fields:
            out = out & equal(a.fields[k], b.fields[k], ft)
        return out
    assert isinstance(a, Value) and isinstance(b, Value)
    if is_matrix(a.type):
        return np.all(a.data == b.data, axis=(-2, -1))
    type_, (x, y) = align([a, b], ft)
    same = x == y
    return np.all(same, axis=-1) if vec_size(type_) > 1 else same
