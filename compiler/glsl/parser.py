"""Parse preprocessed GLSL ES 3.00 into a lark tree with positions on every node.

Tree positions (`tree.meta.line`, token `.line`) are lines of the *preprocessed* text; map them
to the user's file with `Preprocessed.locate`. `parse_source` does both steps and reports
syntax errors at the original file:line.
"""

from __future__ import annotations

import functools
from collections.abc import Iterator
from pathlib import Path

from lark import Lark, Token, Tree
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken
from lark.lark import PostLex

from ..errors import InputError
from .keywords import BUILTIN_TYPES, QUALIFIER_GROUPS, RESERVED_WORDS, words
from .preprocessor import Preprocessed, preprocess

_GRAMMAR = Path(__file__).with_name("glsl.lark")

# How terminals are named in "expected ..." lists; several collapse into one word.
_FRIENDLY = {
    "IDENTIFIER": "identifier",
    "BUILTIN_TYPE": "type",
    "TYPE_NAME": "type",
    "INTCONSTANT": "number",
    "FLOATCONSTANT": "number",
    "TRUE": "number",
    "FALSE": "number",
    "STORAGE_QUALIFIER": "qualifier",
    "PRECISION_QUALIFIER": "qualifier",
    "INTERPOLATION_QUALIFIER": "qualifier",
    "INVARIANT": "qualifier",
    "LAYOUT": "qualifier",
}
# Punctuation that usually *is* the fix goes first in the list.
_FIRST = ("';'", "')'", "']'", "'}'", "','", "':'", "'('", "'{'", "identifier", "an expression")
_OPERATORS = words(
    "= *= /= %= += -= <<= >>= &= ^= |= || ^^ && | ^ & == != < > <= >= << >> + - * / % "
    "++ -- ? . [ ! ~"
)
_MAX_EXPECTED = 6


class GLSLSyntaxError(InputError):
    """A syntax error at `file:line:column`."""

    def __init__(self, file: str, line: int, column: int, what: str) -> None:
        super().__init__(f"{file}:{line}:{column}: syntax error: {what}")
        self.file = file
        self.line = line
        self.column = column
        self.what = what


class _ReservedWord(Exception):
    def __init__(self, token: Token) -> None:
        super().__init__(token.value)
        self.token = token


class _TypeNamePostLex(PostLex):
    """Retypes identifiers that are really keywords or type names, so LALR can tell
    a declaration (`S x;`) from an expression (`a * b;`).

    Struct names are learnt as `struct NAME` goes by. A snippet may also use a struct that
    another snippet defines; no expression has two identifiers in a row, so an unknown name
    followed by an identifier is taken as a type (`Material m`) and remembered as one.
    Scopes are ignored, as shaders rarely reuse a type's name for anything else."""

    always_accept = ()

    def process(self, stream: Iterator[Token]) -> Iterator[Token]:
        types: set[str] = set()
        after_struct = False
        tokens = iter(stream)
        tok = next(tokens, None)
        while tok is not None:
            nxt = next(tokens, None)  # one token of lookahead
            if tok.type == "IDENTIFIER":
                self._retype(tok, nxt, types, after_struct)
            after_struct = tok.type == "STRUCT"
            yield tok
            tok = nxt

    @staticmethod
    def _retype(tok: Token, nxt: Token | None, types: set[str], after_struct: bool) -> None:
        text = tok.value
        if text in BUILTIN_TYPES:
            tok.type = "BUILTIN_TYPE"
        elif text in QUALIFIER_GROUPS:
            tok.type = QUALIFIER_GROUPS[text]
        elif text in RESERVED_WORDS or "__" in text:
            raise _ReservedWord(tok)
        elif after_struct:
            types.add(text)
        elif text in types or _is_plain_identifier(nxt):
            tok.type = "TYPE_NAME"
            types.add(text)


def _is_plain_identifier(tok: Token | None) -> bool:
    return (
        tok is not None
        and tok.type == "IDENTIFIER"
        and tok.value not in BUILTIN_TYPES
        and tok.value not in QUALIFIER_GROUPS
    )


@functools.cache
def glsl_parser() -> Lark:
    """The LALR parser, built once per process (building it takes a while)."""
    return Lark(
        _GRAMMAR.read_text(encoding="utf-8"),
        parser="lalr",
        lexer="basic",
        postlex=_TypeNamePostLex(),
        propagate_positions=True,
        maybe_placeholders=False,
    )


def parse(text: str, filename: str = "<input>") -> Tree:
    """Parse preprocessed GLSL; raise GLSLSyntaxError with the position in `text`."""
    try:
        return glsl_parser().parse(text)
    except _ReservedWord as exc:
        tok = exc.token
        raise GLSLSyntaxError(
            filename, tok.line or 1, tok.column or 1, f"'{tok.value}' is a reserved word"
        ) from None
    except UnexpectedInput as exc:
        line, column, what = _describe(exc, text)
        raise GLSLSyntaxError(filename, line, column, what) from None


def parse_source(
    source: str, filename: str = "<input>", predefined: dict[str, str] | None = None
) -> tuple[Tree, Preprocessed]:
    """Preprocess and parse; errors point at the original file and line."""
    pre = preprocess(source, filename, predefined)
    try:
        return parse(pre.text, filename), pre
    except GLSLSyntaxError as exc:
        loc = pre.locate(exc.line)
        raise GLSLSyntaxError(loc.file, loc.line, exc.column, exc.what) from None


def _describe(exc: UnexpectedInput, text: str) -> tuple[int, int, str]:
    """Position and wording of a lark error."""
    if isinstance(exc, UnexpectedCharacters):
        return exc.line, exc.column, f"unexpected character '{exc.char}'"
    if isinstance(exc, UnexpectedToken) and exc.token.type != "$END":
        tok = exc.token
        what = f"unexpected '{tok.value}'"
        return tok.line or 1, tok.column or 1, what + _expected(_accepted(exc))
    expected = _accepted(exc) if isinstance(exc, UnexpectedToken) else set()
    if isinstance(exc, UnexpectedEOF):
        expected = set(exc.expected)
    lines = text.rstrip().split("\n") or [""]
    return len(lines), len(lines[-1]) + 1, "unexpected end of input" + _expected(expected)


def _accepted(exc: UnexpectedToken) -> set[str]:
    """Terminals the parser would really take here; LALR's `expected` over-approximates."""
    try:
        return set(exc.accepts) or set(exc.expected)
    except Exception:  # the simulation is a nicety; never let it hide the real error
        return set(exc.expected)


def _expected(names: set[str]) -> str:
    """`, expected one of ...`, short: operators collapse, the likely fixes come first."""
    words: set[str] = set()
    starts_expression = "INTCONSTANT" in names
    for name in names:
        word = _friendly(name)
        if starts_expression and word in ("identifier", "number", "'('"):
            words.add("an expression")
        elif word.strip("'") in _OPERATORS:
            if not starts_expression:  # else they are only unary operators of an expression
                words.add("an operator")
        else:
            words.add(word)
    if not words:
        return ""
    ordered = sorted(words, key=lambda w: (_FIRST.index(w) if w in _FIRST else len(_FIRST), w))
    shown = ordered[:_MAX_EXPECTED]
    more = ", ..." if len(ordered) > _MAX_EXPECTED else ""
    if len(shown) == 1:
        return f", expected {shown[0]}"
    return ", expected one of " + ", ".join(shown) + more


@functools.cache
def _friendly(name: str) -> str:
    if name in _FRIENDLY:
        return _FRIENDLY[name]
    for term in glsl_parser().terminals:
        if term.name == name and term.pattern.type == "str":
            return f"'{term.pattern.value}'"
    return name.lower()
