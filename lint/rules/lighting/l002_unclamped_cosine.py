"""L002 unclamped-cosine."""

from __future__ import annotations

import re
from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import Assignment, Constructor, Declarator, JumpStatement

from ...analysis.constants import const_value
from ...analysis.functions import Function, functions, resolve
from ...analysis.model import is_unit, may_be_negative
from ...analysis.syntax import binary_op, call_name, names_in, operands, root_var, var_name
from ...context import LintContext, Node, walk_kind
from ...finding import Finding, Fix
from .. import Rule, register
from ._common import COSINE_TEXT, short_text
from ._terms import cosine_of, vector_role

_DIFFUSE_FUNCTION = re.compile(r"diffuse|lambert|brdf|shade|light|illum|^fd|^dif", re.I)


_CLAMPS = {"max", "clamp", "saturate", "abs", "smoothstep", "step", "sqrt", "pow"}


_COLOUR_TYPES = ("vec3", "vec4")


@register
class UnclampedCosine(Rule):
    """Finds N·L or N·V that can be negative multiplied into a colour (or returned as a diffuse
    term) without max, clamp or saturate.

    The range comes from the semantic model (a value whose interval may be negative) when it is
    available; candidates are dot(N, L) / dot(N, V) calls and locals holding one, in a product with
    a colour (a vec3/vec4 factor or target) or returned bare by a function named like diffuse,
    Lambert, BRDF, shade or light. A cosine that the function compares (`if (ndl > 0.0)`) is taken
    as guarded, and a product with a scalar constant only (half-Lambert's `dot(N, L) * 0.5 + 0.5`)
    is not a lighting term; nor is wrap lighting with any scale (`0.6 + density * dot(N, L) *
    0.4`: a positive constant plus the scaled cosine), nor a direction scaled by a cosine (`v - n
    * nv`, a projection, which must stay signed).

    Why is this bad?
        On the side facing away from the light the cosine is negative, and the product subtracts
        light: other lights and ambient terms go dark or negative, and a later pow or sqrt of the
        sum is undefined.

    Example:
        vec3 col = albedo * dot(N, L);

    Use instead:
        vec3 col = albedo * max(dot(N, L), 0.0);

    Fix safety:
        Unsafe: the inserted max(..., 0.0) changes every pixel where the cosine was negative, which
        is the point, but also code that relied on the negative part on purpose (a signed term that
        a later step folds back).

    References:
        - Akenine-Möller et al., Real-Time Rendering, 4th ed., 2018, ch. 9 (the clamped cosine
          (n·l)⁺)
        - Lambert's cosine law
    """

    code = "L002"
    name = "unclamped-cosine"
    default = False  # opt-in: no finding on the corpus, so no measured precision
    category = "lighting"
    fixable = "unsafe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        self._ctx = ctx
        up = ctx.parents()
        for fn in functions(ctx):
            compared: set[str] | None = None  # found when a candidate needs it (few do)
            for node in walk_kind(fn.body, "jump_statement", "binary"):
                returned = JumpStatement(node).value if node.data == "jump_statement" else None
                if returned is not None:
                    candidates = [returned]
                    # a bare cosine returned by a diffuse-named function is its diffuse term;
                    # elsewhere (`facing(n, v)`) a signed cosine may be the point
                    colour = bool(_DIFFUSE_FUNCTION.search(fn.name))
                elif binary_op(node) == "*" and binary_op(up.get(id(node))) != "*":
                    candidates = operands(node, "*")
                    if not any(self._cosine(c, fn) for c in candidates):
                        continue  # no N·L or N·V here: skip the costlier tests below
                    # a scalar constant scales the cosine (half-Lambert); a colour does not
                    others = [c for c in candidates if const_value(c) is None
                              or (isinstance(c, Tree) and c.data == "constructor")]  # fmt: skip
                    colour = (
                        len(others) >= 2
                        and not self._geometry(candidates, fn)
                        and not self._wrapped(node, up)
                        and self._colour(node, candidates, fn, up)
                    )
                else:
                    continue
                if not colour:
                    continue
                if compared is None:
                    compared = self._compared(fn)
                for operand in candidates:
                    if (
                        self._raw(operand, fn, compared)
                        and not self._clamped(node, up, fn)
                        and may_be_negative(ctx, operand)
                    ):
                        yield self._finding(ctx, operand, fn)

    def _geometry(self, factors: list[Node], fn: Function) -> bool:
        """`n * nv`: a direction (a normal, light, view or half vector) scaled by a cosine is a
        projection (v - n * dot(n, v) is v's tangent part), which must stay signed."""
        for f in factors:
            role = vector_role(f, fn)
            if (
                role is not None
                and cosine_of(f, fn) is None
                and (role == "N" or is_unit(self._ctx, f))
            ):  # a colour may be named `light`; a unit vector is a direction
                return True
        return False

    def _wrapped(self, node: Tree, up: dict[int, Tree]) -> bool:
        """`a + s * dot(N, L)` with a positive constant a: wrap lighting (half-Lambert with any
        scale, such as a density), whose negative side is meant to darken, not to subtract."""
        current: Node = node
        while (parent := up.get(id(current))) is not None and binary_op(parent) in ("+", "*"):
            if binary_op(parent) == "+":
                others = [p for p in operands(parent, "+") if p is not current]
                if any((const_value(p) or 0.0) > 0.0 for p in others):
                    return True
            current = parent
        return False

    def _raw(self, node: Node, fn: Function, compared: set[str]) -> bool:
        return self._cosine(node, fn) and not (names_in(node) & compared)

    @staticmethod
    def _cosine(node: Node, fn: Function) -> bool:
        """Whether the factor is N·L or N·V: a dot call, or a local holding one."""
        value = resolve(node, fn)
        return call_name(value) == "dot" and cosine_of(value, fn) in ("NL", "NV")

    def _compared(self, fn: Function) -> set[str]:
        found: set[str] = set()
        for node in walk_kind(fn.body, "binary"):
            if binary_op(node) in ("<", ">", "<=", ">="):
                found |= names_in(node)
        return found

    def _clamped(self, node: Tree, up: dict[int, Tree], fn: Function) -> bool:
        current: Node = node
        while (parent := up.get(id(current))) is not None and parent is not fn.body:
            if call_name(parent) in _CLAMPS or binary_op(parent) in ("<", ">", "<=", ">="):
                return True
            if parent.data in ("declaration_statement", "expression_statement"):
                break
            current = parent
        return False

    def _colour(self, node: Tree, factors: list[Node], fn: Function, up: dict[int, Tree]) -> bool:
        """Whether the product is a colour: a vec3/vec4 factor, or it goes into one."""
        for factor in factors:
            name = var_name(factor)
            typ = fn.type_of(name) if name else None
            if typ in _COLOUR_TYPES:
                return True
            if (
                isinstance(factor, Tree)
                and factor.data == "constructor"
                and ctx_type(factor) in _COLOUR_TYPES
            ):
                return True
        parent = up.get(id(node))
        while parent is not None and parent.data in ("binary", "unary"):
            parent = up.get(id(parent))
        if parent is None:
            return False
        if parent.data == "declarator":
            return fn.locals.get(Declarator(parent).name) in _COLOUR_TYPES
        if parent.data == "assignment":
            target = root_var(Assignment(parent).target)
            return bool(target) and fn.type_of(target) in _COLOUR_TYPES  # type: ignore[arg-type]
        return False

    def _finding(self, ctx: LintContext, operand: Node, fn: Function) -> Finding:
        kind = COSINE_TEXT[cosine_of(resolve(operand, fn), fn) or "NL"]
        fix = None
        if call_name(operand) == "dot":
            edit = ctx.replace(operand, f"max({ctx.node_text(operand)}, 0.0)")
            if edit is not None:
                fix = Fix("clamp the cosine at 0", (edit,), "unsafe")
        return self.report(
            ctx,
            operand,
            f"{kind} (`{short_text(ctx, operand)}`) is negative facing away and is used unclamped "
            "in a lighting term; take max(..., 0.0)",
            fix,
        )


def ctx_type(node: Tree) -> str:
    """The type a constructor builds, "" for an array or a struct in place."""
    spec = Constructor(node).type
    return spec.name if spec.array is None and spec.struct is None else ""
