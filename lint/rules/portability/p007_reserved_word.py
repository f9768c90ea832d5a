"""P007 reserved-word."""

from __future__ import annotations

import re
from collections.abc import Iterator

from glint.compiler.glsl.keywords import RESERVED_WORDS
from glint.compiler.glsl.pptokens import tokenize

from ...context import LintContext
from ...finding import Finding
from .. import Rule, register


@register
class ReservedWord(Rule):
    """Finds GLSL ES 3.00 reserved words used as names: `input`, `output`, `sample`, `filter`,
    `common`, `partition`, `active`, `half`, `fixed`, `superp`, `cast`, ...

    Why is this bad?
        These words are reserved for future versions, and using one anywhere (a variable, a
        function, a struct member) is a compile error in GLSL ES, though some desktop drivers accept
        them. Checked on the preprocessed tokens, so it is reported even when the file does not
        parse.

    Example:
        float sample = texture(iChannel0, uv).r;

    Use instead:
        float sampled = texture(iChannel0, uv).r;

    Fix safety:
        No fix: a new name has to be chosen, and it must not clash with another.

    References:
        - GLSL ES 3.00 spec §3.7 (Keywords: the list of reserved words)
    """

    code = "P007"
    name = "reserved-word"
    category = "portability"
    severity = "error"
    needs_tree = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        if ctx.pre is None or ctx.read_problem:
            return
        for number, text in enumerate(ctx.pre.text.split("\n"), start=1):
            if not text.strip():
                continue
            for tok in tokenize(text):
                if tok.kind != "ident" or tok.text not in RESERVED_WORDS:
                    continue
                line = ctx.pre.locate(number).line
                column = tok.col
                if number in ctx.pre.expansions:  # columns moved: find it in the user's line
                    found = re.search(rf"\b{tok.text}\b", ctx.lines[line - 1]) if (
                        0 < line <= len(ctx.lines)) else None  # fmt: skip
                    column = found.start() + 1 if found else 1
                span = (line, column, line, column + len(tok.text))
                message = (f"`{tok.text}` is a reserved word in GLSL ES 3.00 and cannot be "
                           "used as a name; rename it")  # fmt: skip
                yield self.report(ctx, span, message)
