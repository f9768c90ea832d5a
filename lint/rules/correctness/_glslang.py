"""Shared by C001 and C002: glslangValidator's diagnostics of the file compiled as its target
wraps it (ShaderToy's prelude and `main`), at the user's line and column, with a hint for the
mistakes people make most."""

from __future__ import annotations

import re
from collections.abc import Iterator

from ...context import LintContext
from ...finding import Finding
from .. import Rule

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


class GlslangRule(Rule):
    needs_tree = False
    wanted = ""

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        if not ctx.use_glslang or ctx.read_problem:
            return
        for d in ctx.glslang():
            if d.severity != self.wanted or d.file != ctx.file:
                continue  # another severity, or in the Common tab (reported for that file)
            hint = hint_for(d.message)
            message = f"glslang: {d.message}" + (f" (hint: {hint})" if hint else "")
            line = min(max(d.line, 1), len(ctx.lines))
            yield self.report(ctx, (line, d.column, line, d.column + 1), message)
