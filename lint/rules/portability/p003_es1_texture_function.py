"""P003 es1-texture-function."""

from __future__ import annotations

from collections.abc import Iterator

from glint.compiler.glsl.ast import Call

from ...context import LintContext
from ...finding import Finding, Fix
from .. import Rule, register
from ._common import defined_names, is_es1

# GLSL ES 1.00 (and its extensions') texture functions and their ES 3.00 overloads.
ES1_TEXTURE = {
    "texture2D": "texture",
    "textureCube": "texture",
    "texture3D": "texture",
    "texture2DLod": "textureLod",
    "textureCubeLod": "textureLod",
    "texture2DLodEXT": "textureLod",
    "textureCubeLodEXT": "textureLod",
    "texture2DProj": "textureProj",
    "texture2DProjLod": "textureProjLod",
    "texture2DProjLodEXT": "textureProjLod",
    "texture2DGradEXT": "textureGrad",
    "textureCubeGradEXT": "textureGrad",
    "texture2DProjGradEXT": "textureProjGrad",
}


@register
class Es1Texture(Rule):
    """Finds the GLSL ES 1.00 texture functions (`texture2D`, `textureCube`, `texture2DLod`,
    `texture2DProj`, their EXT variants), which GLSL ES 3.00 removed.

    Why is this bad?
        ES 3.00 has one overloaded `texture()` (and `textureLod`, `textureProj`, `textureGrad`) for
        every sampler type; the old names are undeclared and the shader fails to compile on
        ShaderToy and in WebGL 2.

    Example:
        vec4 c = texture2D(iChannel0, uv);

    Use instead:
        vec4 c = texture(iChannel0, uv);

    Fix safety:
        Safe: each renamed function is the ES 3.00 overload with the same arguments and result. A
        file that defines a function of the old name itself is not renamed.

    References:
        - GLSL ES 3.00 spec §8.8 (Texture Lookup Functions)
        - Khronos reference page:
          https://registry.khronos.org/OpenGL-Refpages/es3/html/texture.xhtml
    """

    code = "P003"
    name = "es1-texture-function"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "portability"
    severity = "error"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        if is_es1(ctx):
            return
        own = defined_names(ctx)  # a file may define its own texture2D as a shim
        for node in ctx.nodes("call"):
            call = Call(node)
            old = call.callee_name
            if old is None:
                continue
            callee = call.callee
            new = ES1_TEXTURE.get(old)
            if new is None or old in own:
                continue
            edit = ctx.replace(callee, new)
            fix = Fix(f"use `{new}`", (edit,)) if edit else None
            message = f"`{old}` is GLSL ES 1.00; GLSL ES 3.00 has `{new}`"
            yield self.report(ctx, callee, message, fix)
