"""GLSL builtin functions over lanes. Each takes the argument values and the float dtype.

Formulas follow the GLSL ES 3.00 spec (section 8) step by step, so float16 rounds where a
mediump GPU would: `mod` is x - y·floor(x/y), `mix` is x·(1-a) + y·a, `smoothstep` is t²(3-2t).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from glint.compiler.evaluator.ops import TypeMismatch, align, dot_arrays
from glint.compiler.evaluator.values import Value, base_of, vec_size, vector_type

Builtin = Callable[[list[Value], Any], Value]

# Valid GLSL that has no meaning on the CPU here: textures, derivatives, images.
UNSUPPORTED = frozenset(
    {
        "texture",
        "textureProj",
        "textureLod",
        "textureOffset",
        "texelFetch",
        "texelFetchOffset",
        "textureGrad",
        "textureProjLod",
        "textureProjGrad",
        "textureSize",
        "texture2D",
        "textureCube",
        "dFdx",
        "dFdy",
        "fwidth",
        "packHalf2x16",
        "unpackHalf2x16",
        "packSnorm2x16",
        "unpackSnorm2x16",
        "packUnorm2x16",
        "unpackUnorm2x16",
        "floatBitsToInt",
        "floatBitsToUint",
        "intBitsToFloat",
        "uintBitsToFloat",
        "inverse",
        "determinant",
        "outerProduct",
        "matrixCompMult",
        "transpose",
    }
)


def _float_args(args: list[Value], ft: Any) -> tuple[str, list[np.ndarray]]:
    return align(args, ft, "float")


def _out(type_: str, data: Any, ft: Any) -> Value:
    base = base_of(type_)
    dtype = ft if base == "float" else (np.int32 if base == "int" else np.bool_)
    return Value(type_, np.asarray(data).astype(dtype, copy=False))


def _unary(fn: Callable[[np.ndarray], Any]) -> Builtin:
    def run(args: list[Value], ft: Any) -> Value:
        type_, (x,) = _float_args(args, ft)
        return _out(type_, fn(x), ft)

    return run


def _numeric(fn: Callable[..., Any]) -> Builtin:
    """abs, sign, min, max, clamp: keep ints as ints."""

    def run(args: list[Value], ft: Any) -> Value:
        type_, arrays = align(args, ft)
        return _out(type_, fn(*arrays, ft), ft)

    return run


def _float_fn(fn: Callable[..., Any]) -> Builtin:
    def run(args: list[Value], ft: Any) -> Value:
        type_, arrays = _float_args(args, ft)
        return _out(type_, fn(*arrays, ft), ft)

    return run


def _c(x: Any, ft: Any) -> np.ndarray:
    return np.asarray(x).astype(ft, copy=False)


def _clamp(x: Any, lo: Any, hi: Any, ft: Any) -> np.ndarray:
    return np.minimum(np.maximum(x, lo), hi)


def _mix(args: list[Value], ft: Any) -> Value:
    if base_of(args[2].type) == "bool":  # mix(x, y, bvec) selects, it does not blend
        type_, (x, y) = _float_args(args[:2], ft)
        sel = args[2].data if vec_size(args[2].type) == vec_size(type_) else args[2].data[..., None]
        return _out(type_, np.where(sel, y, x), ft)
    type_, (x, y, a) = _float_args(args, ft)
    return _out(type_, _c(x * _c(1 - a, ft), ft) + _c(y * a, ft), ft)


def _smoothstep(e0: Any, e1: Any, x: Any, ft: Any) -> np.ndarray:
    t = _c(_clamp(_c(_c(x - e0, ft) / _c(e1 - e0, ft), ft), 0, 1, ft), ft)
    return _c(_c(t * t, ft) * _c(3 - _c(2 * t, ft), ft), ft)


def _mod(x: Any, y: Any, ft: Any) -> np.ndarray:
    return _c(x - _c(y * np.floor(_c(x / y, ft)), ft), ft)


def _geometric(name: str) -> Builtin:
    """length, distance, dot, normalize, cross, reflect, refract, faceforward."""

    def run(args: list[Value], ft: Any) -> Value:
        type_, arrays = _float_args(args, ft)
        k = vec_size(type_)
        vec = [a if k > 1 else a[..., None] for a in arrays]
        out: Any
        if name == "dot":
            return _out("float", dot_arrays(vec[0], vec[1], ft), ft)
        if name in ("length", "distance"):
            d = vec[0] if name == "length" else _c(vec[0] - vec[1], ft)
            return _out("float", np.sqrt(dot_arrays(d, d, ft)), ft)
        if name == "normalize":
            inv = _c(1 / np.sqrt(dot_arrays(vec[0], vec[0], ft)), ft)
            out = vec[0] * inv[..., None]
        elif name == "cross":
            a, b = vec
            if k != 3:
                raise TypeMismatch("cross needs vec3 arguments")
            parts = [
                a[..., i] * b[..., j] - a[..., j] * b[..., i] for i, j in ((1, 2), (2, 0), (0, 1))
            ]
            out = np.stack(np.broadcast_arrays(*parts), -1)
        elif name == "reflect":
            i, n = vec
            d = _c(2 * dot_arrays(n, i, ft), ft)
            out = i - _c(d[..., None] * n, ft)
        elif name == "refract":
            i, n, eta = vec  # eta is a float: align gave it a length-1 axis
            d = dot_arrays(n, i, ft)[..., None]
            kk = _c(1 - _c(eta * eta, ft) * _c(1 - _c(d * d, ft), ft), ft)
            r = _c(eta * i, ft) - _c(_c(eta * d, ft) + np.sqrt(np.maximum(kk, 0)), ft) * n
            out = np.where(kk < 0, _c(0, ft), r)
        else:  # faceforward(N, I, Nref)
            n, i, nref = vec
            out = np.where((dot_arrays(nref, i, ft) < 0)[..., None], n, -n)
        out = _c(out, ft)
        return _out(type_, out if k > 1 else out[..., 0], ft)

    return run


def _compare_fn(fn: Callable[[Any, Any], Any]) -> Builtin:
    def run(args: list[Value], ft: Any) -> Value:
        type_, (x, y) = align(args, ft)
        return _out(vector_type("bool", vec_size(type_)), fn(x, y), ft)

    return run


def _reduce_bool(fn: Callable[..., Any]) -> Builtin:
    def run(args: list[Value], ft: Any) -> Value:
        return _out("bool", fn(args[0].data, axis=-1), ft)

    return run


def _atan(args: list[Value], ft: Any) -> Value:
    if len(args) == 2:
        type_, (y, x) = _float_args(args, ft)
        return _out(type_, np.arctan2(y, x), ft)
    return _unary(np.arctan)(args, ft)


def _bools(v: Value) -> str:
    return vector_type("bool", vec_size(v.type))


def _step(edge: Any, x: Any, ft: Any) -> np.ndarray:
    return np.where(x < edge, 0, 1)


BUILTINS: dict[str, Builtin] = {
    "radians": _unary(lambda x: x * _c(np.pi / 180, x.dtype)),
    "degrees": _unary(lambda x: x * _c(180 / np.pi, x.dtype)),
    "sin": _unary(np.sin),
    "cos": _unary(np.cos),
    "tan": _unary(np.tan),
    "asin": _unary(np.arcsin),
    "acos": _unary(np.arccos),
    "atan": _atan,
    "sinh": _unary(np.sinh),
    "cosh": _unary(np.cosh),
    "tanh": _unary(np.tanh),
    "pow": _float_fn(lambda x, y, ft: np.power(x, y)),
    "exp": _unary(np.exp),
    "log": _unary(np.log),
    "exp2": _unary(np.exp2),
    "log2": _unary(np.log2),
    "sqrt": _unary(np.sqrt),
    "inversesqrt": _unary(lambda x: 1 / np.sqrt(x)),
    "abs": _numeric(lambda x, ft: np.abs(x)),
    "sign": _numeric(lambda x, ft: np.sign(x)),
    "floor": _unary(np.floor),
    "ceil": _unary(np.ceil),
    "trunc": _unary(np.trunc),
    "round": _unary(np.round),
    "roundEven": _unary(np.round),
    "fract": _unary(lambda x: x - np.floor(x)),
    "mod": _float_fn(_mod),
    "min": _numeric(lambda x, y, ft: np.minimum(x, y)),
    "max": _numeric(lambda x, y, ft: np.maximum(x, y)),
    "clamp": _numeric(_clamp),
    "mix": _mix,
    "step": _float_fn(_step),
    "smoothstep": _float_fn(_smoothstep),
    "length": _geometric("length"),
    "distance": _geometric("distance"),
    "dot": _geometric("dot"),
    "cross": _geometric("cross"),
    "normalize": _geometric("normalize"),
    "reflect": _geometric("reflect"),
    "refract": _geometric("refract"),
    "faceforward": _geometric("faceforward"),
    "lessThan": _compare_fn(np.less),
    "lessThanEqual": _compare_fn(np.less_equal),
    "greaterThan": _compare_fn(np.greater),
    "greaterThanEqual": _compare_fn(np.greater_equal),
    "equal": _compare_fn(np.equal),
    "notEqual": _compare_fn(np.not_equal),
    "any": _reduce_bool(np.any),
    "all": _reduce_bool(np.all),
    "not": lambda args, ft: Value(args[0].type, ~args[0].data),
    "isnan": lambda args, ft: Value(
        vector_type("bool", vec_size(args[0].type)), np.isnan(args[0].data)
    ),
    "isinf": lambda args, ft: Value(
        vector_type("bool", vec_size(args[0].type)), np.isinf(args[0].data)
    ),
}


def call_builtin(name: str, args: list[Value], ft: Any) -> Value:
    """Run builtin `name`; KeyError when there is none. Warnings about inf/nan are expected."""
    fn = BUILTINS[name]
    with np.errstate(all="ignore"):
        return fn(args, ft)
