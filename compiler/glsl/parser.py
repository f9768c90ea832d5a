"""Parse preprocessed GLSL ES 3.00 into a lark tree with positions on every node.

Tree positions (`tree.meta.line`, token `.line`) are lines of the *preprocessed* text; map them
to the user's file with `Preprocessed.locate`. `parse_source` does both steps and reports
syntax errors at the original file:line.

`parse` runs lark's parser through `_FastParser`, which builds the same tree in half the time;
where it finds an error, lark itself parses again and reports it.
"""

from __future__ import annotations

import contextlib
import functools
import hashlib
import operator
import os
import re
import sys
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path

from lark import Lark, Token, Tree
from lark import __version__ as lark_version
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken
from lark.grammar import Rule
from lark.lark import _LOAD_ALLOWED_OPTIONS as _LOAD_OPTIONS
from lark.lark import PostLex
from lark.parsers.lalr_analysis import Shift
from lark.tree import Meta

from glint.compiler.collector import paused
from glint.compiler.errors import InputError
from glint.compiler.glsl.keywords import BUILTIN_TYPES, QUALIFIER_GROUPS, RESERVED_WORDS, words
from glint.compiler.glsl.preprocessor import Preprocessed, preprocess

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
    a declaration (`S x;`) from an expression (`a * b;`). See `_Retyper`."""

    always_accept = ()

    def process(self, stream: Iterator[Token]) -> Iterator[Token]:
        # The retyper looks ahead, so it takes the whole token list; a lexer error is raised
        # after the tokens before it, where the parser would have met it.
        tokens: list[Token] = []
        error: UnexpectedInput | None = None
        try:
            tokens.extend(stream)
        except UnexpectedInput as exc:
            error = exc
        retyper = _Retyper(tokens)
        for index, tok in enumerate(tokens):
            retyper.retype(index, tok)
            yield tok
        if error is not None:
            raise error


# How far to look past an unknown name's `[...]` for the identifier that makes it a type.
_MAX_LOOKAHEAD = 256


class _Frame:
    """One scope: a `{...}` block, a struct body (`members`), or a `(...)` (`params` when it
    is a function's parameter list). `names` maps a name to True for a type, False for
    anything else declared there."""

    __slots__ = ("kind", "names")

    def __init__(self, kind: str, names: dict[str, bool] | None = None) -> None:
        self.kind = kind
        self.names = names if names is not None else {}


class _Retyper:
    """The lexer side of the typedef-name problem, as glslang's scanner does it.

    An identifier is a TYPE_NAME when a struct of that name is in scope and no variable,
    parameter or local struct of an inner scope hides it. Scopes follow `{}` and `()`:
    parameters (and `for (T i ...)` variables) live in the parenthesis frame and carry over
    into the `{` that follows it. A declared name is in scope after its declarator ends (at
    the `,` or `;`), so `ray ray = ray(o, d);` still constructs with the type.

    Where a name must be a declarator, it stays an IDENTIFIER whatever it names: right after
    a type (`ray ray;`, also as a struct member), after `struct`, after `.` (a field), and
    after the `,` of a declarator list. Struct members are not declared anywhere.

    A name declared nowhere in this source (a struct from another snippet or from ShaderToy's
    Common tab) is a type where only a type can be: before another identifier (`Material m`),
    before `[...]` and an identifier (`Material[2] ms`), at the start of a parameter (also
    an unnamed one) or of a struct member. It is then remembered as a global type.

    `retype` is called for each token of `tokens` in order (it looks ahead in the list)."""

    def __init__(self, tokens: list[Token]) -> None:
        self.tokens = tokens
        self.ahead = 0  # index of the token after the one being retyped
        self.frames: list[_Frame] = [_Frame("block")]
        self.prev: Token | None = None
        self.after_type = False  # the next identifier, outside brackets, is a declarator
        self.after_struct = False
        self.field = False  # after `.`
        self.brackets = 0  # `[` depth: inside an array size no declarator starts
        self.pending: tuple[Token, int] | None = None  # declarator name, its paren depth
        self.decl_list: int | None = None  # paren depth of a declarator list's commas
        self.next_declarator = False  # after such a comma
        self.starts_item = False  # at the start of a parameter or a struct member
        self.carried: dict[str, bool] | None = None  # names of a `(...)` just closed
        self.parens = 0

    def retype(self, index: int, tok: Token) -> None:
        """Retype `tok`, the token at `index`; raises _ReservedWord for a reserved word."""
        self.ahead = index + 1
        if tok.type == "IDENTIFIER":
            self._identifier(tok)
        else:
            self._other(tok)
        self.prev = tok

    def _peek(self, index: int) -> Token | None:
        """The token `index` places after the one being retyped, None past the end."""
        index += self.ahead
        return self.tokens[index] if index < len(self.tokens) else None

    # -- scopes -----------------------------------------------------------------------------

    def _lookup(self, name: str) -> bool | None:
        """True for a type in scope, False for something else, None when never declared."""
        for frame in reversed(self.frames):
            kind = frame.names.get(name)
            if kind is not None:
                return kind
        return None

    def _declare(self, name: str, is_type: bool) -> None:
        frame = self.frames[-1]
        if frame.kind != "members":
            frame.names[name] = is_type

    def _end_declarator(self) -> None:
        """A `,`, `;` or `)` at the declarator's depth ends it: its name is now in scope."""
        if self.pending is not None and self.pending[1] == self.parens:
            self._declare(self.pending[0].value, False)
            self.pending = None

    # -- identifiers ------------------------------------------------------------------------

    def _identifier(self, tok: Token) -> None:
        text = tok.value
        starts_item, self.starts_item = self.starts_item, False
        next_declarator, self.next_declarator = self.next_declarator, False
        if text in BUILTIN_TYPES:
            tok.type = "BUILTIN_TYPE"
            self.after_type = True
            return
        if text in QUALIFIER_GROUPS:
            tok.type = QUALIFIER_GROUPS[text]
            self.starts_item = starts_item  # qualifiers come before the type
            return
        if text in RESERVED_WORDS:  # a name with `__` is only a warning in ES 3.00 (§3.7)
            raise _ReservedWord(tok)
        if self.field:
            self.field = False
            return
        if self.after_struct:
            self.after_struct = False
            self._declare(text, True)
            return
        if (self.after_type or next_declarator) and self.brackets == 0:
            self.after_type = False
            self.pending = (tok, self.parens)
            if self.frames[-1].kind != "params":
                self.decl_list = self.parens
            return
        known = self._lookup(text)
        if known or (known is None and (starts_item or self._looks_like_type())):
            tok.type = "TYPE_NAME"
            self.after_type = True
            if known is None:
                self.frames[0].names[text] = True

    def _looks_like_type(self) -> bool:
        """`T x`, `T[2] x`, `T[] x`: no expression has a name (or `[...]`) before a name."""
        index = 0
        tok = self._peek(0)
        while tok is not None and tok.type == "LSQB" and index < _MAX_LOOKAHEAD:
            depth = 0
            while tok is not None and index < _MAX_LOOKAHEAD:
                depth += {"LSQB": 1, "RSQB": -1}.get(tok.type, 0)
                index += 1
                if depth == 0:
                    break
                tok = self._peek(index)
            tok = self._peek(index)
        return _is_plain_identifier(tok)

    # -- everything else --------------------------------------------------------------------

    def _other(self, tok: Token) -> None:
        kind = tok.type
        self.field = kind == "DOT"
        self.after_struct = kind == "STRUCT"
        self.next_declarator = False
        self.starts_item = False
        if kind in ("SEMICOLON", "COMMA", "ASSIGN", "LPAR", "RPAR"):
            self.after_type = False
        if kind == "SEMICOLON":
            self._end_declarator()
            if self.decl_list == self.parens:
                self.decl_list = None
            self.starts_item = self.frames[-1].kind == "members"
        elif kind == "COMMA":
            self._end_declarator()
            if self.frames[-1].kind == "params":
                self.starts_item = True
            elif self.decl_list == self.parens and self.brackets == 0:
                self.next_declarator = True
        elif kind == "LPAR":
            function = self.pending is not None and self.prev is self.pending[0]
            if function:  # `T name(`: a function's parameter list; the name is not a variable
                self.pending = None
                self.decl_list = None
            self.parens += 1
            self.frames.append(_Frame("params" if function else "parens"))
            self.starts_item = function
        elif kind == "RPAR":
            self._end_declarator()
            if self.parens > 0 and len(self.frames) > 1:
                self.parens -= 1
                frame = self.frames.pop()
                self.carried = frame.names or None
        elif kind == "LBRACE":
            prev = self.prev.type if self.prev is not None else ""
            if prev in ("IDENTIFIER", "STRUCT"):  # a struct body or an interface block
                self.frames.append(_Frame("members"))
                self.starts_item = True
            else:
                names = dict(self.carried) if prev == "RPAR" and self.carried else None
                self.frames.append(_Frame("block", names))
            self.after_type = False
            self.pending = None
            self.decl_list = None
        elif kind == "RBRACE":
            if len(self.frames) > 1:
                frame = self.frames.pop()
                self.after_type = frame.kind == "members"  # `struct S { ... } s;`
            self.pending = None
            self.decl_list = None
        elif kind == "LSQB":
            self.brackets += 1
        elif kind == "RSQB":
            self.brackets = max(self.brackets - 1, 0)


def _is_plain_identifier(tok: Token | None) -> bool:
    return (
        tok is not None
        and tok.type == "IDENTIFIER"
        and tok.value not in BUILTIN_TYPES
        and tok.value not in QUALIFIER_GROUPS
    )


# Binding strength of the binary operators (GLSL ES 3.00 §5.1), loosest first; all of them
# associate to the left.
_PRECEDENCE = {
    "OR_OP": 1, "XOR_OP": 2, "AND_OP": 3, "BIT_OR": 4, "BIT_XOR": 5, "BIT_AND": 6,
    "EQ_OP": 7, "NE_OP": 7, "LT_OP": 8, "GT_OP": 8, "LE_OP": 8, "GE_OP": 8,
    "LEFT_OP": 9, "RIGHT_OP": 9, "PLUS": 10, "MINUS": 10, "STAR": 11, "SLASH": 11, "PERCENT": 11,
}  # fmt: skip


class _Shape:
    """Callbacks the parser runs as it reduces, in place of building a plain tree node (lark
    calls the method named like the rule; other rules build a `Tree`)."""

    def binary_chain(self, items: list[Tree | Token]) -> Tree:
        """`a op b op c ...` nested by precedence (shunting-yard) into `binary` nodes, the
        tree a grammar with one rule per precedence level gives, positions included."""
        operands: list[Tree | Token] = [items[0]]
        operators: list[Token] = []
        for index in range(1, len(items), 2):
            op = items[index]
            strength = _PRECEDENCE[op.type]  # type: ignore[union-attr]
            while operators and _PRECEDENCE[operators[-1].type] >= strength:
                _nest(operands, operators)
            operators.append(op)  # type: ignore[arg-type]
            operands.append(items[index + 1])
        while operators:
            _nest(operands, operators)
        return operands[0]  # type: ignore[return-value]

    def for_statement(self, items: list[Tree | Token]) -> Tree:
        """`for (init cond? ; update?) body` as [init, cond?, update?, body], the children
        lark gives, with `meta.for_parts` saying which optional parts are there: the `;`
        between them (kept by the grammar for this) is where the condition ends."""
        semicolon = next(
            i
            for i, item in enumerate(items)
            if isinstance(item, Token) and item.type == "SEMICOLON"
        )
        node = Tree("for_statement", items[:semicolon] + items[semicolon + 1 :], Meta())
        node.meta.for_parts = (semicolon == 2, len(items) - semicolon == 3)  # type: ignore[attr-defined]
        return node


def _nest(operands: list[Tree | Token], operators: list[Token]) -> None:
    """Replace the last two operands by their `binary` node, with the positions lark's
    propagate_positions gives a node: from its first child's container (a parenthesised
    operand starts at its `(`) to its last child's."""
    right, left = operands.pop(), operands.pop()
    node = Tree("binary", [left, operators.pop(), right])
    meta, first, last = node.meta, _position(left), _position(right)
    meta.line = meta.container_line = getattr(first, "container_line", first.line)
    meta.column = meta.container_column = getattr(first, "container_column", first.column)
    meta.start_pos = meta.container_start_pos = getattr(
        first, "container_start_pos", first.start_pos
    )
    meta.end_line = meta.container_end_line = getattr(last, "container_end_line", last.end_line)
    meta.end_column = meta.container_end_column = getattr(
        last, "container_end_column", last.end_column
    )
    meta.end_pos = meta.container_end_pos = getattr(last, "container_end_pos", last.end_pos)
    meta.empty = False
    operands.append(node)


def _position(node: Tree | Token) -> object:
    return node.meta if isinstance(node, Tree) else node


@functools.cache
def glsl_parser() -> Lark:
    """The LALR parser, built once per process (building it takes a while)."""
    parser = _lark()
    _pass_unit_rules_through(parser)
    return parser


def _lark() -> Lark:
    """The parser from the tables cached by an earlier process, else built (about 80 ms: most
    of a one-file `glint lint`) and cached. lark's own `cache=` cannot serve: it hashes the
    options' text, and the tree class's text holds its address, new in every process."""
    grammar = _GRAMMAR.read_text(encoding="utf-8")
    # what is not in the tables, given again on loading (as lark's own cache does)
    given = {
        "postlex": _TypeNamePostLex(),
        "transformer": _Shape(),
        "tree_class": _tree,
        "propagate_positions": True,
    }
    cached = _table_cache(grammar)
    if cached is not None and cached.is_file():
        try:
            with cached.open("rb") as f:
                return Lark.__new__(Lark)._load(f, **given)
        except Exception:  # noqa: BLE001 - a stale or damaged cache: build anew
            pass
    parser = Lark(grammar, parser="lalr", lexer="basic", maybe_placeholders=False, **given)
    if cached is not None:
        _save_tables(parser, cached)
    return parser


def _table_cache(grammar: str) -> Path | None:
    """Where the parser's tables are cached: the user's cache folder (never a shared temporary
    one: the file is a pickle), named by what the tables depend on."""
    try:
        base = os.environ.get("XDG_CACHE_HOME") or (Path.home() / ".cache")
    except (RuntimeError, KeyError):  # no home to find (a bare container): no cache
        return None
    key = f"{grammar}\0{lark_version}\0{sys.version_info[:2]}\0{sys.implementation.name}"
    digest = hashlib.sha256(key.encode("utf-8")).hexdigest()[:24]
    return Path(base) / "glint" / f"glsl-parser-{digest}.pickle"


def _save_tables(parser: Lark, path: Path) -> None:
    """Write the tables (atomically: a parallel process never reads half a file); a folder
    that cannot be written only means building them again next time."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=path.parent, delete=False) as f:
            parser.save(f, exclude_options=_LOAD_OPTIONS)
        os.replace(f.name, path)
    except OSError:
        with contextlib.suppress(OSError, UnboundLocalError):
            os.unlink(f.name)


def _tree(data: str, children: list[Tree | Token], meta: object = None) -> Tree:
    """A tree node named by a plain string: lark names nodes with a Token, whose `==` runs in
    Python, and the analyses compare `node.data` millions of times."""
    return Tree(str(data), children, meta)  # type: ignore[arg-type]


def _pass_unit_rules_through(parser: Lark) -> None:
    """Make the reductions of unit rules (`?statement: simple_statement`, `?type_name:
    BUILTIN_TYPE`) hand their one child on untouched.

    lark already returns that child, but only after its tree-building wrappers have looked
    at it: a third of the parse went there. The child keeps the positions it has, so the
    tree is the same (tests/glsl/test_parser_shortcuts.py compares). lark has no option for
    this; its LALR parser's table of callbacks is replaced where it is found, and where lark
    keeps it elsewhere the parser stays as it is, only slower."""
    callbacks = getattr(getattr(getattr(parser, "parser", None), "parser", None), "parser", None)
    table = getattr(callbacks, "callbacks", None)
    if not isinstance(table, dict):
        return
    for rule in table:
        if _is_unit_rule(rule):
            table[rule] = operator.itemgetter(0)


def _is_unit_rule(rule: Rule) -> bool:
    """A `?rule: symbol` alternative that hands its one child on as it is."""
    options = getattr(rule, "options", None)
    if rule.alias or options is None or not options.expand1 or len(rule.expansion) != 1:
        return False
    symbol = rule.expansion[0]
    # inlined into its parent, or a token lark drops: not one child
    return not (symbol.name.startswith("_") or getattr(symbol, "filter_out", False))


# A value on the parser's stack, and what a reduction does with the values it pops.
_Value = Tree | Token
_Build = Callable[[list[_Value]], _Value]


class _FastParser:
    """The parser of `glsl_parser()` without lark's machinery around it: the same terminals,
    LALR table, rules and tree shaping, run by one tight loop each (lexing, `_Retyper`, LALR).

    lark spends most of a parse in its generality: a generator per token, three wrapper calls
    per reduction (child filter, single-child expansion, position propagation), `getattr`
    with defaults for every position. Here each rule gets one closure (`_builder`) doing
    what those wrappers do, and unit rules (`_is_unit_rule`) only change the parser state.

    `parse` returns None where it cannot parse; `parse()` then runs lark itself, which
    raises the error with all its details (errors are rare, so they may be slow).
    tests/glsl/test_fast_parser.py checks the trees against plain lark's, positions included.
    """

    def __init__(self, lark: Lark) -> None:
        options = lark.options
        if options.propagate_positions is not True or options.maybe_placeholders:
            raise TypeError("the fast parser builds trees as `_lark()` has lark build them")
        lexer = lark.parser.lexer.lexer  # lark's BasicLexer, under the postlexer
        terminals = lexer.scanner.terminals  # in lark's order: the first that matches wins
        self._scan = re.compile(
            "|".join(f"(?P<{t.name}>{t.pattern.to_regexp()})" for t in terminals),
            lexer.g_regex_flags,
        ).finditer
        self._ignore: frozenset[str] = lexer.ignore_types
        self._newlines: frozenset[str] = lexer.newline_types
        # lark retypes a terminal's match that is one of the keywords it hides (IDENTIFIER
        # `if` is IF) with a second regex; a literal keyword is a dict lookup
        self._keywords: dict[str, dict[str, str]] = {}
        for name, callback in lexer.callback.items():
            words = callback.scanner.terminals
            if not all(w.pattern.type == "str" and not w.pattern.flags for w in words):
                raise TypeError(f"lexer callback for {name} is not keywords")
            self._keywords[name] = {w.pattern.value: w.name for w in words}

        parser = lark.parser.parser.parser
        table = parser.parse_table
        self._start: int = table.start_states["start"]
        self._end: int = table.end_states["start"]
        shape = lark.options.transformer
        reductions = {rule: (len(rule.expansion), str(rule.origin.name), _builder(rule, shape))
                      for rule in parser.callbacks}  # fmt: skip
        # per state: terminal -> the state to shift to, or (size, rule name, build) to
        # reduce by; rule name -> the state to go to after that reduction. lark names rules
        # with Tokens, whose `==` runs in Python: the keys are plain strings.
        self._table: list[dict[str, int | tuple[int, str, _Build | None]]] = [
            {} for _ in range(max(table.states) + 1)
        ]
        self._units: dict[tuple[int, str, str], int] = {}
        for state, actions in table.states.items():
            for symbol, (action, arg) in actions.items():
                self._table[state][str(symbol)] = arg if action is Shift else reductions[arg]

    def parse(self, text: str) -> Tree | None:
        """The tree lark gives for `text`, or None where lark raises an error."""
        with paused():
            tokens = self._lex(text)
            if tokens is None:
                return None
            retyper = _Retyper(tokens)
            try:
                for index, tok in enumerate(tokens):
                    retyper.retype(index, tok)
            except _ReservedWord:
                return None
            return self._run(tokens)

    def _lex(self, text: str) -> list[Token] | None:
        """lark's basic lexer: the same matches, types and positions."""
        ignore, newlines, keywords = self._ignore, self._newlines, self._keywords
        # `Token(...)` checks its keyword arguments for a deprecated name, then calls this
        new_token = getattr(Token, "_future_new", Token)
        tokens: list[Token] = []
        line, line_start, pos = 1, 0, 0
        for match in self._scan(text):
            start = match.start()
            if start != pos:
                return None  # a character no terminal matches
            kind, value, pos = match.lastgroup, match.group(), match.end()
            first_line, column = line, start - line_start + 1
            if kind in newlines:
                count = value.count("\n")
                if count:
                    line += count
                    line_start = start + value.rindex("\n") + 1
            if kind in ignore:
                continue
            if kind in keywords:
                kind = keywords[kind].get(value, kind)
            tokens.append(
                new_token(kind, value, start, first_line, column, line, pos - line_start + 1, pos)
            )
        return tokens if pos == len(text) else None

    def _run(self, tokens: list[Token]) -> Tree | None:
        """lark's LALR loop (`ParserState.feed_token`) over the tokens and `$END`."""
        table, end, units = self._table, self._end, self._units
        states = [self._start]
        values: list[_Value] = []
        for kind, tok in [(t.type, t) for t in tokens] + [("$END", None)]:
            while True:
                action = table[states[-1]].get(kind)
                if action is None:
                    return None
                if action.__class__ is int:
                    if tok is None:
                        return None  # lark does not shift `$END`
                    states.append(action)  # type: ignore[arg-type]
                    values.append(tok)
                    break
                size, origin, build = action  # type: ignore[misc]
                if build is None:  # unit rules: the child stays the value, the state changes
                    key = (states[-2], origin, kind)
                    state = units.get(key)
                    if state is None:
                        state = units[key] = self._after_units(*key)
                    states[-1] = state
                else:
                    if size:
                        children = values[-size:]
                        del values[-size:]
                        del states[-size:]
                    else:
                        children = []
                    values.append(build(children))
                    states.append(table[states[-1]][origin])  # type: ignore[arg-type]
                if tok is None and states[-1] == end:
                    return values[-1]  # type: ignore[return-value]
        return None

    def _after_units(self, below: int, origin: str, kind: str) -> int:
        """The state after a unit rule's reduction to `origin` over state `below`, and after
        the unit reductions that follow it at the lookahead `kind`. Unit reductions only
        replace the top state, so that depends on these three alone: `_units` caches it."""
        state = self._table[below][origin]
        while state != self._end:
            action = self._table[state].get(kind)
            if action.__class__ is int or action is None or action[2] is not None:  # type: ignore[index]
                break
            state = self._table[below][action[1]]  # type: ignore[index,assignment]
        return state  # type: ignore[return-value]


def _builder(rule: Rule, shape: object) -> _Build | None:
    """What lark's tree builder does for a reduction by `rule` (None for a unit rule):
    drop filtered tokens, splice in the children of inlined `_rules`, hand on a single child
    of a `?rule`, call the transformer's method or build a `Tree`, and propagate positions
    (`PropagatePositions`: a node spans from its first child's container to its last's)."""
    if _is_unit_rule(rule):
        return None
    options = rule.options
    name = str(rule.alias or options.template_source or rule.origin.name)
    make: Callable[[list[_Value]], _Value] | None = getattr(shape, name, None)
    expand1 = options.expand1 and not rule.alias
    keep = _keeper(rule)
    if not expand1 and make is None:  # most rules: always a new node

        def build_node(children: list[_Value]) -> _Value:
            meta = Meta()
            _propagate(meta, children, True)
            return Tree(name, children if keep is None else keep(children), meta)

        return build_node

    def build(children: list[_Value]) -> _Value:
        nodes = children if keep is None else keep(children)
        if expand1 and len(nodes) == 1:
            node = nodes[0]
        elif make is not None:
            node = make(nodes)
        else:
            node = Tree(name, nodes, Meta())
        if isinstance(node, Tree):
            _propagate(node.meta, children, not hasattr(node.meta, "line"))
        return node

    return build


def _keeper(rule: Rule) -> Callable[[list[_Value]], list[_Value]] | None:
    """lark's child filter for `rule`: the children a node keeps (None: all of them), the
    tokens it drops left out and the children of inlined `_rules` spliced in."""
    include = [
        (index, not symbol.is_term and symbol.name.startswith("_"))
        for index, symbol in enumerate(rule.expansion)
        if rule.options.keep_all_tokens or not (symbol.is_term and symbol.filter_out)
    ]
    if len(include) == len(rule.expansion) and not any(inline for _, inline in include):
        return None

    def keep(children: list[_Value]) -> list[_Value]:
        kept: list[_Value] = []
        for index, inline in include:
            if not inline:
                kept.append(children[index])
            elif kept:
                kept += children[index].children  # type: ignore[union-attr]
            else:  # lark's shortcut for left recursion: reuse the list
                kept = children[index].children  # type: ignore[union-attr]
        return kept

    return keep


def _propagate(meta: Meta, children: list[_Value], new: bool) -> None:
    """lark's `PropagatePositions`, on a `new` node or on one handed on (which keeps its
    own span, and only takes the container's). Every non-empty node's meta has container
    positions (this function or `_nest` set them): they are read without `getattr` defaults."""
    for child in children:
        if isinstance(child, Token):
            line, column, start_pos = child.line, child.column, child.start_pos
            break
        first = child.meta
        if not first.empty:
            line, column = first.container_line, first.container_column
            start_pos = first.container_start_pos
            break
    else:
        return  # no child takes up space: neither does the node
    for child in reversed(children):
        if isinstance(child, Token):
            end_line, end_column, end_pos = child.end_line, child.end_column, child.end_pos
            break
        last = child.meta
        if not last.empty:
            end_line, end_column = last.container_end_line, last.container_end_column
            end_pos = last.container_end_pos
            break
    if new:
        meta.line, meta.column, meta.start_pos = line, column, start_pos
        meta.end_line, meta.end_column, meta.end_pos = end_line, end_column, end_pos
        meta.empty = False
    meta.container_line, meta.container_column = line, column
    meta.container_start_pos = start_pos
    meta.container_end_line, meta.container_end_column = end_line, end_column
    meta.container_end_pos = end_pos


@functools.cache
def _fast_parser() -> _FastParser | None:
    """The fast parser, or None where this lark keeps its parts elsewhere than 1.x does."""
    try:
        return _FastParser(glsl_parser())
    except (AttributeError, KeyError, TypeError):
        return None


def prepare_parser() -> None:
    """Build the parser's tables now rather than at the first parse (worker processes forked
    afterwards share them instead of each building its own)."""
    _fast_parser()


def parse(text: str, filename: str = "<input>") -> Tree:
    """Parse preprocessed GLSL; raise GLSLSyntaxError with the position in `text`."""
    fast = _fast_parser()
    tree = fast.parse(text) if fast is not None else None
    if tree is not None:
        return tree
    try:  # lark itself: the tree where the fast parser has none, else the error's details
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
