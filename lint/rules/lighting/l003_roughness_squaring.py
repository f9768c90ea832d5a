"""L003 roughness-squaring."""

from __future__ import annotations

import re
from collections.abc import Iterator

from lark import Tree

from ...analysis.constants import const_value
from ...analysis.functions import Function, function_map, functions, resolve
from ...analysis.syntax import binary_op, call_args, call_name, calls_in, last_name, operands
from ...context import LintContext, Node
from ...finding import Finding
from .. import Rule, register
from ._common import short_text

_GGX_LIKE = re.compile(
    r"ggx|smith|trowbridge|beckmann|distribution|visibility|geometry|ndf|^d_|^v_|^g_|g1", re.I
)


_POWER_BY_NAME = [
    (re.compile(r"^(perceptual_?)?rough(ness)?(_?perceptual)?$", re.I), 1),
    (re.compile(r"^(a|alpha|alpha_?g|linear_?roughness)$", re.I), 2),
    (re.compile(r"^(a2|a_2|asq|asqr|alpha_?2|alpha_?sq|alpha_?sqr|alpha_?squared)$", re.I), 4),
]


_POWER_TEXT = {1: "perceptual roughness", 2: "α = roughness²", 4: "α² = roughness⁴"}


def _name_power(name: str | None) -> int | None:
    if not name:
        return None
    for pattern, power in _POWER_BY_NAME:
        if pattern.match(name):
            return power
    return None


def roughness_power(node: Node, fn: Function | None, depth: int = 5) -> int | None:
    """The power of perceptual roughness an expression holds (1, 2, 4 ...), from names and
    products; None when unknown."""
    if depth <= 0 or not isinstance(node, Tree):
        return None
    if node.data in ("variable", "field"):
        value = resolve(node, fn, 1) if node.data == "variable" else node
        if value is not node:
            found = roughness_power(value, fn, depth - 1)
            if found is not None:
                return found
        return _name_power(last_name(node))
    name = call_name(node)
    if name in ("max", "min", "clamp"):
        inner = [a for a in call_args(node) if const_value(a) is None]
        return roughness_power(inner[0], fn, depth - 1) if len(inner) == 1 else None
    if name == "pow":
        args = call_args(node)
        base, exponent = roughness_power(args[0], fn, depth - 1), const_value(args[1])
        if base is not None and exponent is not None and float(exponent).is_integer():
            return base * int(exponent)
        return None
    if binary_op(node) == "*":
        powers = [roughness_power(f, fn, depth - 1) for f in operands(node, "*")]
        if any(p is None for p in powers):
            return None
        return sum(powers)  # type: ignore[arg-type]
    return None


@register
class RoughnessSquaring(Rule):
    """Finds roughness squared twice, or not at all, on the way into a GGX or Smith term: the
    argument holds a different power of roughness than the parameter's name says.

    What is decided statically: the callee is a function of the file named like a distribution or
    visibility term (GGX, Smith, Beckmann, D_, V_, G_, G1, distribution, visibility); its parameter
    says what it expects by name (roughness/perceptualRoughness: roughness; alpha/a/linearRoughness:
    α; a2/alpha2/alphaSq: α²); the argument's power of roughness is known from names and products
    (`r * r` with r = roughness is α, `a * a` with a = α is α²). Anything else (`k`, `m`, arbitrary
    expressions) is not judged.

    Why is this bad?
        GGX and Smith take α = roughness² (Burley's remapping). Passing α where the function squares
        again gives α² (surfaces look much glossier than the roughness slider says); passing
        perceptual roughness where α is expected makes everything rougher.

    Example:
        float a = roughness * roughness;
        float D = D_GGX(NoH, a * a);  // D_GGX(float NoH, float a) squares a itself

    Use instead:
        float a = roughness * roughness;
        float D = D_GGX(NoH, a);

    Fix safety:
        No fix: whether the call or the callee's name is wrong is the author's choice.

    References:
        - Burley, "Physically-Based Shading at Disney", SIGGRAPH 2012 course notes (α = roughness²)
        - Walter et al., "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007
        - Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013 course notes
    """

    code = "L003"
    name = "roughness-squaring"
    default = False  # opt-in: no finding on the corpus, so no measured precision
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        defined = function_map(ctx)
        for fn in functions(ctx):
            for node in calls_in(fn.body):
                callee = defined.get(call_name(node) or "")
                if callee is None or not _GGX_LIKE.search(callee.name):
                    continue
                for param, arg in zip(callee.param_order, call_args(node), strict=False):
                    expected = _name_power(param)
                    got = roughness_power(arg, fn)
                    if expected is None or got is None or got == expected:
                        continue
                    how = "squared once too often" if got > expected else "not squared"
                    yield self.report(
                        ctx,
                        arg,
                        f"roughness {how}: `{short_text(ctx, arg)}` is "
                        f"{_POWER_TEXT.get(got, f'roughness^{got}')} but {callee.name}'s "
                        f"parameter `{param}` is {_POWER_TEXT[expected]}",
                    )
