"""Macro definitions and their expansion.

Expansion follows the C preprocessor as GLSL ES 3.00 specifies it (no `#` stringizing, `##`
pasting allowed). Each token carries a "hide set" of macros it came from (Prosser's algorithm),
which is what stops a macro from expanding inside its own replacement while still letting
arguments be expanded and the result be rescanned.

Hide sets are shared: every token of one expansion holds the same set object, and a union is
made once per file for each pair of sets (`Expander._union`). Copied per token, a chain of a
thousand macros (`#define A1 A0+A0` ...) held a set of up to a thousand names in every one of
its tokens: gigabytes.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from glint.compiler.glsl.pptokens import Tok, strip_ws, tokenize


@dataclass(frozen=True)
class Macro:
    """A `#define`: `params` is None for an object-like macro."""

    name: str
    params: tuple[str, ...] | None
    body: str
    file: str
    line: int
    tokens: tuple[Tok, ...] = field(default=(), compare=False, repr=False)

    @staticmethod
    def make(name: str, params: tuple[str, ...] | None, body: str, file: str, line: int) -> Macro:
        """Build a macro, normalising the body's whitespace once (for comparing redefinitions)."""
        toks: list[Tok] = []
        for tok in strip_ws(tokenize(body)):
            if tok.kind == "ws":
                if toks and toks[-1].kind != "ws":
                    toks.append(Tok("ws", " "))
            else:
                toks.append(tok._replace(col=0))
        text = "".join(t.text for t in toks)
        return Macro(name, params, text, file, line, tuple(toks))


class NeedMoreInput(Exception):
    """A function-like macro call runs past the end of the tokens we were given."""


class MacroCallError(Exception):
    """A malformed macro call; the preprocessor turns it into a positioned error."""

    def __init__(self, message: str, col: int) -> None:
        super().__init__(message)
        self.col = col


_SPACE = Tok("ws", " ")
# Tokens that macro bodies may produce in one source. Macros that double (`#define B A A`)
# nest into billions of tokens; real shaders stay far below this (the corpus's largest
# expansion of a file is under 20,000 tokens).
MAX_EXPANDED_TOKENS = 500_000
# Macros expanding inside macros: a token's hide set holds one name per level, and each level
# makes a set of its own, so a chain of n macros (`#define A2 (A1+1)` ...) holds n^2/2 names.
# Real shaders nest a few levels (the corpus: 6).
MAX_MACRO_NESTING = 256
# Names held in all the distinct hide sets of one file: what bounds their memory whatever the
# shape of the macros (the corpus: under 200).
MAX_HIDDEN_NAMES = 1_000_000

HideSet = frozenset[str]


class Expander:
    """Expands macros in token lists against a (mutable) table of definitions."""

    def __init__(self, macros: dict[str, Macro], line: Callable[[], int]) -> None:
        self.macros = macros
        self._line = line  # current reported line, for __LINE__
        self.used: set[str] = set()  # macro names expanded since the caller last cleared it
        self.produced = 0  # tokens substituted so far, against MAX_EXPANDED_TOKENS
        self.outer = ""  # the macro, as the source names it, being expanded
        # (set, set) -> their union, the one object every token of that union holds
        self._unions: dict[tuple[HideSet, HideSet], HideSet] = {}
        self._hidden = 0  # names in the sets of `_unions`, against MAX_HIDDEN_NAMES

    def expand(self, tokens: list[Tok], more_input: bool = False) -> list[Tok]:
        """Fully expand `tokens`; raise NeedMoreInput when a call is cut off and more may follow."""
        out: list[Tok] = []
        stack = list(reversed(tokens))  # next token on top
        while stack:
            tok = stack.pop()
            name = tok.text
            if tok.kind != "ident" or name in tok.hide:
                out.append(tok)
            elif name == "__LINE__":
                out.append(Tok("num", str(self._line()), tok.col))
            elif name == "__FILE__":
                out.append(Tok("num", "0", tok.col))
            elif (macro := self.macros.get(name)) is None:
                out.append(tok)
            elif macro.params is None:
                self.used.add(name)
                self._entering(name, tok)
                hide = self._union(tok.hide, frozenset((name,)))
                self._check_nesting(hide, tok.col)
                body = self._substitute(macro, [], hide)
                self._count(len(body), tok.col)
                stack.extend(reversed([_SPACE, *body, _SPACE]))
            else:
                call = self._take_call(stack, more_input)
                if call is None:  # a function-like macro's name without `(` stays as it is
                    out.append(tok)
                    continue
                args, close = call
                self._entering(name, tok)
                # Arguments count too: calls nested in arguments copy them once per level.
                self._count(sum(len(a) for a in args), tok.col)
                args = self._check_arity(macro, args, tok.col)
                self.used.add(name)
                hide = self._union(tok.hide & close.hide, frozenset((name,)))
                self._check_nesting(hide, tok.col)
                body = self._substitute(macro, args, hide)
                self._count(len(body), tok.col)
                stack.extend(reversed([_SPACE, *body, _SPACE]))
        return out

    def _entering(self, name: str, tok: Tok) -> None:
        if not tok.hide:  # a name the source wrote, not one an expansion produced
            self.outer = name

    def _count(self, n: int, col: int) -> None:
        self.produced += n
        if self.produced > MAX_EXPANDED_TOKENS:
            raise MacroCallError(
                f"macro expansion too large: expanding '{self.outer}' takes this file's macro "
                f"expansions past {MAX_EXPANDED_TOKENS:,} tokens (macro calls nested too "
                "deeply, or macros that each use the one before twice, which doubles the "
                "expansion at every level)",
                col,
            )

    def _check_nesting(self, hide: HideSet, col: int) -> None:
        if len(hide) > MAX_MACRO_NESTING:
            raise MacroCallError(
                f"macros nested too deeply: expanding '{self.outer}' expands macros inside "
                f"macros more than {MAX_MACRO_NESTING} levels deep",
                col,
            )

    def _union(self, a: HideSet, b: HideSet) -> HideSet:
        """a | b, one object for every token that holds it (see the module's docstring)."""
        if not a or a is b:
            return b
        if not b:
            return a
        found = self._unions.get((a, b))
        if found is None:
            found = a | b
            if found == a:
                found = a
            elif found == b:
                found = b
            else:
                self._hidden += len(found)
                if self._hidden > MAX_HIDDEN_NAMES:
                    raise MacroCallError(
                        f"macro expansion too large: expanding '{self.outer}' nests more "
                        f"macros inside macros than glint follows ({MAX_HIDDEN_NAMES:,} names "
                        "hidden from re-expansion)",
                        0,
                    )
            self._unions[(a, b)] = found
        return found

    def _take_call(self, stack: list[Tok], more_input: bool) -> tuple[list[list[Tok]], Tok] | None:
        """Pop `( args )` from the stack if it follows; None (stack untouched) when it does not."""
        i = len(stack) - 1
        while i >= 0 and stack[i].kind == "ws":
            i -= 1
        if i < 0:
            if more_input:
                raise NeedMoreInput
            return None
        if stack[i].text != "(":
            return None
        open_col = stack[i].col
        del stack[i:]
        args: list[list[Tok]] = [[]]
        depth = 0
        while stack:
            tok = stack.pop()
            if tok.text == "(":
                depth += 1
            elif tok.text == ")":
                if depth == 0:
                    return [strip_ws(a) for a in args], tok
                depth -= 1
            elif tok.text == "," and depth == 0:
                args.append([])
                continue
            args[-1].append(tok)
        if more_input:
            raise NeedMoreInput
        raise MacroCallError("unterminated macro call: missing ')'", open_col)

    @staticmethod
    def _check_arity(macro: Macro, args: list[list[Tok]], col: int) -> list[list[Tok]]:
        params = macro.params or ()
        if not params and args == [[]]:
            return []
        if len(args) != len(params):
            raise MacroCallError(
                f"macro '{macro.name}' takes {len(params)} argument(s), got {len(args)}", col
            )
        return args

    def _substitute(self, macro: Macro, args: list[list[Tok]], hide: frozenset[str]) -> list[Tok]:
        """The macro body with arguments put in and `##` applied, every token hidden from `hide`."""
        params = macro.params or ()
        body = list(macro.tokens)
        result: list[Tok] = []
        for i, tok in enumerate(body):
            if tok.kind == "ident" and tok.text in params:
                arg = args[params.index(tok.text)]
                if _next_to_paste(body, i):
                    # operands of ## are pasted as written, not expanded first
                    result.extend(arg or [Tok("placeholder", "")])
                else:
                    result.extend(self.expand(list(arg)))
            else:
                result.append(tok)
        pasted = _paste(result, self._union)
        return [t._replace(hide=self._union(t.hide, hide)) for t in pasted
                if t.kind != "placeholder"]  # fmt: skip


def _next_to_paste(body: list[Tok], i: int) -> bool:
    """Whether body[i] is an operand of `##`."""
    for step in (-1, 1):
        j = i + step
        while 0 <= j < len(body) and body[j].kind == "ws":
            j += step
        if 0 <= j < len(body) and body[j].text == "##":
            return True
    return False


def _paste(tokens: list[Tok], union: Callable[[HideSet, HideSet], HideSet]) -> list[Tok]:
    """Apply the `##` operators in a substituted body."""
    out: list[Tok] = []
    i = 0
    while i < len(tokens):
        tok = tokens[i]
        if tok.text != "##" or tok.kind != "op":
            out.append(tok)
            i += 1
            continue
        while out and out[-1].kind == "ws":
            out.pop()
        left = out.pop() if out else Tok("placeholder", "")
        i += 1
        while i < len(tokens) and tokens[i].kind == "ws":
            i += 1
        right = tokens[i] if i < len(tokens) else Tok("placeholder", "")
        i += 1
        text = left.text + right.text
        merged = tokenize(text) if text else [Tok("placeholder", "")]
        hide = union(left.hide, right.hide)
        out.extend(t._replace(col=0, hide=hide) for t in merged)
    return out
