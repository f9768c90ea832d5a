"""The value model: every GLSL value holds numpy arrays over lanes.

A scalar's data has the lane shape (any shape that broadcasts, `()` for a uniform); a vecK
appends one axis of K components, a matN two axes (column, row), as GLSL is column-major.
Typing values explicitly is what tells a float over 3 lanes from a uniform vec3.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Union

import numpy as np

from glint.compiler.glsl import types as T

_NP_DTYPE = {"int": np.int32, "bool": np.bool_}


@dataclass(frozen=True)
class Value:
    """A scalar, vector or matrix: `type` is its GLSL type name."""

    type: str
    data: np.ndarray


@dataclass
class StructValue:
    type: str
    fields: dict[str, AnyValue] = field(default_factory=dict)


AnyValue = Union[Value, StructValue]  # noqa: UP007 (used at runtime in isinstance-free code)


# The evaluator's names for the type algebra's answers (compiler/glsl/types.py), as its
# modules ask them: a scalar counts as a vector of 1, and a type is taken to be valid.


def base_of(type_: str) -> str:
    """`vec3` -> float, `ivec2` -> int, `bvec4` -> bool, `mat3` -> float."""
    return T.element_type(type_) or "float"


def is_vector(type_: str) -> bool:
    return T.is_vector(type_)


def is_matrix(type_: str) -> bool:
    return T.is_matrix(type_)


def vec_size(type_: str) -> int:
    """Components of a scalar (1) or vector (K); 1 for anything else."""
    return T.size(type_) or 1


def mat_shape(type_: str) -> tuple[int, int]:
    """(columns, rows) of matN or matCxR."""
    shape = T.matrix_shape(type_)
    if shape is None:
        raise ValueError(f"{type_} is no matrix")
    return shape


vector_type = T.vector


def component_dims(type_: str) -> int:
    """Trailing axes that are components rather than lanes."""
    return len(T.shape(type_) or ())


def is_value_type(type_: str) -> bool:
    """A scalar, vector or matrix the evaluator computes with: not (yet) an unsigned one."""
    return T.is_value(type_) and T.element_type(type_) != "uint"


def np_dtype(base: str, ft: Any) -> Any:
    return ft if base == "float" else _NP_DTYPE[base]


def lanes(value: AnyValue) -> tuple[int, ...]:
    """The lane shape of a value (broadcast over a struct's fields)."""
    if isinstance(value, StructValue):
        return np.broadcast_shapes(*(lanes(v) for v in value.fields.values()))
    dims = component_dims(value.type)
    return value.data.shape[: value.data.ndim - dims]


def expand_mask(mask: np.ndarray, dims: int) -> np.ndarray:
    return mask.reshape(mask.shape + (1,) * dims)


def select(mask: np.ndarray, a: AnyValue, b: AnyValue) -> AnyValue:
    """Lane-wise `mask ? a : b`; both sides have the same type."""
    if isinstance(a, StructValue):
        assert isinstance(b, StructValue)
        return StructValue(a.type, {k: select(mask, a.fields[k], b.fields[k]) for k in a.fields})
    assert isinstance(b, Value)
    m = expand_mask(np.asarray(mask), component_dims(a.type))
    return Value(a.type, np.where(m, a.data, b.data).astype(a.data.dtype, copy=False))


def copy_value(value: AnyValue) -> AnyValue:
    """GLSL values copy on assignment; arrays are never written in place, so only structs'
    field dictionaries need copying."""
    if isinstance(value, StructValue):
        return StructValue(value.type, {k: copy_value(v) for k, v in value.fields.items()})
    return value


def components(value: Value) -> list[np.ndarray]:
    """Lane-shaped arrays of each component, in constructor order (matrices column-major)."""
    dims = component_dims(value.type)
    if dims == 0:
        return [value.data]
    if dims == 1:
        return [value.data[..., k] for k in range(value.data.shape[-1])]
    c, r = value.data.shape[-2:]
    return [value.data[..., i, j] for i in range(c) for j in range(r)]


def stack(parts: list[np.ndarray], dtype: Any) -> np.ndarray:
    """Components back into one array with a trailing axis."""
    arrays = np.broadcast_arrays(*[np.asarray(p) for p in parts])
    return np.stack(arrays, axis=-1).astype(dtype, copy=False)


def to_numpy(value: AnyValue, shape: tuple[int, ...] | None = None) -> Any:
    """A result for Python: arrays broadcast to the lane shape, structs as dicts."""
    if isinstance(value, StructValue):
        return {k: to_numpy(v, shape) for k, v in value.fields.items()}
    data = value.data
    if shape is not None:
        dims = component_dims(value.type)
        full = np.broadcast_shapes(shape, data.shape[: data.ndim - dims])
        data = np.broadcast_to(data, full + data.shape[data.ndim - dims :])
    return np.array(data)
