"""L008 energy-not-split."""

from __future__ import annotations

import re
from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import Binary, Field

from ...analysis.constants import const_value
from ...analysis.functions import Function, function_map, functions
from ...analysis.syntax import (
    binary_op,
    call_args,
    call_name,
    calls_in,
    last_name,
    names_in,
    operands,
)
from ...context import LintContext, Node, walk, walk_kind
from ...finding import Finding
from .. import Rule, register
from ._common import is_lobe, product_factors, short_text
from ._terms import cosine_of, is_fresnel_name, schlick_base

_DIFFUSE_NAME = re.compile(
    r"^(diffuse|diff|dif|fd|lambert|albedo|base_?colou?r|basecol|base|kd_?albedo)$", re.I
)


_DIFFUSE_CALL = re.compile(r"diffuse|lambert|burley|oren_?nayar|^fd", re.I)


_SPLIT_NAME = re.compile(
    r"^(kd|k_d|kdiffuse|diffusecolou?r|cdiff|c_diff|diffuse_colou?r|diffusealbedo)$", re.I
)


_METAL_NAME = re.compile(r"metal(lic|ness)?", re.I)


@register
class EnergyNotSplit(Rule):
    """Finds a diffuse term added to a Fresnel-weighted specular term without being scaled by what
    the Fresnel term does not reflect, (1 − F), or by (1 − metallic).

    Decided per sum, `diffuse + specular` in one expression (including locals it reads): the
    specular side contains a Fresnel call or the inline Schlick form, the diffuse side is named like
    diffuse, Lambert, albedo or base colour, or is a product with N·L and no specular lobe; the
    split is any factor `1 - x` with x Fresnel or metallic, a kD factor, or an already split colour
    (diffuseColor, cdiff), also inside the diffuse function it calls. Sums built by separate `+=`
    statements are not followed.

    Why is this bad?
        Light reflected at the surface (F) is not available to scatter inside it. Adding full
        diffuse to Fresnel specular reflects more than arrives at grazing angles, and a metal (which
        has no diffuse) keeps a coloured diffuse glow.

    Example:
        vec3 F = fresnelSchlick(f0, VoH);
        vec3 col = albedo / PI * NoL + F * D * Vis * NoL;

    Use instead:
        vec3 F = fresnelSchlick(f0, VoH);
        vec3 col = (1.0 - F) * (1.0 - metallic) * albedo / PI * NoL + F * D * Vis * NoL;

    Fix safety:
        No fix: whether to scale by (1 − F), (1 − metallic) or both depends on the material model.

    References:
        - Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013 course notes (diffuse colour =
          base colour × (1 − metallic))
        - Kelemen and Szirmay-Kalos, "A Microfacet Based Coupled Specular-Matte BRDF Model with
          Importance Sampling", Eurographics 2001
    """

    code = "L008"
    name = "energy-not-split"
    default = False  # opt-in: no finding on the corpus, so no measured precision
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        up = ctx.parents()
        defined = function_map(ctx)
        for fn in functions(ctx):
            fresnel_vars = self._fresnel_vars(fn)
            for node in walk_kind(fn.body, "binary"):
                if binary_op(node) != "+" or binary_op(up.get(id(node))) == "+":
                    continue
                parts = operands(node, "+")
                spec = [p for p in parts if self._has_fresnel(p, fn, fresnel_vars)]
                if not spec:
                    continue  # no specular term: the diffuse ones need not be looked for
                diffuse = [p for p in parts if p not in spec and self._diffuse(p, fn)]
                if not diffuse:
                    continue
                for part in diffuse:
                    if not self._split(part, fn, fresnel_vars, defined):
                        yield self.report(
                            ctx,
                            part,
                            f"diffuse `{short_text(ctx, part, 40)}` is added to Fresnel specular "
                            "without (1 - F) or (1 - metallic): reflected light is counted "
                            "twice",
                        )

    def _fresnel_vars(self, fn: Function) -> set[str]:
        found = set()
        for name, value in fn.init.items():
            if fn.value_of(name) is not None and self._has_fresnel(value, fn, set()):
                found.add(name)
        return found

    def _has_fresnel(self, node: Node, fn: Function, fresnel_vars: set[str]) -> bool:
        if fresnel_vars and names_in(node) & fresnel_vars:
            return True
        return any(schlick_base(c) is not None or is_fresnel_name(call_name(c))
                   for c in calls_in(node))  # fmt: skip

    def _expand(self, node: Node, fn: Function, depth: int = 3) -> list[Node]:
        """The node and the values of the locals it reads (a few levels)."""
        found = [node]
        if depth > 0:
            for name in names_in(node):
                value = fn.value_of(name)
                if value is not None:
                    found += self._expand(value, fn, depth - 1)
        return found

    def _diffuse(self, node: Node, fn: Function) -> bool:
        top, _ = product_factors(node)
        if any(cosine_of(f, fn) == "NL" for f in top) and not any(is_lobe(f, fn) for f in top):
            return True  # a colour times N·L with no specular lobe: Lambert by another name
        for part in self._expand(node, fn):
            if any(_DIFFUSE_NAME.match(n) for n in names_in(part)):
                return True
            if any(_DIFFUSE_NAME.match(Field(f).name) for f in walk_kind(part, "field")):
                return True
            if any(_DIFFUSE_CALL.search(call_name(c) or "") for c in calls_in(part)):
                return True
        return False

    def _split(
        self, node: Node, fn: Function, fresnel_vars: set[str], defined: dict[str, Function]
    ) -> bool:
        for part in self._expand(node, fn):
            if not isinstance(part, Tree):
                continue
            for sub in walk(part):
                if self._one_minus(sub, fn, fresnel_vars):
                    return True
                leaf = last_name(sub)
                if leaf and _SPLIT_NAME.match(leaf):
                    return True
                callee = defined.get(call_name(sub) or "")
                if callee is not None and callee is not fn:
                    args = call_args(sub)
                    if any(names_in(a) & fresnel_vars for a in args):
                        return True  # F handed to the diffuse function: it splits inside
                    if any(self._one_minus(s, callee, set()) or _SPLIT_NAME.match(
                            last_name(s) or "") for s in walk(callee.body)):  # fmt: skip
                        return True
        return False

    def _one_minus(self, node: Tree, fn: Function, fresnel_vars: set[str]) -> bool:
        if binary_op(node) != "-":
            return False
        difference = Binary(node)
        if const_value(difference.left) != 1.0:
            return False
        right = difference.right
        names = names_in(right)
        if names & fresnel_vars or any(_METAL_NAME.search(n) for n in names):
            return True
        if any(_METAL_NAME.search(Field(f).name) for f in walk_kind(right, "field")):
            return True
        return self._has_fresnel(right, fn, fresnel_vars) or any(
            n.upper().startswith("F") or n.lower().startswith("ks") for n in names
        )
