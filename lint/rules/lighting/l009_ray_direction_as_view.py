"""L009 ray-direction-as-view."""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from lark import Tree

from glint.compiler.glsl.ast import Assignment, Binary, Unary

from ...analysis.constants import const_value
from ...analysis.functions import Function, functions
from ...analysis.syntax import binary_op, call_args, call_name, calls_in, var_name
from ...context import LintContext, Node, walk
from ...finding import Finding
from .. import Rule, register
from ._common import short_text
from ._terms import vector_role


@dataclass(frozen=True)
class _ViewUse:
    """Where a vector is used as the direction toward the eye: the node and what it computes."""

    node: Tree
    what: str  # "the half vector", "a clamped cosine", "a Schlick Fresnel factor"


# Names of a ray direction. Shadow and AO loops march along the light direction or the normal
# as well, so a march alone does not say which vector points away from the eye; the name does
# (the lighting rules read roles from names, see _terms.py).
_RAY_NAME = re.compile(r"^(rd|d|dir|rdir|direction)\d?$|ray|^eye_?dir$", re.I)


def _marched(fn: Function) -> dict[str, Tree]:
    """The ray directions a function marches along: `d` in `o + d * t`, `o + t * d` or
    `p += d * t` with a step `t` that varies (`p + n * 0.01`, an offset along a normal, is no
    march) and a ray's name, with the expression that shows it."""
    found: dict[str, Tree] = {}
    for node in walk(fn.body):
        if binary_op(node) == "+":
            steps = [Binary(node).left, Binary(node).right]
        elif node.data == "assignment" and Assignment(node).op == "+=":
            steps = [Assignment(node).value]
        else:
            continue
        for step in steps:
            if binary_op(step) != "*":
                continue
            a, b = Binary(step).left, Binary(step).right  # type: ignore[arg-type]
            for factor, other in ((a, b), (b, a)):
                name = var_name(factor)
                if (
                    name is not None
                    and _is_vec3(fn, name)
                    and const_value(other) is None
                    and _RAY_NAME.search(name)
                ):
                    found.setdefault(name, node)
    return found


def _is_vec3(fn: Function, name: str) -> bool:
    return fn.type_of(name) == "vec3"


def _negated(fn: Function) -> set[str]:
    """Names assigned a negation somewhere (`v = -rd`): their direction flips, no fact holds."""
    names = set()
    for node in walk(fn.body):
        assignment = Assignment.cast(node)
        unary = Unary.cast(assignment.value) if assignment is not None else None
        if assignment is not None and unary is not None and unary.op == "-":
            name = var_name(assignment.target)
            names |= {name} if name else set()
    return names


def _view_uses(fn: Function) -> dict[str, list[_ViewUse]]:
    """Where each name is used as the view vector (toward the eye), in one walk of the body: in
    a half vector with a light `normalize(name + l)`, a cosine with a normal clamped at 0
    (`max(dot(n, name), 0.0)`, `clamp(dot(n, name), 0.0, 1.0)`) or a Schlick factor
    `1.0 - dot(n, name)`."""
    uses: dict[str, list[_ViewUse]] = {}
    for node in walk(fn.body):
        callee = call_name(node)
        args = call_args(node) if callee else []
        if callee == "normalize" and len(args) == 1 and binary_op(args[0]) == "+":
            a, b = Binary(args[0]).left, Binary(args[0]).right  # type: ignore[arg-type]
            names = {
                name
                for vector, light in ((a, b), (b, a))
                if (name := var_name(vector)) is not None and vector_role(light, fn) == "L"
            }
            for name in names:
                uses.setdefault(name, []).append(_ViewUse(node, "the half vector"))
        elif callee in ("max", "clamp") and len(args) >= 2 and const_value(args[1]) == 0.0:
            for name in _dotted_with_normal(fn, args[0]):
                uses.setdefault(name, []).append(_ViewUse(node, "a cosine clamped at 0"))
        elif binary_op(node) == "-" and const_value(Binary(node).left) == 1.0:
            for name in _dotted_with_normal(fn, Binary(node).right):
                uses.setdefault(name, []).append(_ViewUse(node, "a Schlick Fresnel factor"))
    return uses


def _dotted_with_normal(fn: Function, node: Node) -> set[str]:
    """The variables v of `dot(n, v)` or `dot(v, n)` with n a normal."""
    args = call_args(node) if call_name(node) == "dot" else []  # type: ignore[arg-type]
    if len(args) != 2:
        return set()
    a, b = args
    return {
        name
        for vector, normal in ((a, b), (b, a))
        if (name := var_name(vector)) is not None and vector_role(normal, fn) == "N"
    }


def _rays(fns: list[Function]) -> tuple[dict[str, set[str]], dict[str, dict[str, Tree]]]:
    """Per function, the names that hold a ray direction, and among them those with evidence
    in the function itself (the expression that shows it): vectors it marches along, and
    arguments it passes to a parameter that its callee marches along (`intersect(ro, rd)`);
    then parameters that every call site passes a ray direction. Names the function negates
    (`v = -rd`) hold no fact. A fixpoint over the call graph: a direction passed on through
    shade(p, rd) into spec(n, rd, l) is still one."""
    by_name = {f.name: f for f in fns}
    negated = {f.name: _negated(f) for f in fns}
    own = {f.name: {n: e for n, e in _marched(f).items() if n not in negated[f.name]} for f in fns}
    rays = {f.name: set(own[f.name]) for f in fns}
    for _ in range(len(fns) + 1):
        passed: dict[tuple[str, int], list[bool]] = {}
        changed = False
        for f in fns:
            for call in calls_in(f.body):
                callee = by_name.get(call_name(call) or "")
                if callee is None:
                    continue
                for i, arg in enumerate(call_args(call)):
                    name = var_name(arg)
                    passed.setdefault((callee.name, i), []).append(name in rays[f.name])
                    param = callee.param_order[i] if i < len(callee.param_order) else ""
                    if (
                        name is not None
                        and param in own[callee.name]
                        and name not in rays[f.name]
                        and name not in negated[f.name]
                        and _is_vec3(f, name)
                        and _RAY_NAME.search(name)
                    ):
                        own[f.name][name] = call
                        rays[f.name].add(name)
                        changed = True
        for f in fns:
            for i, param in enumerate(f.param_order):
                flags = passed.get((f.name, i))
                new = param not in rays[f.name] and param not in negated[f.name]
                if flags and all(flags) and _is_vec3(f, param) and new:
                    rays[f.name].add(param)
                    changed = True
        if not changed:
            break
    return rays, own


@register
class RayDirectionAsView(Rule):
    """Finds a ray direction (the vector a march steps along, pointing away from the eye) used
    where the view vector (pointing toward the eye) belongs: in a half vector, a cosine clamped
    at 0, or a Schlick Fresnel factor, directly or passed to a function that uses its parameter
    so.

    A ray direction is a vec3 that the function marches along (`p = ro + rd * t`, `p += rd *
    h`) and never negates, or a parameter that every call site passes one. It is reported where
    it enters the use: at the call that passes it, or at the expression of the function that
    marches along it.

    Why is this bad?
        The view vector V points from the surface toward the eye, the ray direction the other
        way: V = -rd. With rd in its place, N·V is negative on every visible surface, so a
        clamped N·V is 0 (a Smith term of 0 or a division by it), `1 - dot(n, rd)` runs from 1 to
        2 (a Schlick factor up to 32), and `normalize(rd + l)` is not the half vector: the
        highlight lands where the light grazes away from the viewer.

    Example:
        vec3 h = normalize(rd + l);   // rd marches p = ro + rd * t

    Use instead:
        vec3 h = normalize(-rd + l);

    Fix safety:
        No fix: the sign may belong at the call site or in the function.

    References:
        - Akenine-Möller et al., Real-Time Rendering, 4th ed., §9.8 (the half vector h =
          normalize(l + v), v toward the viewer)
        - Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013 course notes (V and N·V)
    """

    code = "L009"
    name = "ray-direction-as-view"
    category = "lighting"
    default = False  # until its precision on real shaders is measured

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        fns = functions(ctx)
        by_name = {f.name: f for f in fns}
        rays, own = _rays(fns)
        uses_in = {f.name: _view_uses(f) for f in fns}
        views = {
            (f.name, i): uses
            for f in fns
            for i, p in enumerate(f.param_order)
            if (uses := uses_in[f.name].get(p))
        }
        for f in fns:
            # Reported where the evidence is: in the function that marches along the vector,
            # else at each call that passes one into a parameter used as the view vector.
            for name, evidence in sorted(own[f.name].items()):
                for use in uses_in[f.name].get(name, []):
                    yield self._direct(ctx, name, use, evidence)
            for call in calls_in(f.body):
                callee = by_name.get(call_name(call) or "")
                if callee is None:
                    continue
                for i, arg in enumerate(call_args(call)):
                    uses = views.get((callee.name, i))
                    if not uses or callee.param_order[i] in own[callee.name]:
                        continue
                    if var_name(arg) in rays[f.name]:
                        yield self._passed(ctx, arg, callee, i, uses[0])

    def _direct(self, ctx: LintContext, name: str, use: _ViewUse, march: Tree) -> Finding:
        line = ctx.span(march)[0]
        return self.report(
            ctx,
            use.node,
            f"`{short_text(ctx, use.node)}` uses {name}, the ray direction (marched at line "
            f"{line}), as the view vector in {use.what}: it points away from the eye, so on "
            f"visible surfaces dot(n, {name}) < 0; use -{name}",
        )

    def _passed(self, ctx: LintContext, arg: Node, callee: Function, i: int,
                use: _ViewUse) -> Finding:  # fmt: skip
        param = callee.param_order[i]
        line = ctx.span(use.node)[0]
        return self.report(
            ctx,
            arg,
            f"passes the ray direction {short_text(ctx, arg)} as `{param}` of {callee.name}(), "
            f"which uses it as the view vector in {use.what} at line {line} "
            f"(`{short_text(ctx, use.node)}`): it points away from the eye, so on visible "
            f"surfaces dot(n, {param}) < 0; pass -{short_text(ctx, arg)}",
        )
