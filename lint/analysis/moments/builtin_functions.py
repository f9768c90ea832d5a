"""The exact semantics of GLSL's builtin functions on first-path values (`builtin_value`), and
the domain each one's arguments must lie in (`builtin_event`: mod by 0, atan(0, 0), sqrt of a
negative, ...)."""

from __future__ import annotations

import math
from collections.abc import Callable

from lark import Tree

from ...context import Node
from .values import (
    MV,
    NO_TAGS,
    Comp,
    Event,
    Sym,
    base_of,
    broadcast,
    cast,
    known,
    size_of,
    union,
    unknown,
    vector_type,
)

DOMAIN_BUILTINS = frozenset(
    {"sqrt", "inversesqrt", "log", "log2", "pow", "acos", "asin", "normalize"}
)


def _float1(fn: Callable[[float], float]) -> Callable[[float], Comp]:
    def run(x: float) -> Comp:
        try:
            return fn(x)
        except (ArithmeticError, ValueError):
            return Sym()

    return run


def _fract(x: float) -> float:
    return x - math.floor(x)


def _mod(x: float, y: float) -> Comp:
    if y == 0:
        return Sym()
    return x - y * math.floor(x / y)


def _clamp(x: float, lo: float, hi: float) -> float:
    return min(max(x, lo), hi)


def _mix(x: float, y: float, a: float) -> float:
    return x * (1 - a) + y * a


def _step(edge: float, x: float) -> float:
    return 0.0 if x < edge else 1.0


def _smoothstep(e0: float, e1: float, x: float) -> Comp:
    if e0 == e1:
        return Sym()
    t = _clamp((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3 - 2 * t)


def _sign(x: float) -> float:
    return 1.0 if x > 0 else (-1.0 if x < 0 else 0.0)


def _pow(x: float, y: float) -> Comp:
    if x < 0 or (x == 0 and y <= 0):
        return Sym()
    return x**y


_UNARY: dict[str, Callable[[float], Comp]] = {
    "sin": _float1(math.sin),
    "cos": _float1(math.cos),
    "tan": _float1(math.tan),
    "asin": _float1(math.asin),
    "acos": _float1(math.acos),
    "sinh": _float1(math.sinh),
    "cosh": _float1(math.cosh),
    "tanh": _float1(math.tanh),
    "exp": _float1(math.exp),
    "exp2": _float1(lambda x: 2.0**x),
    "log": _float1(math.log),
    "log2": _float1(math.log2),
    "sqrt": _float1(math.sqrt),
    "inversesqrt": _float1(lambda x: 1 / math.sqrt(x)),
    "abs": abs,
    "sign": _sign,
    "floor": _float1(math.floor),
    "ceil": _float1(math.ceil),
    "trunc": _float1(math.trunc),
    "round": _float1(lambda x: math.floor(x + 0.5)),
    "fract": _float1(_fract),
    "radians": lambda x: x * math.pi / 180,
    "degrees": lambda x: x * 180 / math.pi,
}
_COMPONENTWISE: dict[str, Callable[..., Comp]] = {
    "mod": _mod,
    "min": min,
    "max": max,
    "clamp": _clamp,
    "mix": _mix,
    "step": _step,
    "smoothstep": _smoothstep,
    "pow": _pow,
}
# The type of a builtin's result where it is not the type of its first argument.
_SCALAR_RESULT = frozenset({"length", "distance", "dot"})
_VEC4_RESULT = frozenset(
    {"texture", "texture2D", "textureLod", "texelFetch", "textureGrad", "textureCube",
     "textureProj", "textureOffset", "textureProjLod", "texelFetchOffset", "textureLodOffset"}
)  # fmt: skip


def builtin_value(name: str, args: list[MV]) -> MV:
    if name in _VEC4_RESULT:
        return unknown("vec4")
    if not args:
        return MV(None)
    tags = union(*(a.tags for a in args))
    first = args[0]
    if name in _SCALAR_RESULT:
        return _reduce(name, args, tags)
    if name == "cross" and len(args) == 2:
        return _cross(args[0], args[1], tags)
    if name == "normalize":
        return unknown(first.type)
    if name in ("atan",) and len(args) == 2:
        return _componentwise(
            lambda y, x: Sym() if x == 0 and y == 0 else math.atan2(y, x), args, tags
        )
    if name == "atan":
        return _componentwise(_float1(math.atan), args, tags)
    if name in _UNARY and len(args) == 1:
        return _componentwise(_UNARY[name], args, tags)
    if name in _COMPONENTWISE:
        return _componentwise(_COMPONENTWISE[name], args, tags, mix_bool=name == "mix")
    if name in ("isnan", "isinf", "lessThan", "greaterThan", "equal", "notEqual",
                "lessThanEqual", "greaterThanEqual", "any", "all", "not"):  # fmt: skip
        n = size_of(first.type) or 1
        return unknown("bool" if name in ("any", "all", "isnan", "isinf") and n == 1 or
                       name in ("any", "all") else vector_type("bool", n))  # fmt: skip
    if size_of(first.type) is not None and name not in ("modf", "frexp"):
        return unknown(first.type)
    return MV(None)


def _componentwise(fn: Callable[..., Comp], args: list[MV], tags: frozenset,
                   mix_bool: bool = False) -> MV:  # fmt: skip
    sizes = [size_of(a.type) for a in args]
    if any(s is None for s in sizes) or any(a.comps is None for a in args):
        n = max((s or 0) for s in sizes) if all(sizes) else 0
        return unknown(vector_type("float", n)) if n else MV(None)
    n = max(sizes)  # type: ignore[type-var]
    base = "int" if all(base_of(a.type) == "int" for a in args) else "float"
    if mix_bool:
        base = base_of(args[0].type) if base_of(args[0].type) != "bool" else "float"
    type_ = vector_type(base, n)  # type: ignore[arg-type]
    lanes = [a.comps * n if len(a.comps) == 1 else a.comps for a in args]  # type: ignore[operator]
    if any(len(lane) != n for lane in lanes):
        return unknown(type_)
    comps: list[Comp] = []
    for i in range(n):  # type: ignore[arg-type]
        xs = [lane[i] for lane in lanes]
        if all(known(x) for x in xs):
            try:
                value = fn(*(float(x) if base == "float" else x for x in xs))
            except (ArithmeticError, ValueError, TypeError):
                value = Sym()
            comps.append(cast(base, value))
        else:
            comps.append(Sym())
    return MV(type_, tuple(comps), tags)


def _reduce(name: str, args: list[MV], tags: frozenset) -> MV:
    if any(a.comps is None or not a.exact() for a in args):
        return unknown("float")
    if name == "length":
        value = math.sqrt(sum(float(c) ** 2 for c in args[0].comps))  # type: ignore[union-attr]
    elif len(args) != 2 or len(args[0].comps) != len(args[1].comps):  # type: ignore[arg-type]
        return unknown("float")
    elif name == "distance":
        value = math.sqrt(sum((float(p) - float(q)) ** 2 for p, q in  # type: ignore[arg-type]
                              zip(args[0].comps, args[1].comps, strict=True)))  # type: ignore[arg-type]  # fmt: skip
    else:
        value = sum(float(p) * float(q) for p, q in zip(args[0].comps, args[1].comps, strict=True))  # type: ignore[arg-type]
    return MV("float", (cast("float", value),), tags)


def _cross(a: MV, b: MV, tags: frozenset) -> MV:
    if not (a.exact() and b.exact()) or len(a.comps or ()) != 3 or len(b.comps or ()) != 3:
        return unknown("vec3")
    x1, y1, z1 = (float(c) for c in a.comps)  # type: ignore[union-attr]
    x2, y2, z2 = (float(c) for c in b.comps)  # type: ignore[union-attr]
    comps = (y1 * z2 - z1 * y2, z1 * x2 - x1 * z2, x1 * y2 - y1 * x2)
    return MV("vec3", tuple(cast("float", c) for c in comps), tags)


def builtin_event(call: Tree, name: str, nodes: list[Node], args: list[MV],
                  control: frozenset) -> Event | None:  # fmt: skip
    """The event of a builtin called outside its domain, if it is; `control` holds the moments
    that chose the path the call is on."""
    if name == "mod" and len(args) == 2 and args[1].has_zero():
        return Event("mod", nodes[1], args[1], args[0], union(args[1].tags, control))
    if name == "atan" and len(args) == 2:
        y, x = args
        if y.comps and x.comps and any(
            known(a) and known(b) and a == 0 and b == 0
            for a, b in zip(broadcast(y.comps, x.comps), broadcast(x.comps, y.comps),
                            strict=False)):  # fmt: skip
            return Event("atan", call, x, y, union(y.tags, x.tags, control))
    elif name in DOMAIN_BUILTINS and args and args[0].comps is not None:
        x = args[0]
        comps = [c for c in x.comps if known(c)]  # type: ignore[union-attr]
        bad = False
        other = args[1] if len(args) > 1 else None
        if name == "sqrt":
            bad = any(c < 0 for c in comps)
        elif name in ("log", "log2", "inversesqrt"):
            bad = any(c <= 0 for c in comps)
        elif name in ("acos", "asin"):
            bad = any(abs(c) > 1 for c in comps)
        elif name == "normalize":
            bad = x.exact() and all(c == 0 for c in comps)
        elif name == "pow" and other is not None and other.comps is not None:
            ys = broadcast(other.comps, x.comps)  # type: ignore[arg-type]
            for c, y in zip(broadcast(x.comps, other.comps), ys, strict=False):  # type: ignore[arg-type]
                if known(c) and (c < 0 or (c == 0 and known(y) and y <= 0)):
                    bad = True
        if bad:
            tags = union(x.tags, other.tags if name == "pow" and other else NO_TAGS, control)
            return Event(name, nodes[0], x, other, tags)
    return None
