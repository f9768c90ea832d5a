"""What every value of a scene must be, in one place: the types of its numbers, the rule for
its directions, how deep its tables may nest, and how its strings reach a shader.

- A number is a finite float32 (the shader's precision): not nan or inf (TOML has both), not
  beyond ±3.4e38 (1e300, or an integer of any size, which TOML gives as it is), and not so
  small that float32 flushes it to 0 (a nonzero number below 1.2e-38 in magnitude). -0.0 is
  taken as 0.0. A boolean is not a number. An integer (a count, a level) is at most 2^24, the
  largest float32 holds exactly.
- A colour or a light's intensity is at most RADIOMETRIC_MAX (1e6): their products in shading
  stay within float32.
- A direction (a plane's normal, a light's direction, the camera's line of sight) is one that
  float32 can normalise: its largest component between 1e-18 and 1e18 in magnitude, so that
  its squared length is neither 0 nor inf in float32.
- Groups nest at most MAX_GROUP_DEPTH levels, and nothing else in a scene nests deeper than
  its groups may (the walks over a scene are bounded by it, and pydantic's own is ~250).
- A string of the scene (its name, a material's, a file's) reaches a shader only inside a
  comment, through `comment_text`, which leaves no line break, control character or `*/` in it.
"""

from __future__ import annotations

import math
import unicodedata
from collections.abc import Mapping
from typing import Annotated, Any

from pydantic import BeforeValidator, Field

FLOAT32_MAX = 3.4028234663852886e38  # numpy.finfo(numpy.float32).max
FLOAT32_TINY = 1.1754943508222875e-38  # the smallest normal float32
INT_LIMIT = 1 << 24  # float32 holds every integer up to 2^24 exactly
DIRECTION_RANGE = (1e-18, 1e18)  # of a direction's largest component; float32 squares it
MAX_GROUP_DEPTH = 100  # [[objects.children]] nested at most this deep
# Tables and arrays nested deeper than this anywhere in a scene: a group level is two (the
# children array and the part's table), and the scene, objects and a value add a few more.
MAX_NESTING = 2 * MAX_GROUP_DEPTH + 6


def _float32(value: Any) -> Any:
    """A number that float32 holds, -0.0 as 0.0; anything else is left to the type's check."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return value
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"{value!r} is not a finite number; expected a finite number")
    if abs(value) > FLOAT32_MAX:
        raise ValueError(
            f"{shown(value)} is beyond float32's range (the shader's precision); expected a "
            "number of magnitude at most 3.4e38"
        )
    if 0 < abs(value) < FLOAT32_TINY:
        raise ValueError(
            f"{value!r} is too small for float32, which flushes it to 0; write 0 or a number "
            "of magnitude at least 1.2e-38"
        )
    return value + 0.0 if isinstance(value, float) else value  # -0.0 + 0.0 is 0.0


def _number(**constraints: Any) -> Any:
    return Annotated[
        float, Field(strict=True, allow_inf_nan=False, **constraints), BeforeValidator(_float32)
    ]


Number = _number()
Positive = _number(gt=0.0)
NonNegative = _number(ge=0.0)
Unit = _number(ge=0.0, le=1.0)
SignedUnit = _number(ge=-1.0, le=1.0)
AtLeastOne = _number(ge=1.0)
# A camera's field of view in degrees: any lens, short of 180° (where the focal length is 0).
FieldOfView = _number(gt=0.0, lt=179.0)
# A cone's half-angle in degrees, from its axis: a spot light's.
ConeAngle = _number(ge=0.0, le=89.0)
Vec3 = Annotated[list[Number], Field(min_length=3, max_length=3)]
PositiveVec3 = Annotated[list[Positive], Field(min_length=3, max_length=3)]
NonNegativeVec3 = Annotated[list[NonNegative], Field(min_length=3, max_length=3)]
# A colour or a light's intensity: shading multiplies a light's radiance (colour × intensity)
# by terms that peak near 1e7 (GGX at roughness 0.05 facing the half vector) and tone mapping
# squares it, so values past this would overflow float32 to inf and the picture to black.
# A million covers photometric units (direct sun is about 1e5 lux) with room.
RADIOMETRIC_MAX = 1e6
Radiometric = _number(ge=0.0, le=RADIOMETRIC_MAX)
Color = Annotated[list[Radiometric], Field(min_length=3, max_length=3)]


def integer(low: int, high: int = INT_LIMIT) -> Any:
    """An integer from `low` to `high` (at most 2^24)."""
    return Annotated[int, Field(strict=True, ge=low, le=min(high, INT_LIMIT))]


def direction_problem(vector: list[float]) -> str | None:
    """Why float32 cannot normalise `vector`, or None when it can."""
    largest = max((abs(x) for x in vector), default=0.0)
    if largest == 0.0:
        return "must not be the zero vector"
    low, high = DIRECTION_RANGE
    if not low <= largest <= high:
        return (
            f"{shown(vector)} cannot be normalised in float32 (its squared length would be "
            f"{'0' if largest < low else 'inf'}); scale it so that its largest component is "
            f"between {low:g} and {high:g}"
        )
    return None


def nesting_problem(data: Any) -> str | None:
    """Where the tables of a scene nest too deep, and what the limit is; None when they do not.
    The walk keeps its own stack: it cannot itself run out of Python's."""
    stack: list[tuple[Any, tuple[Any, ...], int]] = [(data, (), 0)]
    while stack:
        value, path, depth = stack.pop()
        if isinstance(value, Mapping):
            items: Any = value.items()
        elif isinstance(value, list | tuple):
            items = enumerate(value)
        else:
            continue
        groups = sum(1 for key in path if key == "children")
        if groups > MAX_GROUP_DEPTH and isinstance(value, Mapping):
            return (
                f"{key_path(path)}: groups nest at most {MAX_GROUP_DEPTH} levels deep "
                "([[objects.children]] in [[objects.children]] ...); this one is deeper: "
                "flatten the tree (a union takes any number of parts)"
            )
        if depth > MAX_NESTING:
            return (
                f"{key_path(path)}: nested more than {MAX_NESTING} tables or arrays deep; no "
                "value of a scene nests that deep"
            )
        stack.extend((child, (*path, key), depth + 1) for key, child in items)
    return None


def key_path(path: tuple[Any, ...]) -> str:
    """('lights', 0, 'color') -> 'lights[0].color'; a long path (groups in groups) keeps its
    ends and counts the levels between them."""
    parts = [f"[{key}]" if isinstance(key, int) else f".{key}" for key in path]
    if len(parts) > 12:
        tail = len(parts) - 4
        while tail > 4 and parts[tail].startswith("["):  # the tail starts at a key
            tail -= 1
        hidden = parts[4:tail]
        levels = sum(1 for part in hidden if part == ".children")
        what = f"{levels} more levels" if 2 * levels == len(hidden) else f"{len(hidden)} more"
        parts = [*parts[:4], f"…({what})…", *parts[tail:]]
    return "".join(parts).lstrip(".")


def shown(value: Any, limit: int = 60) -> str:
    """repr(value), shortened to about `limit` characters for a message."""
    try:
        text = repr(value)
    except (RecursionError, ValueError):  # a nesting too deep, an int too long to print
        text = f"<{type(value).__name__}>"
    if len(text) <= limit:
        return text
    return f"{text[: limit - 12]}…({len(text)} characters)"


# Characters that end a line for some reader of GLSL (or the editor showing it), besides the
# control characters: NEL, LINE SEPARATOR and PARAGRAPH SEPARATOR.
_LINE_ENDS = frozenset("\x85\u2028\u2029")
# Unicode categories escaped: control, surrogate (not UTF-8), format (the bidirectional
# overrides that make a line read as other code), line and paragraph separators.
_ESCAPED = frozenset({"Cc", "Cs", "Cf", "Zl", "Zp"})


def comment_text(text: str) -> str:
    """`text` as it may stand inside a GLSL comment, on one line: control, format and
    surrogate characters and line separators as \\xNN or \\uNNNN escapes, a backslash doubled
    (so that no escape is ambiguous), `*/` and `/*` broken up. Callers put it between quotes
    or before more text, so that no line ends with a backslash (a line continuation in GLSL)."""
    out = []
    for char in text:
        if char == "\\":
            out.append("\\\\")
        elif char in _LINE_ENDS or unicodedata.category(char) in _ESCAPED:
            code = ord(char)
            out.append(f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}")
        else:
            out.append(char)
    return "".join(out).replace("*/", "*\\/").replace("/*", "/\\*")
