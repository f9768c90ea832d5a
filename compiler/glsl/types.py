"""GLSL ES 3.00 types and their algebra: the one place the front end reads a type name.

A type is its source text: "float", "uvec3", "mat2x3", "isampler2DArray", "float[4]",
"vec3[2][3]", or a struct's name. Everything else (the lint's semantic model, the expression
types, the evaluator, code generation) asks this module what a type is made of and what an
operator, a swizzle, an index or a constructor makes of it, so they cannot disagree about,
say, `uvec3` or the `stpq` swizzle set (they used to: see tests/glsl/test_types.py).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import lru_cache

Type = str | None

# --- the names ----------------------------------------------------------------------------

_PREFIX_ELEMENT = {"": "float", "i": "int", "u": "uint", "b": "bool"}
_ELEMENT_PREFIX = {v: k for k, v in _PREFIX_ELEMENT.items()}
_VEC = re.compile(r"^([iub]?)vec([234])$")
_MAT = re.compile(r"^mat([234])(?:x([234]))?$")
_SAMPLER = re.compile(r"^([iu]?)sampler(2D|3D|Cube|2DArray)(Shadow)?$")

SCALARS = frozenset({"float", "int", "uint", "bool"})
VECTORS = frozenset(f"{p}vec{n}" for p in _PREFIX_ELEMENT for n in (2, 3, 4))
MATRICES = frozenset(
    {f"mat{n}" for n in (2, 3, 4)} | {f"mat{c}x{r}" for c in (2, 3, 4) for r in (2, 3, 4)}
)
# Section 4.1 of the spec: only float samplers have shadow forms, and no 3D one.
SAMPLERS = frozenset(
    {f"{p}sampler{d}" for p in ("", "i", "u") for d in ("2D", "3D", "Cube", "2DArray")}
    | {"sampler2DShadow", "samplerCubeShadow", "sampler2DArrayShadow"}
)
# Every type the language names with a keyword.
BUILTIN_TYPES = frozenset({"void"}) | SCALARS | VECTORS | MATRICES | SAMPLERS
# The types a constructor call `T(...)` builds (structs and arrays too, by their own names).
CONSTRUCTIBLE = SCALARS | VECTORS | MATRICES

SWIZZLE_SETS = ("xyzw", "rgba", "stpq")
_SWIZZLE_SLOT = {c: i for letters in SWIZZLE_SETS for i, c in enumerate(letters)}
_SWIZZLE_SET = {c: letters for letters in SWIZZLE_SETS for c in letters}


# --- scalars, vectors, matrices -----------------------------------------------------------


@lru_cache(maxsize=4096)  # few distinct types, asked about a million times in the corpus
def components(t: Type) -> tuple[str, int] | None:
    """("float", 3) for vec3, ("uint", 1) for uint; None for matrices, arrays, structs."""
    if t in SCALARS:
        return t, 1  # type: ignore[return-value]
    m = _VEC.match(t or "")
    return (_PREFIX_ELEMENT[m.group(1)], int(m.group(2))) if m else None


@lru_cache(maxsize=4096)
def matrix_shape(t: Type) -> tuple[int, int] | None:
    """(columns, rows) of a matrix type; None for anything else (a struct named `material`)."""
    m = _MAT.match(t or "")
    if not m:
        return None
    cols = int(m.group(1))
    return cols, int(m.group(2) or cols)


def vector(element: str, n: int) -> str:
    """The scalar (n = 1) or vector of n `element`s: ("uint", 3) -> "uvec3"."""
    return element if n == 1 else f"{_ELEMENT_PREFIX[element]}vec{n}"


def matrix(cols: int, rows: int) -> str:
    return f"mat{cols}" if cols == rows else f"mat{cols}x{rows}"


def size(t: Type) -> int:
    """Component count of a scalar or vector, 0 otherwise."""
    c = components(t)
    return c[1] if c else 0


def is_scalar(t: Type) -> bool:
    return t in SCALARS


def is_vector(t: Type) -> bool:
    return size(t) > 1


def is_matrix(t: Type) -> bool:
    return matrix_shape(t) is not None


def is_value(t: Type) -> bool:
    """A scalar, vector or matrix: a type made of numbers (not an array, struct, sampler)."""
    return components(t) is not None or matrix_shape(t) is not None


@lru_cache(maxsize=4096)
def element_type(t: Type) -> str | None:
    """The component type: "uint" for uvec3, "float" for mat3 and float; None otherwise."""
    c = components(t)
    if c:
        return c[0]
    return "float" if matrix_shape(t) else None


def is_float_like(t: Type) -> bool:
    return element_type(t) == "float"


def shape(t: Type) -> tuple[int, ...] | None:
    """The axes of a value's components: () for a scalar, (3,) for vec3, (cols, rows) for a
    matrix (column-major, as GLSL stores it); None for anything else."""
    n = size(t)
    if n:
        return () if n == 1 else (n,)
    return matrix_shape(t)


# --- arrays -------------------------------------------------------------------------------


def is_array(t: Type) -> bool:
    return t is not None and t.endswith("]")


def array_base(t: str) -> str:
    """ "vec3" for "vec3[4]" and "vec3[2][3]"; the type itself when it is no array."""
    return t.partition("[")[0]


# --- access: indexing and swizzles --------------------------------------------------------


@lru_cache(maxsize=4096)
def element(t: Type) -> Type:
    """The type `x[i]` has: an array's element, a vector's component, a matrix's column."""
    if t is None:
        return None
    if is_array(t):
        base, _, rest = t.partition("[")
        return base + rest[rest.index("]") + 1 :]
    c = components(t)
    if c and c[1] > 1:
        return c[0]
    cols_rows = matrix_shape(t)
    return vector("float", cols_rows[1]) if cols_rows else None


def index_count(t: Type) -> int:
    """How many elements `x[i]` may select: a vector's components, a matrix's columns, a sized
    array's elements; 0 for anything else (a scalar, an unsized array)."""
    if t is None:
        return 0
    if is_array(t):
        first = t[t.index("[") + 1 : t.index("]")]
        return int(first) if first.isdigit() else 0
    cols_rows = matrix_shape(t)
    return cols_rows[0] if cols_rows else (size(t) if size(t) > 1 else 0)


def swizzle_index(letter: str) -> int:
    """The component a swizzle letter names (x, r, s: 0; w, a, q: 3); 0 for any other letter.
    Only for a letter already known to be part of a swizzle: see `swizzle_indices`."""
    return _SWIZZLE_SLOT.get(letter, 0)


@lru_cache(maxsize=4096)
def swizzle_indices(name: str, n: int = 4) -> tuple[int, ...] | None:
    """The components `v.name` selects from a scalar or vector of n components, or None when
    it is no swizzle of one: more than 4 letters, letters of two sets (`xg`), or a component
    past the end (`.z` of a vec2)."""
    if not 1 <= len(name) <= 4:
        return None
    letters = _SWIZZLE_SET.get(name[0])
    if letters is None or any(c not in letters[:n] for c in name):
        return None
    return tuple(letters.index(c) for c in name)


@lru_cache(maxsize=4096)
def swizzle(t: Type, name: str) -> Type:
    """The type of `v.name` for a vector or scalar `v`, None if it is no swizzle of `t`. (A
    scalar's swizzle, `f.xx`, is desktop GLSL's; ES 3.00 rejects it, glslang says so.)"""
    c = components(t)
    if c is None or swizzle_indices(name, c[1]) is None:
        return None
    return vector(c[0], len(name))


def is_lvalue_swizzle(name: str) -> bool:
    """Whether `v.name = ...` may be written: no component twice (`v.xx = ...` is an error)."""
    return len(set(name)) == len(name)


# --- constructors -------------------------------------------------------------------------


def constructor(name: str, structs: frozenset[str] | dict | None = None) -> Type:
    """The type `name(...)` builds: a scalar, vector, matrix or array type is itself, as is a
    struct (any name in `structs`, or any non-keyword name when `structs` is None); a sampler
    or void builds nothing."""
    if is_array(name) or name in CONSTRUCTIBLE:
        return name
    if name in BUILTIN_TYPES:
        return None
    return name if structs is None or name in structs else None


def constructor_sources(t: Type, arg_sizes: list[int]) -> list[tuple[int, int]] | None:
    """Where each component of a scalar or vector `t(args)` comes from: (argument, component)
    pairs, in order. One scalar argument fills every component (`vec3(x)`); otherwise the
    arguments' components follow each other and the extra ones are dropped (`vec2(v3)`).
    None when t is no scalar or vector, an argument is no scalar or vector (size 0), or there
    are too few components (an error)."""
    n = size(t)
    if not n or not arg_sizes or 0 in arg_sizes:
        return None
    if arg_sizes == [1]:
        return [(0, 0)] * n
    sources = [(a, k) for a, m in enumerate(arg_sizes) for k in range(m)]
    return sources[:n] if len(sources) >= n else None


def is_scalar_constructible(t: Type) -> bool:
    """Whether `t(x)` of one float builds a `t` (a matrix: x on its diagonal)."""
    return t in CONSTRUCTIBLE


# --- operators ----------------------------------------------------------------------------

RELATIONAL = frozenset({"<", ">", "<=", ">=", "==", "!=", "&&", "||", "^^"})


def binary(op: str, left: Type, right: Type) -> Type:
    """The result type of `left op right` (section 5.9 of the spec), for valid operands; an
    unknown side (None) leaves only what the known one decides."""
    if op in RELATIONAL:
        return "bool"
    if op in ("<<", ">>"):
        return left  # the shifted operand's type, whatever the shift count's
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
        return vector("float", lm[1])  # a column vector: one component per row
    if rm and is_vector(left):
        return vector("float", rm[0])  # a row vector: one component per column
    return left if lm else right  # matrix times scalar


def unary(op: str, operand: Type) -> Type:
    """The result type of `op operand` (- + ~ ! ++ --)."""
    return "bool" if op == "!" else operand


# --- samplers -----------------------------------------------------------------------------


@dataclass(frozen=True)
class Sampler:
    """A sampler type's parts: isampler2DArray is Sampler("int", "2DArray", False)."""

    element: str  # what a texel holds: float, int or uint
    dim: str  # 2D, 3D, Cube or 2DArray
    shadow: bool  # a depth comparison: texture() returns one float


@lru_cache(maxsize=64)
def sampler(t: Type) -> Sampler | None:
    if t not in SAMPLERS:
        return None
    m = _SAMPLER.match(t)  # type: ignore[arg-type]
    assert m is not None
    return Sampler(_PREFIX_ELEMENT[m.group(1)], m.group(2), m.group(3) is not None)


def texture_result(t: Type) -> str:
    """What texture(), texelFetch() and the like return from a sampler of type t: a gvec4 of
    its element type, one float for a shadow sampler; vec4 when t is unknown."""
    s = sampler(t)
    if s is None:
        return "vec4"
    return "float" if s.shadow else vector(s.element, 4)


def texture_size_result(t: Type) -> str:
    """What textureSize() returns: ivec3 for 3D and array samplers (the layers), else ivec2."""
    s = sampler(t)
    return "ivec3" if s is not None and s.dim in ("3D", "2DArray") else "ivec2"


# --- what each builtin function returns, from its arguments' types -------------------------


def _words(text: str) -> frozenset[str]:
    return frozenset(text.split())


def _gen(args: Sequence[Type]) -> Type:
    """genType rule: the result has the type of the vector argument (or the first one)."""
    for t in args:
        if is_vector(t) or is_matrix(t):
            return t
    return args[0] if args else None


def _fixed(t: str) -> Callable[[Sequence[Type]], Type]:
    return lambda args: t


def _of(element: str) -> Callable[[Sequence[Type]], Type]:
    """A vector of `element` as wide as the first argument (lessThan, floatBitsToInt)."""

    def rule(args: Sequence[Type]) -> Type:
        n = size(args[0]) if args else 0
        return vector(element, n) if n else None

    return rule


def _transpose(args: Sequence[Type]) -> Type:
    shape = matrix_shape(args[0]) if args else None
    return matrix(shape[1], shape[0]) if shape else None


def _outer(args: Sequence[Type]) -> Type:
    if len(args) != 2 or not size(args[0]) or not size(args[1]):
        return None
    return matrix(size(args[1]), size(args[0]))


def _texture(args: Sequence[Type]) -> Type:
    return texture_result(args[0] if args else None)


def _texture_size(args: Sequence[Type]) -> Type:
    return texture_size_result(args[0] if args else None)


_GENTYPE = _words(
    """radians degrees sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh pow
exp log exp2 log2 sqrt inversesqrt abs sign floor trunc round roundEven ceil fract mod modf min
max clamp mix step smoothstep normalize faceforward reflect refract matrixCompMult inverse
dFdx dFdy fwidth"""
)

RETURN_TYPES: dict[str, Callable[[Sequence[Type]], Type]] = {
    **dict.fromkeys(_GENTYPE, _gen),
    **dict.fromkeys(("length", "distance", "dot", "determinant"), _fixed("float")),
    "cross": _fixed("vec3"),
    **dict.fromkeys(("any", "all"), _fixed("bool")),
    **dict.fromkeys(
        _words(
            """isnan isinf lessThan lessThanEqual greaterThan greaterThanEqual equal notEqual
            not"""
        ),
        _of("bool"),
    ),
    "floatBitsToInt": _of("int"),
    "floatBitsToUint": _of("uint"),
    "intBitsToFloat": _of("float"),
    "uintBitsToFloat": _of("float"),
    **dict.fromkeys(("packSnorm2x16", "packUnorm2x16", "packHalf2x16"), _fixed("uint")),
    **dict.fromkeys(("unpackSnorm2x16", "unpackUnorm2x16", "unpackHalf2x16"), _fixed("vec2")),
    "transpose": _transpose,
    "outerProduct": _outer,
    "textureSize": _texture_size,
    **dict.fromkeys(
        _words(
            """texture textureProj textureLod textureOffset texelFetch texelFetchOffset
            textureProjOffset textureLodOffset textureProjLod textureProjLodOffset textureGrad
            textureGradOffset textureProjGrad textureProjGradOffset"""
        ),
        _texture,
    ),
}


def builtin_return(name: str, args: Sequence[Type]) -> Type:
    """The type a call of the builtin function `name` returns, None if unknown."""
    rule = RETURN_TYPES.get(name)
    return rule(args) if rule else None
