"""The value model: every GLSL value holds numpy arrays over lanes.

A scalar's data has the lane shape (any shape that broadcasts, `()` for a uniform); a vecK
appends one axis of K components, a matN two axes (column, row), as GLSL is column-major.
Typing values explicitly is what tells a float over 3 lanes from a uniform vec3.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any, Union

import numpy as np

SWIZZLE_SETS = ("xyzw", "rgba", "stpq")
SCALARS = ("float", "int", "bool")
_PREFIX = {"float": "", "int": "i", "bool": "b"}
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


def base_of(type_: str) -> str:
    """`vec3` -> float, `ivec2` -> int, `bvec4` -> bool, `mat3` -> float."""
    if type_ in SCALARS:
        return type_
    if type_.startswith("ivec"):
        return "int"
    if type_.startswith("bvec"):
        return "bool"
    return "float"


def is_vector(type_: str) -> bool:
    return re.fullmatch(r"[ib]?vec[234]", type_) is not None


def is_matrix(type_: str) -> bool:
    return type_.startswith("mat")


def vec_size(type_: str) -> int:
    """Components of a scalar (1) or vector (K)."""
    return int(type_[-1]) if is_vector(type_) else 1


def mat_shape(type_: str) -> tuple[int, int]:
    """(columns, rows) of matN or matCxR."""
    dims = type_[3:]
    if "x" in dims:
        c, r = dims.split("x")
        return int(c), int(r)
    return int(dims), int(dims)


def vector_type(base: str, size: int) -> str:
    return base if size == 1 else f"{_PREFIX[base]}vec{size}"


def component_dims(type_: str) -> int:
    """Trailing axes that are components rather than lanes."""
    if is_matrix(type_):
        return 2
    return 1 if is_vector(type_) else 0


def is_value_type(type_: str) -> bool:
    return type_ in SCALARS or is_vector(type_) or is_matrix(type_)


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


def swizzle_indices(name: str, size: int) -> list[int] | None:
    """Component indices of `.xyz`-style selectors, or None when `name` is not one."""
    for letters in SWIZZLE_SETS:
        if all(c in letters[:size] for c in name) and 1 <= len(name) <= 4:
            return [letters.index(c) for c in name]
    return None


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
