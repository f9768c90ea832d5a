"""Correctness (C1xx): data flow. Reads of values that were never written, and a mainImage
that can return without writing its colour. Built on the definite-assignment analysis in
`analysis/flow.py`, which stays silent where it cannot follow the code."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from ..analysis.flow import FunctionFlow, Var, function_flows, mask_names
from ..analysis.model import call_args, root_variable
from ..context import LintContext, walk
from ..finding import Finding
from . import Rule, register


def _main_colour(flow: FunctionFlow) -> Var | None:
    """mainImage's `out` colour: its first parameter, when that is an `out`."""
    if flow.name != "mainImage" or not flow.outs:
        return None
    params = flow.definition.children[0].children  # type: ignore[union-attr]
    first = params[2].children[0] if len(params) > 2 else None  # type: ignore[union-attr]
    out = flow.outs[0]
    return out if isinstance(first, Tree) and out.token in first.children else None


def _assigns(definition: Tree, name: str) -> bool:
    """Whether any statement assigns to `name` (or a component of it), on any path."""
    for node in walk(definition):
        if node.data in ("assignment", "postfix"):
            target = node.children[0]
        elif node.data == "prefix":
            target = node.children[1]
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
    return any(n.data == "variable" and n.children[0] in ("gl_FragColor", "gl_FragData")
               for n in walk(definition))  # fmt: skip


@register
class ColourNotWritten(Rule):
    """Finds a mainImage that can finish without writing its `out` colour: a path through an
    `if`, a loop that may not run, or an early `return` leaves it (or some of its components)
    unwritten. `discard` counts as written.

    Why it matters: an `out` parameter starts undefined, so on that path the pixel is whatever
    the driver leaves there: black on one GPU, garbage or the previous frame on another.

    Example:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            if (fragCoord.x < 10.0) return;
            fragColor = vec4(1.0);
        }

    Fix:
        write the colour before the early return, or give it a default first:
        `fragColor = vec4(0.0, 0.0, 0.0, 1.0);`
    """

    code = "C101"
    name = "colour-not-written"
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for flow in function_flows(ctx):
            colour = _main_colour(flow)
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


@register
class ColourReadBeforeWritten(Rule):
    """Finds mainImage's `out` colour read before it is written, such as
    `fragColor.rgb *= 0.5;` or `fragColor += ...` as the first use.

    Why it matters: an `out` parameter starts undefined, not as ShaderToy's black; reading
    it gives whatever the driver leaves there, so the result differs between GPUs.

    Example:
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            fragColor.rgb += vec3(0.5);
            fragColor.a = 1.0;
        }

    Fix:
        assign it first: `fragColor = vec4(0.0); fragColor.rgb += vec3(0.5);`
    """

    code = "C102"
    name = "colour-read-before-written"
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for flow in function_flows(ctx):
            colour = _main_colour(flow)
            for read in flow.reads:
                if read.var is colour:
                    what = f"`{read.var.name}{mask_names(read.var, read.missing)}`"
                    message = (
                        f"{what} is read before mainImage writes it; out parameters start undefined"
                    )
                    yield self.report(ctx, read.node, message)


@register
class UsedBeforeInitialised(Rule):
    """Finds a local variable read before it is given a value on some path (declared without
    an initialiser, assigned only in one branch or in a loop that may not run), and an `out`
    parameter read before the function writes it.

    Why it matters: GLSL does not zero local variables. An uninitialised value is whatever
    the register held, so the shader looks right on one GPU and flickers on another.

    Example:
        float d;
        if (hit) d = t;
        col *= exp(-d);

    Fix:
        float d = 1e10;
        if (hit) d = t;
        col *= exp(-d);
    """

    code = "C103"
    name = "used-before-initialised"
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for flow in function_flows(ctx):
            colour = _main_colour(flow)
            for read in flow.reads:
                var = read.var
                if var is colour:
                    continue
                what = f"`{var.name}{mask_names(var, read.missing)}`"
                if var.kind == "out":
                    message = (
                        f"out parameter {what} is read before {flow.name} writes it; "
                        "out parameters start undefined (use `inout` to pass a value in)"
                    )
                else:
                    line = ctx.span(var.token)[0]
                    message = (
                        f"{what} may be read before it is given a value (declared without "
                        f"one on line {line}); GLSL does not zero local variables"
                    )
                yield self.report(ctx, read.node, message)
