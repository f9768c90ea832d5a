"""C004 preprocessor-error."""

from __future__ import annotations

from collections.abc import Iterator

from glint.compiler.glsl import PreprocessorError

from ...context import LintContext
from ...finding import Finding
from .. import Rule, register


@register
class PreprocessorProblem(Rule):
    """Finds preprocessor errors: unknown or malformed directives, unterminated `#if`, `#error`, bad
    macro calls.

    Why is this bad?
        The shader is not what it looks like until the preprocessor has run, and a driver stops at
        the first such error.

    Example:
        #ifdef HIGH_QUALITY
        const int STEPS = 128;

    Use instead:
        #ifdef HIGH_QUALITY
        const int STEPS = 128;
        #endif

    Fix safety:
        No fix: where a missing `#endif` belongs is the author's choice.

    References:
        - GLSL ES 3.00 spec §3.4 (Preprocessor)
    """

    code = "C004"
    name = "preprocessor-error"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "correctness"
    severity = "error"
    needs_tree = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        error = ctx.front_end_error
        if ctx.read_problem:
            return
        # what the lenient preprocessor went past (an undefined name in `#if`), then what
        # stopped it
        errors = list(ctx.pre.problems) if ctx.pre is not None else []
        if isinstance(error, PreprocessorError):
            errors.append(error)
        for error in errors:
            line = min(ctx.file_line(error.physical_line), len(ctx.lines))  # not moved by #line
            if line < 1:
                continue  # in the Common tab's code: reported when that file is linted
            span = (line, error.column, line, error.column + 1)
            yield self.report(ctx, span, error.what)
