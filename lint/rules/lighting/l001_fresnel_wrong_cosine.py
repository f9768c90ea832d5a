"""L001 fresnel-wrong-cosine."""

from __future__ import annotations

import re
from collections.abc import Iterator

from lark import Tree

from ...analysis.constants import const_value
from ...analysis.functions import Function, functions
from ...analysis.syntax import call_args, call_name, calls_in
from ...context import LintContext, Node
from ...finding import Finding
from .. import Rule, register
from ._common import COSINE_TEXT, short_text
from ._terms import cosine_of, is_fresnel_name, schlick_base


def _fresnel_terms(fn: Function) -> Iterator[tuple[Tree, Node]]:
    """Fresnel terms of a function body and the cosine each is fed: calls of functions named
    like Fresnel/Schlick (the argument that is a known cosine), and inline
    `f0 + (1 - f0) * pow(1 - x, 5)` (x)."""
    for node in calls_in(fn.body):
        base = schlick_base(node)
        if base is not None:
            yield node, base
        elif is_fresnel_name(call_name(node)):
            known = [a for a in call_args(node) if cosine_of(a, fn)]
            if len(known) == 1:
                yield node, known[0]


# Functions where Schlick-shaped factors of N·L and N·V are right: diffuse models with a
# retro-reflection or transmission factor (Burley/Disney, Shirley, Ashikhmin).
_DIFFUSE_CONTEXT = re.compile(r"diffuse|burley|disney|lambert|shirley|ashikhmin|^fd", re.I)


@register
class FresnelCosine(Rule):
    """Finds a Fresnel term fed with N·L or N·H, where V·H belongs (for a light; L·H is the same
    angle) or N·V (for environment light).

    Fresnel terms are calls of functions named like Fresnel or Schlick (not Schlick's phase function
    or G1), and the inline form `f0 + (1 - f0) * pow(1 - x, 5)`. Cosines are read from names: dot(N,
    L) with the usual vector names, or precomputed NdotL, NoL, ndl, and locals holding them. Diffuse
    models that multiply Schlick factors of N·L and N·V on purpose (Burley, Shirley) are not
    reported: the function has a matching N·V factor or a diffuse name.

    Why is this bad?
        Fresnel depends on the angle between the viewer and the microfacet that reflects toward it,
        the half vector. N·L makes surfaces brighten where the light grazes them instead of where
        the eye does, so rim reflections appear on the wrong side.

    Example:
        float NdotL = max(dot(N, L), 0.0);
        vec3 F = f0 + (1.0 - f0) * pow(1.0 - NdotL, 5.0);

    Use instead:
        float VdotH = max(dot(V, H), 0.0);
        vec3 F = f0 + (1.0 - f0) * pow(1.0 - VdotH, 5.0);

    Fix safety:
        No fix: the half vector may not exist yet where the term is computed.

    References:
        - Schlick, "An Inexpensive BRDF Model for Physically-based Rendering", Computer Graphics
          Forum 13(3), 1994
        - Walter et al., "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007
        - Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013 course notes
    """

    code = "L001"
    name = "fresnel-wrong-cosine"
    default = False  # opt-in: no finding on the corpus, so no measured precision
    category = "lighting"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for fn in functions(ctx):
            if _DIFFUSE_CONTEXT.search(fn.name):
                continue
            terms = [(node, cosine_of(arg, fn), arg) for node, arg in _fresnel_terms(fn)]
            paired = any(kind == "NV" for _, kind, _ in terms)
            for node, kind, arg in terms:
                if kind not in ("NL", "NH") or (kind == "NL" and paired):
                    continue
                if len(call_args(node)) == 3 and any(const_value(a) == 1.0
                                                     for a in call_args(node)):  # fmt: skip
                    continue  # F_Schlick(1.0, f90, NoL): a diffuse scatter factor, not specular
                yield self.report(
                    ctx,
                    arg,
                    f"Fresnel fed with {COSINE_TEXT[kind]} (`{short_text(ctx, arg)}`): use V·H for "
                    "a light (L·H is the same angle), N·V for environment light",
                )
