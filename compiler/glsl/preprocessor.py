"""The GLSL ES 3.00 preprocessor, with a line map back to the original source.

The output has exactly one line per input line: directives, skipped branches, comment-only
lines and lines folded into a previous one (a `\\` continuation, a macro call spread over
several lines) come out empty. So `line_map[i]` is simply where output line i+1 came from,
and everything downstream (parser, linter, glslang errors) can report the user's file:line.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from glint.compiler.errors import InputError
from glint.compiler.glsl.macros import Expander, Macro, MacroCallError, NeedMoreInput
from glint.compiler.glsl.ppexpr import ExprError, evaluate
from glint.compiler.glsl.pptokens import (
    Segment,
    Tok,
    join,
    join_expanded,
    significant,
    tokenize,
)

__all__ = ["Macro", "Preprocessed", "PreprocessorError", "SourceLocation", "preprocess"]


@dataclass(frozen=True)
class SourceLocation:
    """Where a line came from; `line` is 1-based and honours `#line`."""

    file: str
    line: int


@dataclass
class Preprocessed:
    """Preprocessor output: text for the parser and what the directives said."""

    text: str
    line_map: list[SourceLocation]  # line_map[i] is the origin of output line i+1
    defines: dict[str, Macro]  # macros still defined at the end of the source
    version: str | None = None  # e.g. "300 es"
    extensions: list[str] = field(default_factory=list)  # names from #extension
    expansions: dict[int, set[str]] = field(default_factory=dict)  # output line -> macros used
    # output line -> where the source's own tokens are on it (pptokens.Segment), for a line
    # that macros changed (one line of source: a call over several lines has none)
    columns: dict[int, list[Segment]] = field(default_factory=dict)
    # with `lenient`: the errors it went past (an undefined name in `#if`, taken as 0)
    problems: list[PreprocessorError] = field(default_factory=list)

    def locate(self, line: int) -> SourceLocation:
        """Origin of a 1-based output line (clamped, so a parser's EOF position maps too)."""
        if not self.line_map:
            return SourceLocation("<input>", 1)
        return self.line_map[min(max(line, 1), len(self.line_map)) - 1]


class PreprocessorError(InputError):
    """A preprocessing error at `file:line:column`; `line` honours `#line`, `physical_line`
    is the line of the text as given (where an editor or a fix must point)."""

    def __init__(
        self, file: str, line: int, column: int, what: str, physical_line: int | None = None
    ) -> None:
        super().__init__(f"{file}:{line}:{column}: {what}")
        self.file = file
        self.line = line
        self.column = column
        self.what = what
        self.physical_line = line if physical_line is None else physical_line


# Predefined in every ES 3.00 fragment shader (section 3.4); callers may override.
_BUILTIN_DEFINES = {"GL_ES": "1", "__VERSION__": "300", "GL_FRAGMENT_PRECISION_HIGH": "1"}

_COMMENT_START = re.compile(r"//|/\*")
# Every identifier of a line (pptokens' `ident`), and names inside numbers: a quick way to
# see that a line has no macro to expand without making its tokens.
_NAME = re.compile(r"[A-Za-z_]\w*")
_CONDITIONALS = frozenset({"if", "ifdef", "ifndef", "elif", "else", "endif"})


@dataclass
class _Branch:
    """One open #if: whether its parent is live, a branch was taken, #else was seen."""

    parent_active: bool
    taken: bool
    active: bool
    line: int
    col: int
    else_seen: bool = False
    physical_line: int = 0  # `line` ignoring #line


def preprocess(
    source: str,
    filename: str = "<input>",
    predefined: dict[str, str] | None = None,
    lenient: bool = False,
) -> Preprocessed:
    """Preprocess GLSL source; raise PreprocessorError with the position of the first problem.
    `lenient` (the linter): an undefined name in `#if` counts as 0, as in C, and is kept in
    `problems` instead of stopping, since a ShaderToy pass often tests a macro that its Common
    tab defines, and the rest of the file can still be checked."""
    return _Preprocessor(filename, predefined or {}, lenient).run(source)


class _Preprocessor:
    def __init__(self, filename: str, predefined: dict[str, str], lenient: bool = False) -> None:
        self.filename = filename
        self.lenient = lenient
        self.problems: list[PreprocessorError] = []
        self.file = filename
        self.offset = 0  # reported line = physical line + offset, moved by #line
        self.index = 0  # 0-based physical line being processed
        self.macros: dict[str, Macro] = {}
        self.branches: list[_Branch] = []
        self.version: str | None = None
        self.extensions: list[str] = []
        self.seen_content = False
        self.overridden = set(predefined)
        self.expander = Expander(self.macros, lambda: self.index + 1 + self.offset)
        for key, value in {**_BUILTIN_DEFINES, **predefined}.items():
            self._define_from_text(f"{key} {value}", "<predefined>", 0)

    # -- helpers ----------------------------------------------------------------------------

    @property
    def active(self) -> bool:
        return self.branches[-1].active if self.branches else True

    def error(self, col: int, what: str) -> PreprocessorError:
        line = self.index + 1
        return PreprocessorError(self.file, line + self.offset, max(col, 1), what, line)

    def location(self) -> SourceLocation:
        return SourceLocation(self.file, self.index + 1 + self.offset)

    # -- driver -----------------------------------------------------------------------------

    def run(self, source: str) -> Preprocessed:
        lines = self._strip_comments(_splice(source.replace("\r\n", "\n").split("\n")))
        out = [""] * len(lines)
        line_map: list[SourceLocation] = []
        expansions: dict[int, set[str]] = {}
        columns: dict[int, list[Segment]] = {}
        i = 0
        while i < len(lines):
            self.index = i
            line_map.append(self.location())
            text = lines[i]
            if text.lstrip().startswith("#"):
                self._directive(text)
                self.seen_content = True
                i += 1
                continue
            if not self.active or not text.strip():
                i += 1
                continue
            self.seen_content = True
            segments: list[Segment] = []
            consumed, out[i] = self._expand_line(lines, i, segments)
            if self.expander.used:
                expansions[i + 1] = set(self.expander.used)
                if consumed == 0:
                    columns[i + 1] = segments
            for extra in range(1, consumed + 1):  # lines folded into a multi-line macro call
                self.index = i + extra
                line_map.append(self.location())
            i += consumed + 1
        if self.branches:
            top = self.branches[-1]
            raise PreprocessorError(
                self.file, top.line, top.col, "unterminated #if: missing #endif", top.physical_line
            )
        return Preprocessed(
            text="\n".join(out),
            line_map=line_map,
            defines=dict(self.macros),
            version=self.version,
            extensions=self.extensions,
            expansions=expansions,
            columns=columns,
            problems=self.problems,
        )

    def _expand_line(
        self, lines: list[str], i: int, segments: list[Segment] | None = None
    ) -> tuple[int, str]:
        """Expand one code line, pulling in following lines while a macro call is open; where
        the source's own tokens went, in `segments`."""
        self.expander.used.clear()
        if not any(self._expandable(name) for name in _NAME.findall(lines[i])):
            return 0, lines[i]  # fast path: nothing to expand, text untouched
        tokens = tokenize(lines[i])
        if not any(t.kind == "ident" and self._expandable(t.text) for t in tokens):
            return 0, lines[i]  # a macro's name inside a number (`0x1Fu`, `2.f`)
        consumed = 0
        while True:
            nxt = i + consumed + 1
            more = nxt < len(lines) and not lines[nxt].lstrip().startswith("#")
            try:
                arguments = self._arguments(tokens) if segments is not None else frozenset()
                expanded = self.expander.expand(tokens, more_input=more)
                if segments is not None:
                    segments.clear()
                return consumed, join_expanded(expanded, segments, arguments)
            except NeedMoreInput:
                consumed += 1
                tokens = [*tokens, Tok("ws", " "), *tokenize(lines[nxt])]
                self.expander.used.clear()
            except MacroCallError as exc:
                raise self.error(exc.col, str(exc)) from None

    def _arguments(self, tokens: list[Tok]) -> frozenset[int]:
        """The columns of the tokens inside the argument lists of function-like macro calls on
        a line: they land inside an expansion, where no column of the line is theirs alone."""
        found: set[int] = set()
        sig = significant(tokens)
        i = 0
        while i < len(sig):
            tok = sig[i]
            macro = self.macros.get(tok.text) if tok.kind == "ident" else None
            called = macro is not None and macro.params is not None
            if called and i + 1 < len(sig) and sig[i + 1].text == "(":
                depth = 0
                for j in range(i + 1, len(sig)):
                    depth += {"(": 1, ")": -1}.get(sig[j].text, 0)
                    found.add(sig[j].col)
                    if depth == 0:
                        break
                i = j
            i += 1
        return frozenset(found)

    def _expandable(self, name: str) -> bool:
        return name in self.macros or name in ("__LINE__", "__FILE__")

    # -- comments ---------------------------------------------------------------------------

    def _strip_comments(self, lines: list[str]) -> list[str]:
        """Blank out comments with spaces, keeping columns and the number of lines."""
        out: list[str] = []
        open_at: tuple[int, int] | None = None  # where an unclosed /* started
        for index, line in enumerate(lines):
            parts: list[str] = []
            pos = 0
            while pos < len(line):
                if open_at is not None:
                    end = line.find("*/", pos)
                    stop = len(line) if end < 0 else end + 2
                    parts.append(" " * (stop - pos))
                    pos = stop
                    if end >= 0:
                        open_at = None
                    continue
                match = _COMMENT_START.search(line, pos)
                if match is None:
                    parts.append(line[pos:])
                    break
                parts.append(line[pos : match.start()])
                if match.group() == "//":
                    break
                open_at = (index, match.start() + 1)
                parts.append("  ")
                pos = match.end()
            out.append("".join(parts).rstrip())
        if open_at is not None:
            self.index = open_at[0]
            raise self.error(open_at[1], "unterminated comment: missing */")
        return out

    # -- directives -------------------------------------------------------------------------

    def _directive(self, text: str) -> None:
        tokens = tokenize(text)
        sig = significant(tokens)
        if len(sig) == 1:
            return  # the null directive
        name_tok = sig[1]
        name = name_tok.text
        if name in _CONDITIONALS:
            self._conditional(name, name_tok, sig[2:])
            return
        if not self.active:
            return
        rest = tokens[tokens.index(name_tok) + 1 :]
        handler = {
            "define": self._define,
            "undef": self._undef,
            "line": self._line,
            "version": self._version,
            "extension": self._extension,
            "pragma": lambda _tok, _rest: None,
            "error": self._error_directive,
        }.get(name)
        if handler is None or name_tok.kind != "ident":
            raise self.error(name_tok.col, f"unknown preprocessor directive '#{name}'")
        handler(name_tok, rest)

    def _conditional(self, name: str, tok: Tok, args: list[Tok]) -> None:
        line = self.index + 1 + self.offset
        if name in ("if", "ifdef", "ifndef"):
            parent = self.active
            cond = parent and self._condition(name, tok, args)
            self.branches.append(_Branch(parent, cond, cond, line, tok.col, False, self.index + 1))
            return
        if not self.branches:
            raise self.error(tok.col, f"#{name} without #if")
        top = self.branches[-1]
        if name == "endif":
            self.branches.pop()
            return
        if top.else_seen:
            raise self.error(tok.col, f"#{name} after #else")
        if name == "else":
            top.else_seen = True
            top.active = top.parent_active and not top.taken
        else:  # elif: only evaluated when no earlier branch was taken
            top.active = top.parent_active and not top.taken and self._condition(name, tok, args)
        top.taken = top.taken or top.active

    def _condition(self, name: str, tok: Tok, args: list[Tok]) -> bool:
        if name in ("ifdef", "ifndef"):
            if len(args) != 1 or args[0].kind != "ident":
                raise self.error(tok.col, f"#{name} expects one macro name")
            return (args[0].text in self.macros) == (name == "ifdef")
        resolved = self._resolve_defined(args, tok)

        def undefined(ident: Tok) -> None:
            what = f"#{name}: undefined macro '{ident.text}' in expression"
            self.problems.append(self.error(ident.col or tok.col, what))

        try:
            tokens = significant(self.expander.expand(resolved))
            return evaluate(tokens, undefined if self.lenient else None) != 0
        except ExprError as exc:
            raise self.error(exc.col or tok.col, f"#{name}: {exc}") from None
        except MacroCallError as exc:
            raise self.error(exc.col, str(exc)) from None

    def _resolve_defined(self, args: list[Tok], tok: Tok) -> list[Tok]:
        """Replace `defined X` and `defined(X)` by 1 or 0 before macro expansion."""
        out: list[Tok] = []
        i = 0
        while i < len(args):
            if args[i].text != "defined":
                out.append(args[i])
                i += 1
                continue
            parens = i + 1 < len(args) and args[i + 1].text == "("
            j = i + 2 if parens else i + 1
            if j >= len(args) or args[j].kind != "ident":
                raise self.error(args[i].col, "'defined' expects a macro name")
            if parens and (j + 1 >= len(args) or args[j + 1].text != ")"):
                raise self.error(args[i].col, "missing ')' after 'defined('")
            value = "1" if args[j].text in self.macros else "0"
            out.append(Tok("num", value, args[i].col))
            i = j + 2 if parens else j + 1
        return out

    def _define(self, tok: Tok, rest: list[Tok]) -> None:
        self._define_from_tokens(rest, tok.col)

    def _define_from_text(self, text: str, file: str, line: int) -> None:
        macro = self._parse_define(tokenize(text), 1, file, line)
        self.macros[macro.name] = macro

    def _define_from_tokens(self, rest: list[Tok], col: int) -> None:
        loc = self.location()
        macro = self._parse_define(rest, col, loc.file, loc.line)
        self._check_name(macro.name, col, "#define")
        old = self.macros.get(macro.name)
        if old is not None and (old.params, old.body) != (macro.params, macro.body):
            raise self.error(col, f"macro '{macro.name}' redefined with a different body")
        self.macros[macro.name] = macro

    def _parse_define(self, rest: list[Tok], col: int, file: str, line: int) -> Macro:
        i = 0
        while i < len(rest) and rest[i].kind == "ws":
            i += 1
        if i >= len(rest) or rest[i].kind != "ident":
            raise self.error(col, "#define expects a macro name")
        name = rest[i].text
        i += 1
        params: tuple[str, ...] | None = None
        if i < len(rest) and rest[i].text == "(":  # no space before '(': function-like
            params, i = self._parse_params(rest, i + 1, col)
        return Macro.make(name, params, join(rest[i:]), file, line)

    def _parse_params(self, rest: list[Tok], i: int, col: int) -> tuple[tuple[str, ...], int]:
        names: list[str] = []
        sig = [(k, t) for k, t in enumerate(rest) if k >= i and t.kind != "ws"]
        expect_name = True
        for k, t in sig:
            if t.text == ")" and (not expect_name or not names):
                return tuple(names), k + 1
            if expect_name and t.kind == "ident" and t.text not in names:
                names.append(t.text)
                expect_name = False
            elif not expect_name and t.text == ",":
                expect_name = True
            else:
                raise self.error(t.col, f"bad macro parameter list at '{t.text}'")
        raise self.error(col, "macro parameter list is missing ')'")

    def _check_name(self, name: str, col: int, what: str) -> None:
        if name.startswith("GL_") or name == "defined":
            raise self.error(col, f"{what}: the name '{name}' is reserved")

    def _undef(self, tok: Tok, rest: list[Tok]) -> None:
        sig = significant(rest)
        if len(sig) != 1 or sig[0].kind != "ident":
            raise self.error(tok.col, "#undef expects one macro name")
        self._check_name(sig[0].text, sig[0].col, "#undef")
        self.macros.pop(sig[0].text, None)

    def _line(self, tok: Tok, rest: list[Tok]) -> None:
        try:
            sig = significant(self.expander.expand(rest))
        except MacroCallError as exc:  # `#line F(` must be an error, not a crash
            raise self.error(exc.col, str(exc)) from None
        if not sig or sig[0].kind != "num" or not sig[0].text.isdigit():
            raise self.error(tok.col, "#line expects a line number")
        source = join(sig[1:]).strip()
        if source.startswith('"') and source.endswith('"') and len(source) >= 2:
            self.file = source[1:-1]
        elif source.isdigit():
            self.file = source
        elif source:
            raise self.error(sig[1].col or tok.col, f"bad source name '{source}' in #line")
        # the line after the directive gets the given number
        self.offset = int(sig[0].text) - (self.index + 2)

    def _version(self, tok: Tok, rest: list[Tok]) -> None:
        if self.seen_content or self.version is not None:
            raise self.error(tok.col, "#version must come first, before anything but comments")
        sig = significant(rest)
        if not sig or sig[0].kind != "num":
            raise self.error(tok.col, "#version expects a version number")
        self.version = " ".join(t.text for t in sig)
        if "__VERSION__" not in self.overridden:  # a caller's value wins over the directive
            self.macros["__VERSION__"] = Macro.make(
                "__VERSION__", None, sig[0].text, "<predefined>", 0
            )

    def _extension(self, tok: Tok, rest: list[Tok]) -> None:
        sig = significant(rest)
        if len(sig) != 3 or sig[0].kind != "ident" or sig[1].text != ":":
            raise self.error(tok.col, "#extension expects 'name : behavior'")
        if sig[2].text not in ("require", "enable", "warn", "disable"):
            raise self.error(sig[2].col, f"unknown #extension behavior '{sig[2].text}'")
        self.extensions.append(sig[0].text)

    def _error_directive(self, tok: Tok, rest: list[Tok]) -> None:
        raise self.error(tok.col, f"#error {join(rest).strip()}".rstrip())


def _splice(lines: list[str]) -> list[str]:
    """Join `\\`-continued lines onto their first line, leaving empty lines in their place."""
    out: list[str] = []
    i = 0
    while i < len(lines):
        text = lines[i]
        extra = 0
        while text.endswith("\\"):
            text = text[:-1]
            if i + extra + 1 >= len(lines):
                break
            extra += 1
            text += lines[i + extra]
        out.append(text)
        out.extend([""] * extra)
        i += extra + 1
    return out
