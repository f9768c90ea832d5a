"""GLSL ES 3.00 types as strings ("float", "vec3", "mat2x3", "float[4]", a struct name) and the
typing rules of operators, swizzles and builtin functions (section 8 of the spec)."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from functools import lru_cache

from glint.compiler.glsl.keywords import words
from glint.compiler.target.shadertoy import CHANNEL_KINDS, UNIFORMS

Type = str | None

_PREFIX_BASE = {"": "float", "i": "int", "u": "uint", "b": "bool"}
_BASE_PREFIX = {v: k for k, v in _PREFIX_BASE.items()}
_VEC = re.compile(r"^([iub]?)vec([234])$")
_MAT = re.compile(r"^mat([234])(?:x([234]))?$")
SCALARS = frozenset({"float", "int", "uint", "bool"})

# ShaderToy's uniforms and mainImage's parameters, by name.
SHADERTOY_TYPES: dict[str, str] = {decl.split("[")[0]: ty for ty, decl in UNIFORMS}
SHADERTOY_TYPES.update(
    {"iChannelTime": "float[4]", "iChannelResolution": "vec3[4]", "gl_FragCoord": "vec4",
     "gl_FrontFacing": "bool", "gl_PointCoord": "vec2", "gl_FragDepth": "float"}
)  # fmt: skip


def shadertoy_types(channels: Sequence[str] = ()) -> dict[str, str]:
    """SHADERTOY_TYPES with iChannelN typed for what it is bound to ("2d", "cube", "3d")."""
    types = dict(SHADERTOY_TYPES)
    for index, kind in enumerate(channels):
        types[f"iChannel{index}"] = CHANNEL_KINDS[kind]
    return types


@lru_cache(maxsize=4096)  # few distinct types, asked about a million times in the corpus
def components(t: Type) -> tuple[str, int] | None:
    """("float", 3) for vec3, ("int", 1) for int; None for matrices, arrays, structs."""
    if t in SCALARS:
        return t, 1
    m = _VEC.match(t or "")
    return (_PREFIX_BASE[m.group(1)], int(m.group(2))) if m else None


@lru_cache(maxsize=4096)
def matrix_shape(t: Type) -> tuple[int, int] | None:
    """(columns, rows) of a matrix type."""
    m = _MAT.match(t or "")
    if not m:
        return None
    cols = int(m.group(1))
    return cols, int(m.group(2) or cols)


def vector(base: str, n: int) -> str:
    return base if n == 1 else f"{_BASE_PREFIX[base]}vec{n}"


def matrix(cols: int, rows: int) -> str:
    return f"mat{cols}" if cols == rows else f"mat{cols}x{rows}"


def size(t: Type) -> int:
    """Component count of a scalar or vector, 0 otherwise."""
    c = components(t)
    return c[1] if c else 0


def is_vector(t: Type) -> bool:
    return size(t) > 1


def is_scalar(t: Type) -> bool:
    return t in SCALARS


def is_float_like(t: Type) -> bool:
    c = components(t)
    return (c is not None and c[0] == "float") or matrix_shape(t) is not None


def element(t: Type) -> Type:
    """The type `x[i]` has: an array's element, a vector's component, a matrix's column."""
    if t is None:
        return None
    if t.endswith("]"):
        return t[: t.index("[")] if t.count("[") == 1 else t[: t.index("[")] + t[t.index("]") + 1 :]
    c = components(t)
    if c and c[1] > 1:
        return c[0]
    shape = matrix_shape(t)
    return vector("float", shape[1]) if shape else None


_SWIZZLE = re.compile(r"^([xyzw]{1,4}|[rgba]{1,4}|[stpq]{1,4})$")


def swizzle(t: Type, name: str) -> Type:
    """The type of `v.name` for a vector or scalar `v`, None if it is no swizzle."""
    c = components(t)
    if c is None or not _SWIZZLE.match(name):
        return None
    return vector(c[0], len(name))


def binary(op: str, left: Type, right: Type) -> Type:
    """The result type of `left op right`."""
    if op in ("<", ">", "<=", ">=", "==", "!=", "&&", "||", "^^"):
        return "bool"
    if op in ("<<", ">>"):
        return left
    if left is None or right is None:
        known = left or right
        # vec3 + x is vec3 whatever x is; vec3 * x may be a matrix product of another size
        return known if op != "*" and is_vector(known) else None
    lm, rm = matrix_shape(left), matrix_shape(right)
    if op == "*" and (lm or rm):
        return _matrix_product(left, right, lm, rm)
    # scalar op vector (either side) is the vector; equal types are themselves
    return right if size(left) == 1 and (size(right) > 1 or rm) else left


def _matrix_product(
    left: str, right: str, lm: tuple[int, int] | None, rm: tuple[int, int] | None
) -> Type:
    if lm and rm:
        return matrix(rm[0], lm[1])
    if lm and is_vector(right):
        return vector("float", lm[1])
    if rm and is_vector(left):
        return vector("float", rm[0])
    return left if lm else right  # matrix times scalar


# --- builtin functions ---------------------------------------------------------------------


def _gen(args: Sequence[Type]) -> Type:
    """genType rule: the result has the type of the vector argument (or the first one)."""
    for t in args:
        if is_vector(t) or matrix_shape(t):
            return t
    return args[0] if args else None


def _fixed(t: str) -> Callable[[Sequence[Type]], Type]:
    return lambda args: t


def _bvec(args: Sequence[Type]) -> Type:
    n = size(args[0]) if args else 0
    return vector("bool", n) if n else None


def _based(base: str) -> Callable[[Sequence[Type]], Type]:
    def rule(args: Sequence[Type]) -> Type:
        n = size(args[0]) if args else 0
        return vector(base, n) if n else None

    return rule


def _transpose(args: Sequence[Type]) -> Type:
    shape = matrix_shape(args[0]) if args else None
    return matrix(shape[1], shape[0]) if shape else None


def _outer(args: Sequence[Type]) -> Type:
    if len(args) != 2 or not size(args[0]) or not size(args[1]):
        return None
    return matrix(size(args[1]), size(args[0]))


def _texture(args: Sequence[Type]) -> Type:
    sampler = args[0] if args else None
    if sampler and sampler.startswith("i"):
        return "ivec4"
    if sampler and sampler.startswith("u"):
        return "uvec4"
    return "float" if sampler and sampler.endswith("Shadow") else "vec4"


def _texture_size(args: Sequence[Type]) -> Type:
    sampler = args[0] if args else ""
    return "ivec3" if sampler and ("3D" in sampler or "Array" in sampler) else "ivec2"


_GENTYPE = words(
    """radians degrees sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh pow
exp log exp2 log2 sqrt inversesqrt abs sign floor trunc round roundEven ceil fract mod modf min
max clamp mix step smoothstep normalize faceforward reflect refract matrixCompMult inverse
dFdx dFdy fwidth"""
)

BUILTIN_TYPES: dict[str, Callable[[Sequence[Type]], Type]] = {
    **dict.fromkeys(_GENTYPE, _gen),
    **dict.fromkeys(("length", "distance", "dot", "determinant"), _fixed("float")),
    "cross": _fixed("vec3"),
    **dict.fromkeys(("any", "all"), _fixed("bool")),
    **dict.fromkeys(
        words(
            """isnan isinf lessThan lessThanEqual greaterThan greaterThanEqual equal notEqual
            not"""
        ),
        _bvec,
    ),
    "floatBitsToInt": _based("int"),
    "floatBitsToUint": _based("uint"),
    "intBitsToFloat": _based("float"),
    "uintBitsToFloat": _based("float"),
    **dict.fromkeys(("packSnorm2x16", "packUnorm2x16", "packHalf2x16"), _fixed("uint")),
    **dict.fromkeys(("unpackSnorm2x16", "unpackUnorm2x16", "unpackHalf2x16"), _fixed("vec2")),
    "transpose": _transpose,
    "outerProduct": _outer,
    "textureSize": _texture_size,
    **dict.fromkeys(
        words(
            """texture textureProj textureLod textureOffset texelFetch texelFetchOffset
            textureProjOffset textureLodOffset textureProjLod textureProjLodOffset textureGrad
            textureGradOffset textureProjGrad textureProjGradOffset"""
        ),
        _texture,
    ),
}


def builtin_return(name: str, args: Sequence[Type]) -> Type:
    rule = BUILTIN_TYPES.get(name)
    return rule(args) if rule else None
