"""The exact semantics of GLSL's binary operators on first-path values: arithmetic with float32
rounding and the identities that hold for unknowns (`x + 0.0` is x, `x - x` is 0), and
comparisons."""

from __future__ import annotations

import math

from glint.compiler.glsl import types as T

from .values import (
    MV,
    Comp,
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


def _result_type(a: MV, b: MV) -> str | None:
    ta, tb = a.type, b.type
    if ta and ta.startswith("mat") or tb and tb.startswith("mat"):
        return None
    na, nb = size_of(ta), size_of(tb)
    if na is None or nb is None:
        return None
    base = "float" if "float" in (T.element_type(ta), T.element_type(tb)) else T.element_type(ta)
    return vector_type(base, max(na, nb))


ORDERED = frozenset({"<", "<=", ">", ">="})
FLIP = {"<": ">", "<=": ">=", ">": "<", ">=": "<="}


def binary_value(op: str, a: MV, b: MV) -> MV:
    if op in ("<", ">", "<=", ">=", "==", "!=", "^^"):
        return _compare(op, a, b)
    return arith(op, a, b)


def _compare(op: str, a: MV, b: MV) -> MV:
    tags = union(a.tags, b.tags)
    if not (a.exact() and b.exact()) or a.comps is None or b.comps is None:
        return MV("bool", (Sym(),))
    x, y = a.comps, b.comps
    if op == "==":
        return MV("bool", (x == y,), tags)
    if op == "!=":
        return MV("bool", (x != y,), tags)
    if len(x) != 1 or len(y) != 1:
        return MV("bool", (Sym(),))
    p, q = x[0], y[0]
    result = {
        "<": lambda: p < q,  # type: ignore[operator]
        ">": lambda: p > q,  # type: ignore[operator]
        "<=": lambda: p <= q,  # type: ignore[operator]
        ">=": lambda: p >= q,  # type: ignore[operator]
        "^^": lambda: bool(p) != bool(q),
    }[op]()
    return MV("bool", (result,), tags)


def arith(op: str, a: MV, b: MV) -> MV:
    type_ = _result_type(a, b)
    if type_ is None or a.comps is None or b.comps is None:
        n = size_of(type_)
        if type_ is None:
            # a matrix times a vector is a vector of its size; anything else is not followed
            vec = next((v.type for v in (a, b) if v.type and v.type.startswith("vec")), None)
            mat = any(v.type and v.type.startswith("mat") for v in (a, b))
            return unknown(vec) if mat and vec else MV(None)
        return unknown(type_) if n else MV(type_)
    x, y = broadcast(a.comps, b.comps), broadcast(b.comps, a.comps)
    if len(x) != len(y):
        return unknown(type_)
    base = base_of(type_)
    comps: list[Comp] = []
    zero_tags: frozenset | None = None
    for p, q in zip(x, y, strict=True):
        comps.append(_op(op, p, q, base))
        if op == "*" and known(comps[-1]) and comps[-1] == 0 and not (known(p) and known(q)):
            zero_tags = b.tags if known(q) else a.tags
    tags = union(a.tags, b.tags)
    if zero_tags is not None and len(comps) == 1:  # x * 0.0 is 0 whatever x is
        tags = zero_tags
    return MV(type_, tuple(comps), tags)


def _op(op: str, p: Comp, q: Comp, base: str) -> Comp:
    kp, kq = known(p), known(q)
    if not (kp and kq):
        # identities that hold for any value: x + 0, x - 0, x * 1, x / 1, x - x, x * 0
        if op in ("+", "-") and kq and q == 0:
            return p
        if op == "+" and kp and p == 0:
            return q
        if op in ("*", "/") and kq and q == 1:
            return p
        if op == "*" and kp and p == 1:
            return q
        if op == "-" and p is q:
            return 0.0 if base == "float" else 0
        if op == "*" and ((kp and p == 0) or (kq and q == 0)) and base == "int":
            return 0
        return Sym()
    try:
        if op == "+":
            r = p + q  # type: ignore[operator]
        elif op == "-":
            r = p - q  # type: ignore[operator]
        elif op == "*":
            r = p * q  # type: ignore[operator]
        elif op == "/":
            if q == 0:
                return Sym()
            if base == "int":
                r = abs(int(p)) // abs(int(q)) * (1 if (p < 0) == (q < 0) else -1)  # type: ignore[operator]
            else:
                r = p / q  # type: ignore[operator]
        elif op == "%" and base == "int":
            if q == 0:
                return Sym()
            r = math.fmod(int(p), int(q))  # type: ignore[arg-type]
        elif base == "int" and op in ("<<", ">>", "&", "|", "^"):
            r = {"<<": lambda: p << q, ">>": lambda: p >> q, "&": lambda: p & q,  # type: ignore[operator]
                 "|": lambda: p | q, "^": lambda: p ^ q}[op]()  # type: ignore[operator]  # fmt: skip
        else:
            return Sym()
    except (ArithmeticError, ValueError, TypeError):
        return Sym()
    return cast(base, r)
