"""C003 syntax-error."""

from __future__ import annotations

from collections.abc import Iterator

from glint.compiler.glsl import GLSLSyntaxError
from glint.compiler.glsl.keywords import RESERVED_WORDS

from ...context import LintContext
from ...finding import Finding
from .. import Rule, register


@register
class SyntaxError_(Rule):
    """Finds GLSL that glint's parser cannot read (GLSL ES 3.00 grammar).

    Why is this bad?
        Nothing else can be checked in a file that does not parse, and the driver will reject it
        too. glslang's message for the same line (C001) is reported instead when glslang runs and
        finds an error there, and a reserved word is left to P007.

    Example:
        float x = 1.0
        vec3 y;

    Use instead:
        float x = 1.0;
        vec3 y;

    Fix safety:
        No fix: what the author meant cannot be read from code that does not parse.

    References:
        - GLSL ES 3.00 spec §9 (Shading Language Grammar)
    """

    code = "C003"
    name = "syntax-error"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "correctness"
    severity = "error"
    needs_tree = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        error = ctx.front_end_error
        if not isinstance(error, GLSLSyntaxError) or ctx.read_problem:
            return
        if _reserved_word(error.what):
            return  # P007 reports every reserved word, parsed or not: one finding per token
        line = min(ctx.file_line(error.line), len(ctx.lines))  # the parser's: the physical one
        if line < 1:
            return  # in the Common tab's code: reported when that file is linted
        # glslang's error on the same line says it (C001), unless C001 is not selected: then
        # this is the only finding that the file does not compile
        glslang_says = ctx.use_glslang and ctx.reports_glslang_errors
        if glslang_says and any(d.severity == "error" and d.line == line for d in ctx.glslang()):
            return
        yield self.report(ctx, (line, error.column, line, error.column + 1), error.what)


def _reserved_word(what: str) -> bool:
    """Whether the parser stopped at a word of RESERVED_WORDS (its message for them)."""
    words = what.split("'")
    return what.endswith("is a reserved word") and len(words) > 1 and words[1] in RESERVED_WORDS
