"""The vocabulary of lighting code, shared by the lighting (L) rules: the naming conventions
by which shader code says which vector is the normal, the light, the view or the half vector,
which cosine a dot product is, Fresnel terms, and the dot products that light a surface. The
analyses they build on (a file's functions and locals, constant folding, liveness) are in
`lint/analysis`.

Roles are decided by names because GLSL has no other way of saying what a vec3 means. The
conventions recognised (case-insensitive, whole names, or the last field of `s.N`):

- normal N: n, nor, nrm, norm, normal, and names containing "normal" (pixelNormal, wNormal)
- light L: l, lig, ld, ldir, lightdir, lightvec, tolight, wi, and names containing "lightdir",
  "sundir" or "sun_dir" (kSunDir, SUN_DIR)
- view V: v, vdir, view, viewdir, eye dir names (toeye, eyedir, tocamera, directiontocamera), wo
- half H: h, hal, half, halfdir, halfvec, halfway, and names containing "half"
- precomputed cosines: NdotL, NoL, ndl, nl, dotNL, n_dot_l ... (any two of n/l/v/h joined by
  nothing, "o", "d", "dot" or "_dot_"), with an optional suffix such as "signed" or "clamped".

L·H is the same angle as V·H (H bisects L and V), so both count as the Fresnel cosine.
"""

from __future__ import annotations

import re

from lark import Tree

from glint.compiler.glsl.ast import Binary, Unary, first_child

from ...analysis.constants import const_value
from ...analysis.expression_types import expression_types
from ...analysis.functions import Function, callable_from_main, functions, resolve
from ...analysis.liveness import reaches_output
from ...analysis.syntax import (
    binary_op,
    call_args,
    call_name,
    calls_in,
    last_name,
    var_name,
)
from ...context import LintContext, Node

# --- roles of vectors and cosines ------------------------------------------------------------

_ROLE_EXACT = {
    "N": {"n", "nor", "nrm", "norm", "normal", "nn", "wn", "sn"},
    "L": {
        "l",
        "lig",
        "ld",
        "ldir",
        "lightdir",
        "lightvec",
        "tolight",
        "wi",
        "lightdirection",
        "lig2",
        "light",
    },
    "V": {
        "v",
        "vdir",
        "view",
        "viewdir",
        "viewvec",
        "toeye",
        "eyedir",
        "tocamera",
        "tocam",
        "directiontocamera",
        "viewdirection",
        "wo",
    },
    "H": {"h", "hal", "half", "halfdir", "halfvec", "halfway", "halfwayvector", "hv"},
}
_ROLE_CONTAINS = {
    "N": ("normal",),
    "L": ("lightdir", "sundir", "sun_dir", "lightvec", "tolight", "light_dir"),
    "V": ("viewdir", "view_dir", "tocamera", "toeye"),
    "H": ("half",),
}
_COSINE = re.compile(
    r"^(?:dot_?|cos_?)?([nlvh])_?(?:dot|o|d)?_?([nlvh])(?:_?(?:signed|clamped|sat|raw|c))?$"
)


def name_role(name: str) -> str | None:
    low = name.lower()
    for role, names in _ROLE_EXACT.items():
        if low in names:
            return role
    for role, parts in _ROLE_CONTAINS.items():
        if any(p in low for p in parts):
            return role
    return None


def vector_role(node: Node, fn: Function | None) -> str | None:
    """N, L, V or H for an expression that names one of those vectors, else None."""
    unary = Unary.cast(node)
    if unary is not None and unary.op in "+-":
        return vector_role(unary.operand, fn)
    if isinstance(node, Tree) and call_name(node) == "normalize":
        args = call_args(node)
        return vector_role(args[0], fn) if len(args) == 1 else None
    name = last_name(node)
    if name is None:
        return None
    role = name_role(name)
    if role is None and var_name(node) is not None:
        value = resolve(node, fn, 1)
        if value is not node:
            return vector_role(value, fn)
    return role


def pair(a: str, b: str) -> str | None:
    """The cosine of two roles: NL, NV, NH, VH (also for L·H), LV."""
    key = "".join(sorted(a + b))
    return {"LN": "NL", "NV": "NV", "HN": "NH", "HV": "VH", "HL": "VH", "LV": "LV"}.get(key)


_PASS_THROUGH = {"max", "clamp", "saturate", "abs", "min"}


def cosine_of(node: Node, fn: Function | None, depth: int = 4) -> str | None:
    """Which cosine an expression is (NL, NV, NH, VH, LV), through clamps and locals."""
    if depth <= 0 or not isinstance(node, Tree):
        return None
    name = call_name(node)
    if name == "dot":
        args = call_args(node)
        if len(args) == 2:
            a, b = vector_role(args[0], fn), vector_role(args[1], fn)
            return pair(a, b) if a and b else None
        return None
    if name in _PASS_THROUGH:
        found = {c for a in call_args(node) if const_value(a) is None
                 and (c := cosine_of(a, fn, depth - 1))}  # fmt: skip
        return found.pop() if len(found) == 1 else None
    leaf = last_name(node)
    if leaf is not None:
        match = _COSINE.match(leaf.lower())
        if match:
            return pair(match.group(1).upper(), match.group(2).upper())
        if var_name(node) is not None and fn is not None:
            value = fn.value_of(leaf)
            if value is not None:
                return cosine_of(value, fn, depth - 1)
    return None


def mentions_normal(ctx: LintContext) -> bool:
    """Whether the file lights a surface: a dot product with a normal anywhere."""
    for fn in functions(ctx):
        for node in calls_in(fn.body):
            if call_name(node) == "dot" and any(vector_role(a, fn) == "N" for a in call_args(node)):
                return True
    return False


# --- terms -----------------------------------------------------------------------------------

FRESNEL_NAME = re.compile(r"fresnel|schlick", re.IGNORECASE)
# Schlick's phase function and Schlick's G1 share the name but are not Fresnel terms.
NOT_FRESNEL_NAME = re.compile(r"phase|ggx|smith|g1|geometry|visib|mask", re.IGNORECASE)


def is_fresnel_name(name: str | None) -> bool:
    return (
        bool(name)
        and bool(FRESNEL_NAME.search(name or ""))
        and not NOT_FRESNEL_NAME.search(name or "")
    )


def schlick_base(node: Node) -> Node | None:
    """For `pow(1 - x, 5.0)` (also clamped or maxed: `pow(clamp(1.0 - x, 0., 1.), 5.)`) the x,
    else None: the cosine of an inline Schlick Fresnel."""
    if call_name(node) != "pow":
        return None
    args = call_args(node)  # type: ignore[arg-type]
    if len(args) != 2 or const_value(args[1]) != 5.0:
        return None
    base = args[0]
    while call_name(base) in ("clamp", "max", "saturate"):
        inner = [a for a in call_args(base) if const_value(a) is None]  # type: ignore[arg-type]
        if len(inner) != 1:
            return None
        base = inner[0]
    if binary_op(base) == "-":
        difference = Binary(base)  # type: ignore[arg-type]
        if const_value(difference.left) == 1.0:
            return difference.right
    return None


def _vec3_or_unknown(ctx: LintContext, node: Node) -> bool:
    typ = expression_types(ctx).type_of(node)
    return typ is None or typ == "vec3"


def lighting_cosines(ctx: LintContext) -> list[tuple[Tree, Function]]:
    """The dot products that light a 3D surface: dot(N, L), dot(N, V) or dot(N, H) of two vec3
    (not a 2D vector that happens to be called n, nor a hash's argument dotted with constants),
    in a function that mainImage runs, whose value reaches that function's result (not a
    lighting term computed and then never used)."""
    return ctx.memo(_lighting_cosines)


def _lighting_cosines(ctx: LintContext) -> list[tuple[Tree, Function]]:
    result: list[tuple[Tree, Function]] = []
    used = callable_from_main(ctx)
    up = ctx.parents()
    for fn in functions(ctx):
        if used is not None and fn.name not in used:
            continue
        for node in calls_in(fn.body):
            if call_name(node) != "dot" or not _lighting_dot(node, fn):
                continue
            if not all(_vec3_or_unknown(ctx, a) for a in call_args(node)):
                continue
            if reaches_output(ctx, node, fn, up):
                result.append((node, fn))
    return result


_LIGHT_WORD = re.compile(r"light|lig|sun", re.I)


def _light_like(node: Node, fn: Function) -> bool:
    """A light (or view, half) vector by its role, or named after a light: `vLight`, `ligt`,
    `sun.dir`, `l.dir` with l the light (a field of a light-named variable)."""
    if vector_role(node, fn) in ("L", "V", "H"):
        return True
    base: Node = node
    while isinstance(base, Tree) and (base.data in ("field", "index") or call_name(base) ==
                                      "normalize" or base.data == "unary"):  # fmt: skip
        base = (
            call_args(base)[0]
            if call_name(base) == "normalize"
            else (Unary(base).operand if base.data == "unary" else first_child(base))
        )
    name = var_name(base)
    if name is None:
        return False
    return name_role(name) == "L" or bool(_LIGHT_WORD.search(name))


def _lighting_dot(node: Tree, fn: Function) -> bool:
    """dot(N, X) with X a light, view or half vector (see _light_like)."""
    if cosine_of(node, fn) in ("NL", "NV", "NH"):
        return True
    args = call_args(node)
    if len(args) != 2:
        return False
    roles = [vector_role(a, fn) for a in args]
    return any(r == "N" and _light_like(args[1 - i], fn) for i, r in enumerate(roles))


def lights_surface(ctx: LintContext) -> bool:
    """Whether the shader lights a 3D surface (see lighting_cosines)."""
    return bool(lighting_cosines(ctx))
