"""P002 gl-fragcolor."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import FunctionDefinition, Index, token_text, variable_name

from ...analysis.syntax import parameter_parts, prototype_parts
from ...context import LintContext, Node, walk
from ...finding import Finding, Fix
from .. import Rule, register
from ._common import declares_name, is_es1, signature_problem


def _functions(ctx: LintContext) -> list[Tree]:
    assert ctx.tree is not None
    return [n for n in ctx.tree.children if isinstance(n, Tree) and n.data == "function_definition"]


def _main_image_out(ctx: LintContext) -> tuple[Tree, str] | None:
    """mainImage's definition and the name of its `out vec4` colour, when its signature is
    the one ShaderToy calls."""
    for fdef in _functions(ctx):
        ret, name, params = prototype_parts(FunctionDefinition(fdef).prototype.syntax)
        if name == "mainImage" and signature_problem(ret, params) is None:
            pname = parameter_parts(params[0])[3]
            if pname is not None:
                return fdef, str(pname)
    return None


@register
class FragColor(Rule):
    """Finds `gl_FragColor` and `gl_FragData`, which GLSL ES 3.00 removed.

    Why is this bad?
        ShaderToy compiles GLSL ES 3.00, where these names are undeclared; the colour goes out
        through mainImage's `out vec4` parameter instead.

    Example:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            gl_FragColor = vec4(1.0);
        }

    Use instead:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            fragColor = vec4(1.0);
        }

    Fix safety:
        Safe: inside mainImage, where the parameter's name is known, the write goes to the same
        output. Uses outside mainImage are not fixed.

    References:
        - GLSL ES 3.00 spec §4.3.6 (Output Variables) and §7.2 (Fragment Shader Special Variables,
          which no longer list gl_FragColor)
    """

    code = "P002"
    name = "gl-fragcolor"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "portability"
    severity = "error"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        if is_es1(ctx):
            return
        uses = [
            n for n in ctx.nodes("variable") if variable_name(n) in ("gl_FragColor", "gl_FragData")
        ]
        if not uses:
            return  # most files: nothing to look up
        main = _main_image_out(ctx)
        inside: set[int] = set()
        if main is not None and not declares_name(FunctionDefinition(main[0]).body, main[1]):
            inside = {id(n) for n in walk(main[0])}
        parents = ctx.parents()
        for node in uses:
            target: Node = node
            name = variable_name(node)
            if name == "gl_FragData":
                parent = Index.cast(parents.get(id(node)))
                at_zero = parent is not None and _literal(parent.index) == "0"
                target = parent.syntax if at_zero else node  # type: ignore[union-attr]
            fix = None
            if id(node) in inside and (target is not node or name == "gl_FragColor"):
                edit = ctx.replace(target, main[1])  # type: ignore[index]
                fix = Fix(f"write `{main[1]}`", (edit,)) if edit else None  # type: ignore[index]
            old = ctx.node_text(target).strip() or str(name)
            where = f"`{main[1]}`" if main else "mainImage's `out vec4` parameter"
            message = f"`{old}` does not exist in GLSL ES 3.00; write {where}"
            yield self.report(ctx, target, message, fix)


def _literal(node: Node) -> str | None:
    if isinstance(node, Tree) and node.data in ("int_literal", "float_literal"):
        return token_text(node)
    return None
