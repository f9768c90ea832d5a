"""L007 hdr-without-tonemap."""

from __future__ import annotations

import math
from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import Assignment, JumpStatement

from ...analysis.constants import const_value, global_constants
from ...analysis.functions import Function, callable_from_main, functions
from ...analysis.model import semantic_model
from ...analysis.syntax import (
    binary_op,
    call_args,
    call_name,
    calls_in,
    operands,
    root_var,
)
from ...context import LintContext, Node, walk, walk_kind
from ...finding import Finding
from .. import Rule, register
from ._common import (
    ColourOutput,
    data_output,
    is_lobe,
    is_vector,
    main_image,
    output_writes,
    product_factors,
    rough_bound,
    short_text,
)
from ._terms import cosine_of, lights_surface


def _light_terms(fn: Function, up: dict[int, Tree]) -> list[Node]:
    """Whole products (chains of * and /) that carry a lighting cosine or a specular lobe."""
    terms = []
    for node in walk_kind(fn.body, "binary"):
        if binary_op(node) not in ("*", "/") or binary_op(up.get(id(node))) in ("*", "/"):
            continue
        top, _ = product_factors(node)
        if any(cosine_of(f, fn) in ("NL", "NH", "NV") or is_lobe(f, fn) for f in top):
            terms.append(node)
    return terms


@register
class HdrWithoutTonemap(Rule):
    """Finds lighting that can exceed 1 written to the output without a tone map.

    Evidence that values exceed 1, in a lit shader: a light term (a product with N·L, N·H or N·V, or
    a pow lobe) whose bound is above 1, or two or more light terms summed in one function whose
    bounds add up to more than 1. The bound is the semantic model's when it is finite; otherwise the
    product of the term's constants (an intensity such as `2.0 * sunColor`, `vec3(1.3, 1.0, 0.7)`,
    divided by the constant divisors such as π), with cosines, lobes and values the code does not
    spell out taken as at most 1. A clamp (clamp(col, 0.0, 1.0) or min(col, 1.0)) is not a tone map,
    but it shows that the author chose to clip, so it is not reported either, whether it is in
    mainImage or in the colour a function it runs returns; this rule is for code that never
    considered the range. "Lit" and the buffer-pass signals are L005's.

    Why is this bad?
        The display clips each channel at 1, so bright highlights and sums of lights lose their hue
        (a saturated orange light clips to yellow, then white) and detail flattens. A tone map (x /
        (1 + x), an ACES fit, 1 − exp(−x)) rolls highlights off.

    Example:
        col = 2.0 * albedo * max(dot(n, l), 0.0) + spec;
        fragColor = vec4(pow(col, vec3(0.4545)), 1.0);

    Use instead:
        col = 2.0 * albedo * max(dot(n, l), 0.0) + spec;
        col = col / (1.0 + col);
        fragColor = vec4(pow(col, vec3(0.4545)), 1.0);

    Fix safety:
        No fix: the choice of tone map, and of exposure, is the author's.

    References:
        - Reinhard et al., "Photographic Tone Reproduction for Digital Images", SIGGRAPH 2002
        - Narkowicz, "ACES Filmic Tone Mapping Curve", 2016
    """

    code = "L007"
    name = "hdr-without-tonemap"
    category = "lighting"
    default = False  # opt-in: few of its sampled findings on real shaders are worth acting on

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        found = main_image(ctx)
        if found is None or not lights_surface(ctx) or data_output(ctx):
            return
        output = ColourOutput(ctx)
        if output.any_tonemap():
            return
        fn, out = found
        writes = output_writes(fn, out)
        if not writes or self._clipped(ctx):
            return
        evidence = self._evidence(ctx)
        if evidence:
            yield self.report(
                ctx,
                writes[-1],
                f"lighting can exceed 1 ({evidence}) and is written to `{out}` without a tone "
                "map; the display clips it (try col / (1.0 + col) before the gamma)",
            )

    def _clipped(self, ctx: LintContext) -> bool:
        """A clip in mainImage, or in the colour a function it runs returns (render() ending
        in `col = clamp(col, 0., 1.)`, `return vec4(clamp(col, 0., 1.), m)`)."""
        found = main_image(ctx)
        assert found is not None
        fn, _ = found
        if any(_clip(ctx, node) for node in calls_in(fn.body)):
            return True
        defined = {f.name: f for f in functions(ctx)}
        for name in callable_from_main(ctx) or ():
            if name != fn.name and _returns_clipped(ctx, defined[name]):
                return True
        return False

    def _evidence(self, ctx: LintContext) -> str:
        assert ctx.tree is not None
        up = ctx.parents()
        for fn in functions(ctx):
            terms = _light_terms(fn, up)
            for term in terms:
                hi = self._hi(ctx, term, fn)
                if hi is not None and hi > 1.0:
                    return f"`{short_text(ctx, term, 40)}` reaches about {hi:.3g}"
            sums = self._summed(ctx, fn, terms)
            if sums:
                return sums
        return ""

    def _hi(self, ctx: LintContext, node: Node, fn: Function) -> float | None:
        """The model's finite upper bound, else the bound from the code's constants."""
        hi = _bounded_hi(ctx, node)
        return hi if hi is not None else rough_bound(node, fn, global_constants(ctx))

    def _summed(self, ctx: LintContext, fn: Function, terms: list[Node]) -> str:
        ids = {id(t) for t in terms}

        def carries(node: Node) -> bool:
            return any(id(n) in ids for n in walk(node)) if isinstance(node, Tree) else False

        def may_exceed(parts: list[Node]) -> bool:
            his = [self._hi(ctx, p, fn) for p in parts]
            return sum(1.0 if h is None else h for h in his) > 1.0

        per_target: dict[str, list[Node]] = {}
        for node in walk_kind(fn.body, "binary", "assignment"):
            if binary_op(node) == "+":
                parts = operands(node, "+")
                if sum(1 for p in parts if carries(p)) >= 2 and may_exceed(parts):
                    return f"light terms summed in {fn.name}"
            assignment = Assignment.cast(node)
            if assignment is not None and assignment.op == "+=":
                target = root_var(assignment.target) or ""
                if carries(assignment.value):
                    added = per_target.setdefault(target, [])
                    added.append(assignment.value)
                    if len(added) >= 2 and may_exceed(added):
                        return f"light terms accumulated into `{target}` in {fn.name}"
        return ""


def _clip(ctx: LintContext, node: Node) -> bool:
    name = call_name(node)
    args = call_args(node) if name else []  # type: ignore[arg-type]
    if name in ("clamp", "saturate") and args and is_vector(ctx, args[0]):
        return True
    return name == "min" and any(const_value(a) == 1.0 for a in args)


def _returns_clipped(ctx: LintContext, fn: Function) -> bool:
    """Whether the function returns a clipped colour: a clip (inside a constructor too), or a
    variable last given one."""
    for node in walk_kind(fn.body, "jump_statement"):
        value = JumpStatement(node).value
        if value is None:
            continue
        while isinstance(value, Tree) and value.data == "constructor" and call_args(value):
            value = call_args(value)[0]
        if _clip(ctx, value):
            return True
        name = root_var(value)
        if name is None:
            continue
        writes = [a.value for w in walk_kind(fn.body, "assignment")
                  if root_var((a := Assignment(w)).target) == name]  # fmt: skip
        if writes and _clip(ctx, writes[-1]):
            return True
    return False


def _bounded_hi(ctx: LintContext, node: Node) -> float | None:
    """The model's upper bound of the value when it has a finite one, else None."""
    hi = semantic_model(ctx).range_of(node).hi
    return float(hi) if math.isfinite(hi) else None
