"""L004 unnormalized-blinn-phong."""

from __future__ import annotations

import re
from collections.abc import Iterator

from ...analysis.constants import const_value
from ...analysis.functions import Function, callable_from_main, functions
from ...analysis.liveness import reaches_output
from ...analysis.syntax import (
    binary_op,
    call_args,
    call_name,
    calls_in,
    names_in,
    operands,
)
from ...context import LintContext, Node
from ...finding import Finding
from .. import Rule, register
from ._common import short_text
from ._terms import cosine_of, is_fresnel_name, schlick_base

_PBR_NAME = re.compile(r"ggx|smith|cook|torrance|beckmann|trowbridge", re.I)


_NORM_NAME = re.compile(r"norm(?!al)", re.I)


def _has_pbr(ctx: LintContext) -> bool:
    """Physically based terms that are used: a GGX/Smith/Fresnel function that mainImage runs, or
    a Schlick Fresnel or Fresnel call whose value reaches its function's result."""
    used = callable_from_main(ctx)
    assert ctx.tree is not None
    up = ctx.parents()
    for fn in functions(ctx):
        if used is not None and fn.name not in used:
            continue
        if fn.name != "mainImage" and (_PBR_NAME.search(fn.name) or is_fresnel_name(fn.name)):
            return True
        for node in calls_in(fn.body):
            if (schlick_base(node) is not None or is_fresnel_name(call_name(node))) and (
                reaches_output(ctx, node, fn, up)
            ):
                return True
    return False


@register
class UnnormalizedBlinnPhong(Rule):
    """Finds an unnormalized Blinn-Phong lobe, pow(N·H, n) without its (n + 8)/(8π) or (n + 2)/(2π)
    factor, in a shader that also has physically based terms (Fresnel, GGX, Smith, Cook-Torrance).

    The lobe is pow(x, n) with x a known N·H (names and dot(N, H)) and n not 5 (that is a Fresnel
    shape) whose value reaches the colour (dead code is not reported, nor counted as physically
    based evidence); it counts as normalized when `n + 8`, `n + 2` (or + 1, 4, 6) appears anywhere
    in the shader, or a name like normFactor multiplies it in the same function.

    Why is this bad?
        The peak of pow(N·H, n) is 1 whatever n is, so the energy it reflects falls as the lobe
        narrows: next to energy-conserving GGX or Fresnel-weighted terms, glossy surfaces come out
        too dark and rough ones too bright. On its own, tuned by eye, Blinn-Phong is fine and is not
        reported.

    Example:
        float spec = pow(NoH, shininess);
        vec3 col = F * spec;

    Use instead:
        float spec = (shininess + 8.0) / (8.0 * PI) * pow(NoH, shininess);
        vec3 col = F * spec;

    Fix safety:
        No fix: normalizing changes the brightness the author tuned by eye.

    References:
        - Akenine-Möller, Haines, Hoffman, Real-Time Rendering, 3rd ed., 2008, §7.6 (the (m +
          8)/(8π) factor)
        - Giesen, "Derivation of Phong and Blinn-Phong BRDF normalization factors", 2009
    """

    code = "L004"
    name = "unnormalized-blinn-phong"
    default = False  # below 80% worth acting on in the labelled corpus sample
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        lobes = []
        assert ctx.tree is not None
        up = ctx.parents()
        for fn in functions(ctx):
            for node in calls_in(fn.body):
                if call_name(node) != "pow" or len(call_args(node)) != 2:
                    continue
                if not reaches_output(ctx, node, fn, up):
                    continue  # a lobe that is computed and never used
                base, exponent = call_args(node)
                if const_value(exponent) == 5.0 or cosine_of(base, fn) != "NH":
                    continue
                if not self._normalized(ctx, fn, exponent):
                    lobes.append((node, exponent))
        if not lobes or not _has_pbr(ctx):
            return
        for node, exponent in lobes:
            n = short_text(ctx, exponent, 20)
            yield self.report(
                ctx,
                node,
                f"Blinn-Phong lobe without its normalization next to physically based terms: "
                f"multiply by ({n} + 8.0) / (8.0 * PI)",
            )

    def _normalized(self, ctx: LintContext, fn: Function, exponent: Node) -> bool:
        wanted = " ".join(ctx.node_text(exponent).split())
        assert ctx.tree is not None
        for node in ctx.nodes("binary"):
            if binary_op(node) == "+":
                parts = operands(node, "+")
                texts = {" ".join(ctx.node_text(p).split()) for p in parts}
                if wanted in texts and any(const_value(p) in (1.0, 2.0, 4.0, 6.0, 8.0)
                                           for p in parts):  # fmt: skip
                    return True
        return any(_NORM_NAME.search(n) for n in names_in(fn.body))
