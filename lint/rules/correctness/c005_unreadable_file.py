"""C005 unreadable-file."""

from __future__ import annotations

from collections.abc import Iterator

from ...context import LintContext
from ...finding import Finding
from .. import Rule, register


@register
class Unreadable(Rule):
    """Finds files that are not GLSL text: binary data, bytes that are not UTF-8 outside
    comments, or a file too large to analyse (over 1 MB).

    A comment may hold bytes of an older encoding (a Latin-1 degree sign in a shader of 2013):
    GLSL and glslang ignore what a comment holds, so such a file is linted, and a fix writes
    those bytes back unchanged.

    Why is this bad?
        A shader is text; anything else is a wrong path or a corrupted file, and should be said
        plainly rather than reported as a thousand syntax errors.

    Example:
        // shader.frag that holds the bytes of a PNG image

    Fix:
        Lint the shader's source, saved as UTF-8 text.

    Fix safety:
        No fix.

    References:
        - GLSL ES 3.00 spec §3.1 (Character Set)
    """

    code = "C005"
    name = "unreadable-file"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "correctness"
    severity = "error"
    needs_tree = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        if ctx.read_problem:
            yield self.report(ctx, (1, 1, 1, 1), f"cannot lint this file: {ctx.read_problem}")
