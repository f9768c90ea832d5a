"""PF001 pow-small-integer."""

from __future__ import annotations

from collections.abc import Iterator

from ...analysis.constants import const_value, folded
from ...analysis.functions import Function, function_map
from ...analysis.syntax import call_args, call_name, is_simple
from ...context import LintContext, walk_kind
from ...finding import Finding, Fix
from .. import Rule, register
from ._common import needs_parens


def _owners(ctx: LintContext) -> dict[int, Function]:
    """The function each call sits in, by id."""
    owner: dict[int, Function] = {}
    for fn in function_map(ctx).values():
        for node in walk_kind(fn.body, "call"):
            owner[id(node)] = fn
    return owner


@register
class PowSmallInteger(Rule):
    """Finds `pow(x, 2.0)` to `pow(x, 5.0)` of a plain variable or swizzle, where a few multiplies
    say the same thing.

    Only plain variables and swizzles are reported, where the product repeats no work and no side
    effect: `pow(clamp(1.0 - c, 0.0, 1.0), 5.0)` would need a temporary of a type the fix cannot
    always name, so it is left alone. A base that is a compile-time constant (literals, macros,
    `const` names, or a variable that still holds a constant where it is read) is not reported
    either: the compiler computes the power and no instruction runs.

    Opt-in: Mesa (nir_opt_algebraic), LLVM-based AMD compilers and NVIDIA's already turn pow by 2
    to 5 into multiplies, so on real shaders this is a portability and accuracy hint (slow or
    low-precision mobile pow), rarely a measurable saving.

    Why is this bad?
        pow is exp2(y·log2(x)) on most GPUs, two transcendental operations and a multiply, and less
        accurate than x·x. Many drivers rewrite small constant exponents themselves, but not all
        (and not at every precision), so spelling out the product is never slower.

    Example:
        float spec = pow(NoH, 2.0) * k;

    Use instead:
        float spec = NoH * NoH * k;

    Fix safety:
        Safe: for x ≥ 0 the product is the same value (more exact); for x < 0, pow is undefined in
        GLSL while the product is defined, so only code that was already wrong can change.

    References:
        - GLSL ES 3.00 spec §8.2 (Exponential Functions)
        - Khronos reference page: https://registry.khronos.org/OpenGL-Refpages/es3/html/pow.xhtml
    """

    code = "PF001"
    name = "pow-small-integer"
    certainty = "certain"
    category = "performance"
    severity = "info"
    fixable = "safe"
    default = False

    _FORMS = {
        2: "{x} * {x}",
        3: "{x} * {x} * {x}",
        4: "({x} * {x}) * ({x} * {x})",
        5: "{x} * {x} * {x} * {x} * {x}",
    }

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        up = ctx.parents()
        owner = _owners(ctx)
        for node in ctx.nodes("call"):
            if call_name(node) != "pow":
                continue
            args = call_args(node)
            if len(args) != 2 or not is_simple(args[0]):
                continue
            exponent = const_value(args[1])
            if exponent not in (2.0, 3.0, 4.0, 5.0):
                continue
            if folded(ctx, args[0], owner.get(id(node))):
                continue  # a constant base: the compiler computes the power, nothing runs
            n = int(exponent)  # type: ignore[arg-type]
            base = ctx.node_text(args[0])
            product = self._FORMS[n].format(x=base)
            text = f"({product})" if needs_parens(node, up.get(id(node))) else product
            edit = ctx.replace(node, text)
            fix = Fix(f"write {product}", (edit,)) if edit else None
            yield self.report(
                ctx,
                node,
                f"pow({base}, {n}.0) costs two transcendentals; {product} is exact and cheaper",
                fix,
            )
