"""PF003 redundant-normalize."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import VariableDeclaration, operand, operator

from ...analysis.constants import folded
from ...analysis.functions import Function, functions, out_param_map, resolve, writes_of
from ...analysis.model import is_unit
from ...analysis.syntax import call_args, call_name, names_in, var_name
from ...context import LintContext, Node, walk_kind
from ...finding import Finding, Fix
from .. import Rule, register
from ._common import WRITERS, needs_parens


def _unit_by_form(node: Node, fn: Function | None, consts: dict[str, Node], depth: int = 4) -> bool:
    """Unit length by construction: normalize(...), reflect of unit vectors, a negated unit
    vector, or a local or global constant whose one value is one of those."""
    if depth <= 0 or not isinstance(node, Tree):
        return False
    name = call_name(node)
    if name == "normalize":
        return True
    if name == "reflect":
        return all(_unit_by_form(a, fn, consts, depth - 1) for a in call_args(node))
    if node.data == "unary" and operator(node) in "+-":
        return _unit_by_form(operand(node), fn, consts, depth - 1)
    variable = var_name(node)
    if variable is not None:
        value = resolve(node, fn, 1)
        if value is not node:
            return _unit_by_form(value, fn, consts, depth - 1)
        local = fn is not None and (variable in fn.locals or variable in fn.params)
        if not local and variable in consts:
            return _unit_by_form(consts[variable], None, consts, depth - 1)
    return False


def _const_values(ctx: LintContext) -> dict[str, Node]:
    values: dict[str, Node] = {}
    assert ctx.tree is not None
    for node in ctx.tree.children:
        if not (isinstance(node, Tree) and node.data == "variable_declaration"):
            continue
        declaration = VariableDeclaration(node)
        if not declaration.type.is_const:
            continue
        for declarator in declaration.declarators:
            init = declarator.initializer
            if isinstance(init, Tree):
                values[declarator.name] = init
    return values


def _written_earlier_in_sequence(
    node: Tree, inner: Node, up: dict[int, Tree], outs: dict[str, list[int]]
) -> bool:
    """Whether an earlier operand of a comma expression around the call writes a variable the
    argument reads: operands run left to right, so that write comes between the variable's
    declaration (or last assignment) and this use."""
    reads = names_in(inner)
    current: Node = node
    while (parent := up.get(id(current))) is not None:
        if parent.data == "sequence":
            for part in parent.children:
                if part is current:
                    break
                if any(writes_of(sub, outs) & reads for sub in walk_kind(part, *WRITERS)):
                    return True
        current = parent
    return False


@register
class RedundantNormalize(Rule):
    """Finds normalize() of a vector that is already unit length: normalize(normalize(x)), a
    variable whose only value came from normalize, a reflect of unit vectors.

    Only vectors that are unit by construction are reported, never parameters (whose callers may
    pass anything), nor a constant (`normalize(vec3(0, 1, 0))`, a `const` direction: the
    compiler folds it, and the form keeps the direction easy to edit), nor a variable that an
    earlier operand of the same comma expression changes.

    Opt-in: once constants are excluded, what remains is real but usually one rsqrt per pixel.

    Why is this bad?
        normalize is a dot product, an inverse square root and a multiply; doing it twice is waste,
        and usually a sign that the code is unsure where its vectors are normalized.

    Example:
        vec3 rd = normalize(dir);
        vec3 r = normalize(rd);

    Use instead:
        vec3 rd = normalize(dir);
        vec3 r = rd;

    Fix safety:
        Safe: renormalizing a unit vector changes it by rounding only.

    References:
        - GLSL ES 3.00 spec §8.5 (Geometric Functions: normalize, reflect)
        - Khronos reference pages: normalize, reflect (unit I and N give a unit result)
    """

    code = "PF003"
    name = "redundant-normalize"
    category = "performance"
    severity = "info"
    fixable = "safe"
    default = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        up = ctx.parents()
        consts = _const_values(ctx)
        outs = out_param_map(ctx)
        for fn in functions(ctx):
            for node in walk_kind(fn.body, "call"):
                if call_name(node) != "normalize":
                    continue
                args = call_args(node)
                if len(args) != 1:
                    continue
                inner = args[0]
                if folded(ctx, inner, fn):
                    continue  # normalize of a constant is folded by the compiler: it costs nothing
                if _written_earlier_in_sequence(node, inner, up, outs):
                    continue  # `no -= d, no = normalize(no)`: the first operand runs first
                # The model's unit facts about parameters come from today's callers; a
                # normalize that guards a parameter is kept for tomorrow's.
                modelled = not (names_in(inner) & set(fn.params)) and is_unit(ctx, inner)
                if not (_unit_by_form(inner, fn, consts) or modelled):
                    continue
                text = ctx.node_text(inner)
                simple = isinstance(inner, Tree) and inner.data in (
                    "call",
                    "variable",
                    "field",
                    "index",
                    "constructor",
                )
                if not simple and needs_parens(node, up.get(id(node))):
                    text = f"({text})"
                edit = ctx.replace(node, text)
                fix = Fix("drop the outer normalize", (edit,)) if edit else None
                shown = " ".join(ctx.node_text(inner).split())
                if len(shown) > 50:
                    shown = shown[:47] + "..."
                yield self.report(
                    ctx, node, f"`{shown}` is already unit length; normalize does nothing", fix
                )
