"""Evaluation of `#if` / `#elif` integer constant expressions.

The operators and precedences are those of GLSL ES 3.00 section 3.4 (C's, without `?:` and
the comma; glslang and ANGLE reject `?:` too). By the time we get here `defined` has been
resolved and macros expanded; an identifier left over is an error in ES (glslang says so
too), not a silent 0 as in C.

`&&` and `||` short-circuit: section 3.4 says that undefined identifiers in an operand that
is not evaluated cause no error, so `#if defined(X) && X > 1` is fine without X. Nothing in
an unevaluated operand is an error but bad syntax: a division by zero there is not one either
(as in C and ANGLE; glslang and Mesa report it).
"""

from __future__ import annotations

from collections.abc import Callable

from glint.compiler.glsl.pptokens import Tok


class ExprError(Exception):
    """A bad `#if` expression; `col` points at the offending token (0 when unknown)."""

    def __init__(self, message: str, col: int = 0) -> None:
        super().__init__(message)
        self.col = col


# Binding power of each binary operator; higher binds tighter.
_BINARY: dict[str, int] = {
    "||": 1, "&&": 2, "|": 3, "^": 4, "&": 5,
    "==": 6, "!=": 6, "<": 7, ">": 7, "<=": 7, ">=": 7,
    "<<": 8, ">>": 8, "+": 9, "-": 9, "*": 10, "/": 10, "%": 10,
}  # fmt: skip


def evaluate(tokens: list[Tok], undefined: Callable[[Tok], None] | None = None) -> int:
    """Value of an expression given as significant (non-whitespace) tokens. An undefined name is
    an error (GLSL ES 3.00 §3.4), unless `undefined` is given: then it is told of the name and
    the name counts as 0, as in C."""
    if not tokens:
        raise ExprError("missing expression")
    parser = _Parser(tokens, undefined)
    value = parser.binary(1)
    if parser.pos < len(tokens):
        tok = tokens[parser.pos]
        raise ExprError(f"unexpected '{tok.text}' in expression", tok.col)
    return value


def _int_literal(tok: Tok) -> int:
    text = tok.text.rstrip("uU")
    try:
        if text[:2] in ("0x", "0X"):
            return int(text[2:], 16)
        if len(text) > 1 and text[0] == "0":
            return int(text, 8)
        return int(text, 10)
    except ValueError:
        raise ExprError(f"'{tok.text}' is not an integer constant", tok.col) from None


def _truncating_div(a: int, b: int, op: str, col: int) -> int:
    if b == 0:
        raise ExprError(f"division by zero in '{op}'", col)
    q = abs(a) // abs(b) * (1 if (a >= 0) == (b >= 0) else -1)
    return q if op == "/" else a - q * b


class _Parser:
    """Precedence-climbing evaluator over a token list."""

    def __init__(self, tokens: list[Tok], undefined: Callable[[Tok], None] | None = None) -> None:
        self.tokens = tokens
        self.undefined = undefined
        self.pos = 0
        self.unevaluated = 0  # > 0 inside an operand that `&&` or `||` short-circuits

    def _peek(self) -> Tok | None:
        return self.tokens[self.pos] if self.pos < len(self.tokens) else None

    def binary(self, min_power: int) -> int:
        left = self.unary()
        while (tok := self._peek()) is not None and _BINARY.get(tok.text, 0) >= min_power:
            self.pos += 1
            skipped = int((tok.text == "&&" and not left) or (tok.text == "||" and bool(left)))
            self.unevaluated += skipped
            right = self.binary(_BINARY[tok.text] + 1)  # all binary operators are left-assoc
            self.unevaluated -= skipped
            if self.unevaluated and tok.text in ("/", "%") and right == 0:
                left = 0  # not evaluated: no division by zero
            else:
                left = _apply(tok, left, right)
        return left

    def unary(self) -> int:
        tok = self._peek()
        if tok is None:
            raise ExprError("expression ends too early")
        self.pos += 1
        if tok.text == "(":
            value = self.binary(1)
            close = self._peek()
            if close is None or close.text != ")":
                raise ExprError("missing ')' in expression", tok.col)
            self.pos += 1
            return value
        if tok.text in ("+", "-", "~", "!"):
            value = self.unary()
            return {"+": value, "-": -value, "~": ~value, "!": int(not value)}[tok.text]
        if tok.kind == "num":
            return _int_literal(tok)
        if tok.kind == "ident":
            if self.unevaluated:
                return 0
            if self.undefined is not None:
                self.undefined(tok)
                return 0
            raise ExprError(f"undefined macro '{tok.text}' in expression", tok.col)
        raise ExprError(f"unexpected '{tok.text}' in expression", tok.col)


def _apply(op: Tok, a: int, b: int) -> int:
    match op.text:
        case "||":
            return int(bool(a) or bool(b))
        case "&&":
            return int(bool(a) and bool(b))
        case "|":
            return a | b
        case "^":
            return a ^ b
        case "&":
            return a & b
        case "==":
            return int(a == b)
        case "!=":
            return int(a != b)
        case "<":
            return int(a < b)
        case ">":
            return int(a > b)
        case "<=":
            return int(a <= b)
        case ">=":
            return int(a >= b)
        case "<<":
            return a << b if b >= 0 else 0
        case ">>":
            return a >> b if b >= 0 else 0
        case "+":
            return a + b
        case "-":
            return a - b
        case "*":
            return a * b
        case _:
            return _truncating_div(a, b, op.text, op.col)
