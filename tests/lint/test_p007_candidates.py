"""P007 tokenizes only the lines where its prefilter finds a reserved word that may be an
identifier: every line where the tokenizer finds one must be among them."""

from __future__ import annotations

from pathlib import Path

from glint.compiler.glsl.keywords import RESERVED_WORDS
from glint.compiler.glsl.pptokens import tokenize
from glint.lint.rules.portability.p007_reserved_word import _candidate_lines

CORPUS = Path(__file__).resolve().parent.parent / "corpus"

# Reserved words next to what may or may not end an identifier: other letters, digits, `_`,
# a non-ASCII letter (a token of its own before an identifier), numbers and operators.
TRICKY = """float input = 1.0;
inputs output_ _half 2half 1.0e5filter 1.input
éinput inputé (cast)+common;public
vec3 f=vec3(0.0);active
\tfixed\t
"""


def reserved_lines(text: str) -> list[int]:
    """The lines the rule reports on when it tokenizes every line."""
    found = []
    for number, line in enumerate(text.split("\n"), start=1):
        if any(t.kind == "ident" and t.text in RESERVED_WORDS for t in tokenize(line)):
            found.append(number)
    return found


def test_the_prefilter_keeps_every_line_with_a_reserved_identifier() -> None:
    texts = [TRICKY] + [p.read_text(encoding="utf-8") for p in sorted(CORPUS.rglob("*.glsl"))]
    for text in texts:
        assert set(reserved_lines(text)) <= set(_candidate_lines(text))
    assert reserved_lines(TRICKY) == [1, 3, 4, 5]
    assert _candidate_lines(TRICKY) == [1, 2, 3, 4, 5]  # `1.input` is one number
