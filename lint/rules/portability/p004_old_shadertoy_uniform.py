"""P004 old-shadertoy-uniform."""

from __future__ import annotations

from collections.abc import Iterator

from glint.compiler.glsl.ast import Field, variable_name

from ...context import LintContext, walk_kind
from ...finding import Finding, Fix
from .. import Rule, register
from ._common import declares_name, defined_names


@register
class OldShadertoyUniform(Rule):
    """Finds ShaderToy uniforms under their old names (`iGlobalTime`, renamed `iTime` in 2017) and
    `iChannelResolution` used without an index.

    Why is this bad?
        ShaderToy no longer declares `iGlobalTime`, so old shaders pasted in fail with "undeclared
        identifier". `iChannelResolution` is an array of four vec3, one per channel;
        `iChannelResolution.xy` does not compile.

    Example:
        float t = iGlobalTime;
        vec2 size = iChannelResolution.xy;

    Use instead:
        float t = iTime;
        vec2 size = iChannelResolution[0].xy;

    Fix safety:
        Safe: `iGlobalTime` becomes `iTime`, the same value under its current name (not when the
        file declares `iGlobalTime` itself). The missing index is not fixed: which channel is meant
        is the author's choice.

    References:
        - ShaderToy's How To (https://www.shadertoy.com/howto): the uniforms it declares
    """

    code = "P004"
    name = "old-shadertoy-uniform"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "portability"
    severity = "error"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        own = defined_names(ctx)
        if "iGlobalTime" in own:
            return  # the file declares it itself
        shadowed = declares_name(ctx.tree, "iTime") or "iTime" in own
        for node in walk_kind(ctx.tree, "variable", "field"):
            if variable_name(node) == "iGlobalTime":
                edit = None if shadowed else ctx.replace(node, "iTime")
                fix = Fix("use `iTime`", (edit,)) if edit else None
                message = "`iGlobalTime` is ShaderToy's old name for `iTime`"
                yield self.report(ctx, node, message, fix)
            elif (
                node.data == "field"
                and "iChannelResolution" not in own
                and variable_name(Field(node).base) == "iChannelResolution"
            ):
                message = ("`iChannelResolution` is an array, one vec3 per channel: "
                               "index it, e.g. `iChannelResolution[0].xy`")  # fmt: skip
                yield self.report(ctx, node, message)
