"""C101 colour-not-written."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import Assignment, operand, variable_name

from ...analysis.flow import function_flows, mask_names
from ...analysis.syntax import call_args, root_variable
from ...context import LintContext, walk_kind
from ...finding import Finding
from .. import Rule, register
from ._data_flow import main_colour


def _assigns(definition: Tree, name: str) -> bool:
    """Whether any statement assigns to `name` (or a component of it), on any path."""
    for node in walk_kind(definition, "assignment", "postfix", "prefix", "call"):
        if node.data == "assignment":
            target = Assignment(node).target
        elif node.data in ("postfix", "prefix"):
            target = operand(node)
        elif node.data == "call":  # an out/inout argument may write it
            if any(root_variable(arg) == name for arg in call_args(node)):
                return True
            continue
        else:
            continue
        if root_variable(target) == name:
            return True
    return False


def _writes_gl_fragcolor(definition: Tree) -> bool:
    return any(variable_name(n) in ("gl_FragColor", "gl_FragData")
               for n in walk_kind(definition, "variable"))  # fmt: skip


@register
class ColourNotWritten(Rule):
    """Finds a mainImage that can finish without writing its `out` colour: a path through an `if`, a
    loop that may not run, or an early `return` leaves it (or some of its components) unwritten.
    `discard` counts as written.

    Why is this bad?
        An `out` parameter starts undefined, so on that path the pixel is whatever the driver leaves
        there: black on one GPU, garbage or the previous frame on another.

    Example:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            if (fragCoord.x < 10.0) return;
            fragColor = vec4(1.0);
        }

    Use instead:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            fragColor = vec4(0.0, 0.0, 0.0, 1.0);
            if (fragCoord.x < 10.0) return;
            fragColor = vec4(1.0);
        }

    Fix safety:
        No fix: which colour the early path should write is the author's choice.

    References:
        - GLSL ES 3.00 spec §6.1.1 (Function Calling Conventions: `out` parameters are not copied
          in) and §4.3.6 (Output Variables)
        - ShaderToy's How To (https://www.shadertoy.com/howto): mainImage's signature
    """

    code = "C101"
    name = "colour-not-written"
    default = False  # below 80% worth acting on in the labelled corpus sample
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for flow in function_flows(ctx):
            colour = main_colour(flow)
            if colour is None or _writes_gl_fragcolor(flow.definition):
                continue  # P002 reports the colour written to the wrong place
            ever = _assigns(flow.definition, colour.name)
            for exit_ in flow.exits:
                missing = colour.full & ~exit_.state.get(id(colour), 0)
                if not missing:
                    continue
                what = f"`{colour.name}{mask_names(colour, missing)}`"
                if missing == colour.full and not ever:
                    message = f"mainImage never writes {what}; the pixel is undefined"
                    yield self.report(ctx, colour.token, message)
                    break
                if exit_.node is not None:
                    message = f"mainImage returns here before writing {what}"
                    yield self.report(ctx, exit_.node, message)
                else:
                    message = (
                        f"{what} is not written on every path through mainImage; "
                        "give it a value first (out parameters start undefined)"
                    )
                    yield self.report(ctx, colour.token, message)
