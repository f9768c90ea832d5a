"""Correctness: glslangValidator's errors and warnings, the file compiled as its target wraps
it (ShaderToy's prelude and `main`), at the user's line and column, with a hint for the
mistakes people make most."""

from __future__ import annotations

import re
from collections.abc import Iterator

from ..context import LintContext
from ..finding import Finding
from . import Rule, register

# (what glslang says, what to do). Matched against "'token': message".
HINTS: list[tuple[re.Pattern[str], str]] = [
    (re.compile(r"'texture2D'|'textureCube'|'texture2DLod'"),
     "GLSL ES 3.00 has no texture2D/textureCube; use texture() (glint lint --fix does)"),
    (re.compile(r"'iGlobalTime'"), "ShaderToy renamed iGlobalTime to iTime (--fix does it)"),
    (re.compile(r"'gl_FragColor'"),
     "ES 3.00 has no gl_FragColor; write the `out vec4` parameter of mainImage"),
    (re.compile(r"cannot convert from ' ?(const )?(highp |mediump |lowp )?int' to "
                r"' ?(temp |const )?(highp |mediump |lowp )?float'|"
                r"wrong operand types.*int.*float|wrong operand types.*float.*int"),
     "ES has no implicit int-to-float conversion; write the literal as a float (1 -> 1.0)"),
    (re.compile(r"global (const )?variable initializers must be constant|"
                r"initializer.*not a constant"),
     "a global may only be initialised with a constant expression; assign it in mainImage"),
]  # fmt: skip


def hint_for(message: str) -> str:
    for pattern, hint in HINTS:
        if pattern.search(message):
            return hint
    return ""


class _Glslang(Rule):
    needs_tree = False
    wanted = ""

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        if not ctx.use_glslang or ctx.read_problem:
            return
        for d in ctx.glslang():
            if d.severity != self.wanted:
                continue
            hint = hint_for(d.message)
            message = f"glslang: {d.message}" + (f" (hint: {hint})" if hint else "")
            line = min(max(d.line, 1), len(ctx.lines))
            yield self.report(ctx, (line, d.column, line, d.column + 1), message)


@register
class GlslangError(_Glslang):
    """Finds what the Khronos reference compiler, glslangValidator, rejects, compiled exactly
    as the target wraps the file (ShaderToy: its uniforms before, a `main` after).

    Why it matters: a shader that glslang rejects will not compile in the browser either; the
    message is placed at the line and column of your file, not of the wrapped source. Where a
    glint rule reports an error on the same line (an int where a float belongs, a reserved
    word), glint's finding, with its fix, replaces glslang's.

    Example:
        vec4 c = texture2D(iChannel0, uv);

    Fix:
        vec4 c = texture(iChannel0, uv);
    """

    code = "C001"
    name = "glslang-error"
    category = "correctness"
    severity = "error"
    wanted = "error"


@register
class GlslangWarning(_Glslang):
    """Finds what glslangValidator warns about in the wrapped file.

    Why it matters: glslang's warnings mark code that some drivers treat differently or not at
    all (deprecated features, extension behaviour).

    Example:
        #extension GL_OES_standard_derivatives : enable

    Fix:
        remove the directive: derivatives are core in GLSL ES 3.00.
    """

    code = "C002"
    name = "glslang-warning"
    category = "correctness"
    severity = "warning"
    wanted = "warning"
