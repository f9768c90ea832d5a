"""Preprocessing tokens: the small lexer the preprocessor works on.

The preprocessor has to see identifiers, numbers and punctuation (to expand macros and to
evaluate `#if`), but must give back the text it did not touch unchanged, so whitespace is kept
as tokens too and joining the tokens of a line gives the line back.
"""

from __future__ import annotations

import re
from typing import NamedTuple

_TOKEN_RE = re.compile(
    r"""
    (?P<ws>[ \t\f\v\r]+)
  | (?P<ident>[A-Za-z_]\w*)
  | (?P<num>\.?\d(?:[eE][+-]|[\w.])*)      # a pp-number: 1, 1.5e-3, 0x1Fu, 2.f
  | (?P<op>\#\#|<<=|>>=|\+\+|--|<<|>>|<=|>=|==|!=|&&|\|\||\^\^|[-+*/%&|^]=
         |[-+*/%&|^!~=<>?:;,.(){}\[\]\#])
  | (?P<other>.)
    """,
    re.VERBOSE,
)


class Tok(NamedTuple):
    """One preprocessing token; `hide` holds the macros that must not expand it again."""

    kind: str  # ws, ident, num, op, other, or placeholder (an empty `##` operand)
    text: str
    col: int = 0  # 1-based column in its line, 0 for tokens made by expansion
    hide: frozenset[str] = frozenset()


_NOT_HIDDEN: frozenset[str] = Tok._field_defaults["hide"]


def tokenize(text: str) -> list[Tok]:
    """Split one line of text into tokens, whitespace included."""
    # `tuple.__new__` is what `Tok(...)` runs after a Python-level call filling in the
    # defaults; the linter tokenizes every line of every file, so that call is worth saving
    new = tuple.__new__
    return [
        new(Tok, (match.lastgroup or "other", match.group(), match.start() + 1, _NOT_HIDDEN))
        for match in _TOKEN_RE.finditer(text)
    ]


def join(tokens: list[Tok]) -> str:
    """Text of a token list, as it will be handed to the parser."""
    return "".join(t.text for t in tokens)


# Where the user's own tokens landed on an expanded line: (start, end) offsets in the output
# line (0-based, end exclusive) and the token's column in the source line (1-based).
Segment = tuple[int, int, int]


def join_expanded(
    tokens: list[Tok],
    segments: list[Segment] | None = None,
    arguments: frozenset[int] = frozenset(),
) -> str:
    """Text of a line after macro expansion: as `join`, with a space where an expanded token
    would otherwise fuse with its neighbour into another token (`a-b` with b = `-1.` must stay
    `a - -1.`, not become `a--1.`): the preprocessor works on tokens, not on text. With
    `segments`, records where each token of the source line (col > 0) went, but for the
    `arguments` of macro calls (by column): they went inside an expansion."""
    out: list[str] = []
    length = 0
    previous: Tok | None = None
    for tok in tokens:
        if (
            previous is not None
            and tok.kind != "ws"
            and previous.kind != "ws"
            and (tok.col == 0 or previous.col == 0)
            and _fuse(previous.text, tok.text)
        ):
            out.append(" ")
            length += 1
        if segments is not None and tok.col > 0 and tok.kind != "ws" and tok.col not in arguments:
            segments.append((length, length + len(tok.text), tok.col))
        out.append(tok.text)
        length += len(tok.text)
        previous = tok
    return "".join(out)


def _fuse(left: str, right: str) -> bool:
    """Whether `left` written right before `right` lexes as something else."""
    match = _TOKEN_RE.match(left + right)
    return match is None or match.group() != left


def strip_ws(tokens: list[Tok]) -> list[Tok]:
    """Drop leading and trailing whitespace tokens."""
    start, end = 0, len(tokens)
    while start < end and tokens[start].kind == "ws":
        start += 1
    while end > start and tokens[end - 1].kind == "ws":
        end -= 1
    return tokens[start:end]


def significant(tokens: list[Tok]) -> list[Tok]:
    """Tokens without whitespace, for directive parsing and `#if` evaluation."""
    return [t for t in tokens if t.kind != "ws"]
