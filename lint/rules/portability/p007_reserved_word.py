"""P007 reserved-word."""

from __future__ import annotations

import re
from collections.abc import Iterator

from glint.compiler.glsl.keywords import RESERVED_WORDS
from glint.compiler.glsl.pptokens import tokenize

from ...context import LintContext
from ...finding import Finding
from .. import Rule, register

# A reserved word where the tokenizer may find it as an identifier: not right after a letter,
# digit or `_` (those would make it part of a longer identifier or number), nor before a word
# character. Lines without one need not be tokenized, which was most of the rule's time.
_CANDIDATE = re.compile(r"(?<![A-Za-z0-9_])(?:" + "|".join(sorted(RESERVED_WORDS)) + r")(?!\w)")


def _candidate_lines(text: str) -> list[int]:
    """The numbers (1-based) of the lines where a reserved word may be an identifier."""
    numbers: list[int] = []
    line, seen = 1, 0
    for match in _CANDIDATE.finditer(text):
        line += text.count("\n", seen, match.start())
        seen = match.start()
        if not numbers or numbers[-1] != line:
            numbers.append(line)
    return numbers


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
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "portability"
    severity = "error"
    needs_tree = False

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        if ctx.pre is None or ctx.read_problem:
            return
        lines = ctx.pre.text.split("\n")
        for number in _candidate_lines(ctx.pre.text):
            for tok in tokenize(lines[number - 1]):
                if tok.kind != "ident" or tok.text not in RESERVED_WORDS:
                    continue
                line = ctx.file_line(number)
                if line < 1:
                    break  # on the Common tab's lines in front of the file
                column = tok.col
                if number in ctx.pre.expansions:  # columns moved: find it in the user's line
                    found = re.search(rf"\b{tok.text}\b", ctx.lines[line - 1]) if (
                        0 < line <= len(ctx.lines)) else None  # fmt: skip
                    column = found.start() + 1 if found else 1
                span = (line, column, line, column + len(tok.text))
                message = (f"`{tok.text}` is a reserved word in GLSL ES 3.00 and cannot be "
                           "used as a name; rename it")  # fmt: skip
                yield self.report(ctx, span, message)
