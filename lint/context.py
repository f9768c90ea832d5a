"""A file being linted: its text as written, the preprocessed text, the parse tree and the
helpers rules use to turn tree nodes into spans, findings and edits of the user's file."""

from __future__ import annotations

from bisect import bisect_left
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import cached_property
from itertools import islice
from operator import itemgetter
from typing import Any, TypeVar

from lark import Token, Tree

from glint.compiler.errors import InputError
from glint.compiler.glsl import Preprocessed
from glint.compiler.glsl.ast import Variable, first_child
from glint.compiler.glsl.binder import Bindings, bind
from glint.compiler.glsl.pptokens import Segment
from glint.compiler.target.glslang import Diagnostic, validate
from glint.compiler.target.shadertoy import Tab, shadertoy_types

from .finding import Certainty, Edit, Finding, Fix, Severity
from .nesting import Nesting

Node = Tree | Token
Span = tuple[int, int, int, int]  # line, column, end line, end column (1-based, end exclusive)
_T = TypeVar("_T")

# glslang's diagnostics computed ahead for many files with one process (lint/parallel.py, with
# `validate_many`), by (file, target, text, tab): `LintContext.glslang` takes them from here
# rather than running glslangValidator for the file. Keyed by the text itself, so a text that
# differs (a fix applied to it) is validated afresh.
GlslangKey = tuple[str, str, str, Tab]
_PRECOMPUTED: dict[GlslangKey, list[Diagnostic]] = {}


@contextmanager
def precomputed_glslang(results: Mapping[GlslangKey, list[Diagnostic]]) -> Iterator[None]:
    """Within the block, contexts of these (file, target, text, tab) use these diagnostics."""
    _PRECOMPUTED.update(results)
    try:
        yield
    finally:
        for key in results:
            _PRECOMPUTED.pop(key, None)


@dataclass
class LintContext:
    file: str
    text: str  # as the user wrote it
    target: str = "shadertoy"  # shadertoy, webgl2 or desktop
    tab: Tab = field(default_factory=Tab)  # the Common tab in front, the channels' types
    # Lines of the Common tab's code in front of the file's own in `pre` and `tree`: a node on
    # those lines lies outside the file (its span's line is 0 or less).
    line_offset: int = 0
    pre: Preprocessed | None = None  # None when preprocessing failed
    tree: Tree | None = None  # None when the file did not parse
    use_glslang: bool = True
    reports_glslang_errors: bool = True  # C001 is selected for this file (when glslang runs)
    front_end_error: InputError | None = None  # why preprocessing or parsing failed
    read_problem: str = ""  # why the file's bytes are not text to lint
    too_deep: bool = False  # nesting beyond what the analysis can follow
    nesting: Nesting = field(default_factory=Nesting)  # how deep it nests (lint/nesting.py)
    lines: list[str] = field(default_factory=list)
    # Analyses computed once per file and shared by rules (the semantic model, the data flow,
    # ...), keyed by the function that computes them: see `memo`.
    _memo: dict[Callable[..., Any], Any] = field(default_factory=dict)
    _pre_lines: list[str] | None = None  # `pre`'s lines, split when a column map needs them
    _glslang: list[Diagnostic] | None = None
    _index: dict[str, list[Tree]] | None = None
    _all_kinds: bool = False  # whether `_index` holds every kind (the tree is not indexed)
    _parents: dict[int, Tree] | None = None

    def __post_init__(self) -> None:
        if not self.lines:
            self.lines = self.text.split("\n")

    def glslang(self) -> list[Diagnostic]:
        """glslangValidator's diagnostics on the file as the target wraps it (run once)."""
        if self._glslang is None:
            known = _PRECOMPUTED.get((self.file, self.target, self.text, self.tab))
            if known is not None:
                self._glslang = known
            elif self.text:
                # at the file's own lines, not where `// source:` markers point
                self._glslang = validate(self.text, self.file, self.target, self.tab, False)
            else:
                self._glslang = []
        return self._glslang

    @cached_property
    def bindings(self) -> Bindings:
        """The binder's results for the file (compiler/glsl/binder.py): scopes, symbols, what
        each name means, the call graph, per-function summaries. Only for a parsed file."""
        if self.tree is None:
            raise ValueError("bindings need a parsed file")
        return bind(self.tree, shadertoy_types(self.tab.channels))

    def memo(self, compute: Callable[[LintContext], _T]) -> _T:
        """`compute(self)`, computed once per file: an analysis rules share, keyed by the
        function that computes it (so its result keeps that function's type)."""
        if compute in self._memo:
            return self._memo[compute]  # type: ignore[no-any-return]
        found = self._memo[compute] = compute(self)
        return found

    def nodes(self, kind: str) -> list[Tree]:
        """Every subtree of this kind (`call`, `variable`, ...), in source order. The tree is
        walked once per file for all rules, which would otherwise each walk it again."""
        if self.tree is None:
            return []
        if self._index is None:
            self._index = {}
            if _index_of(self.tree) is None:
                for node in _walk(self.tree):
                    self._index.setdefault(node.data, []).append(node)
                self._all_kinds = True
        found = self._index.get(kind)
        if found is None:
            # Indexed (an `indexed` block): each kind is sliced from the index when asked for.
            found = [] if self._all_kinds else walk_kind(self.tree, kind)
            self._index[kind] = found
        return found

    def parents(self) -> dict[int, Tree]:
        """The parent of every subtree and token of the file, by id() (lark nodes hash by
        value, not identity); built once per file for all rules. Empty without a tree."""
        if self._parents is None:
            nodes = walk(self.tree) if self.tree is not None else ()
            self._parents = {id(child): node for node in nodes for child in node.children}
        return self._parents

    # --- positions ------------------------------------------------------------------------

    def span(self, node: Node) -> Span:
        """The node's span in the user's file. Tree positions are lines of the preprocessed
        text; the line map takes them back, and on a line that macros changed the columns of
        the user's own tokens do (a node made by a macro spans the macro's name and arguments)."""
        if isinstance(node, Token):
            line, col = node.line or 1, node.column or 1
            end_line, end_col = node.end_line or line, node.end_column or col + len(node)
        else:
            meta = node.meta
            if meta.empty:
                return (1, 1, 1, 1)
            line, col, end_line, end_col = meta.line, meta.column, meta.end_line, meta.end_column
        col = self._source_column(line, col, end=False)[0]
        end_col = self._source_column(end_line, end_col, end=True)[0]
        first, last = self._origin(line), self._origin(end_line)
        # a line spliced with `\` or a macro call over several lines makes one long
        # preprocessed line: keep the columns on the user's line
        col = min(col, self._width(first))
        end_col = min(end_col, self._width(last))
        if last == first and end_col < col:
            end_col = col
        return (first, col, last, end_col)

    def _width(self, line: int) -> int:
        """One past the last column of the file's line (any column for a line it lacks)."""
        return len(self.lines[line - 1]) + 1 if 1 <= line <= len(self.lines) else 1 << 30

    def _source_column(self, pre_line: int, col: int, end: bool) -> tuple[int, bool]:
        """The column in the user's line of a column of a preprocessed line (a start, or with
        `end` an end, exclusive), and whether the text between is the user's: the column lies
        in one of the user's own tokens, or at the edge of a whole macro call (`PI`, `SPEC(r,
        v)`), which then stands for its expansion. Inside an expansion: the start of that
        macro's call in the source, or its end, and not exact."""
        segments = self.pre.columns.get(pre_line) if self.pre is not None else None
        file_line = self.file_line(pre_line)
        if not segments or not 1 <= file_line <= len(self.lines):
            return col, not segments
        offset = col - 1
        source = self.lines[file_line - 1]
        pre = self._pre_line(pre_line)
        before: Segment | None = None
        for start, stop, at in segments:
            if (start <= offset < stop) if not end else (start < offset <= stop):
                return at + offset - start, True
            if stop <= offset:
                before = (start, stop, at)
            elif end:  # the expansion ends before the user's next token: trim the gap
                gap = source[: at - 1].rstrip()
                return len(gap) + 1, not pre[offset:start].strip()
        if end:
            return len(source.rstrip()) + 1, not pre[offset:].strip()
        after = 0 if before is None else before[2] - 1 + before[1] - before[0]
        skipped = len(source[after:]) - len(source[after:].lstrip())
        whole = not pre[(0 if before is None else before[1]) : offset].strip()
        return after + skipped + 1, whole

    def _pre_line(self, pre_line: int) -> str:
        if self._pre_lines is None:
            self._pre_lines = self.pre.text.split("\n") if self.pre is not None else []
        return self._pre_lines[pre_line - 1] if 0 < pre_line <= len(self._pre_lines) else ""

    def _origin(self, pre_line: int) -> int:
        # The preprocessor keeps one output line per input line, so the physical line is the
        # tree's line less the Common tab's; `#line` is ignored, as findings and edits index
        # the file as written.
        return min(self.file_line(pre_line), len(self.lines))

    def file_line(self, pre_line: int) -> int:
        """The file's line of a line of `pre` (1 at least), or 0 or less on the Common tab's."""
        return pre_line - self.line_offset if self.line_offset else max(pre_line, 1)

    def has_macros(self, node: Node) -> bool:
        """Whether the node's lines were changed before parsing: a macro expanded on them, or
        a line continued with `\\` (its columns are then approximate and no edit may be
        computed from them)."""
        if self.pre is None:
            return True
        first, last = _pre_lines(node)
        for line in range(first, last + 1):
            if line in self.pre.expansions:
                return True
            file_line = self.file_line(line)
            text = self.lines[file_line - 1] if 1 <= file_line <= len(self.lines) else ""
            if text.rstrip().endswith("\\"):
                return True
        return False

    # --- text -----------------------------------------------------------------------------

    def node_text(self, node: Node) -> str:
        """The node's text as the user wrote it (`sin(iTime * PI)`, not the expansion of PI)
        where its ends are the user's own tokens, else as preprocessed (macros expanded,
        comments blanked: a node a macro made)."""
        if isinstance(node, Token):
            return str(node)
        if self.pre is None or node.meta.empty:
            return ""
        meta = node.meta
        start, end = meta.start_pos, meta.end_pos
        columns = self.pre.columns
        if columns and (meta.line in columns or meta.end_line in columns):
            first, exact_first = self._source_column(meta.line, meta.column, end=False)
            last, exact_last = self._source_column(meta.end_line, meta.end_column, end=True)
            lines = range(self.file_line(meta.line), self.file_line(meta.end_line) + 1)
            inside = lines.start >= 1 and lines.stop - 1 <= len(self.lines)
            if exact_first and exact_last and inside:
                text = "\n".join(self.lines[n - 1] for n in lines)
                return text[first - 1 : len(text) - len(self.lines[lines.stop - 2]) + last - 1]
        return self.pre.text[start:end]

    # --- findings and edits ---------------------------------------------------------------

    def finding(
        self,
        code: str,
        severity: Severity,
        where: Node | Span,
        message: str,
        fix: Fix | None = None,
        certainty: Certainty = "likely",
    ) -> Finding:
        line, col, end_line, end_col = where if isinstance(where, tuple) else self.span(where)
        return Finding(
            self.file, line, col, end_line, end_col, code, severity, message, fix, certainty
        )

    def replace(self, node: Node, content: str) -> Edit | None:
        """An edit that replaces the node by `content`, or None when the node's position
        cannot be trusted (a macro was expanded on its lines)."""
        if self.has_macros(node):
            return None
        line, col, end_line, end_col = self.span(node)
        return Edit(line, col, end_line, end_col, content)


def _pre_lines(node: Node) -> tuple[int, int]:
    if isinstance(node, Token):
        return node.line or 1, node.end_line or node.line or 1
    if node.meta.empty:
        return 1, 1
    return node.meta.line, node.meta.end_line


def walk(node: Node) -> Iterator[Tree]:
    """Every subtree, parents before children, without recursion (deeply nested input must
    not exhaust the stack). Within `indexed(tree)`, a subtree of that tree is a slice of the
    walk made once for the whole tree."""
    for index in _INDEXES:
        found = index.subtrees(node)
        if found is not None:
            return iter(found)
    return _walk(node)


def subtree_count(node: Node, up_to: int) -> int:
    """How many subtrees `walk(node)` gives (the node included), or any number over `up_to`
    where there are more: read from the index within `indexed(tree)`, else counted."""
    for index in _INDEXES:
        start = index._starts.get(id(node))
        if start is not None:
            return index._ends[start] - start
    return sum(1 for _ in islice(_walk(node), up_to + 1))


def variable_names(node: Node) -> list[str] | None:
    """Within `indexed(tree)`, the names of the variables under a subtree of that tree, in walk
    order, "" for a called function's name (`TreeIndex.variable_names`); None elsewhere."""
    for index in _INDEXES:
        found = index.variable_names(node)
        if found is not None:
            return found
    return None


def walk_kind(node: Node, *kinds: str) -> list[Tree]:
    """The subtrees of these kinds, in `walk` order: `[n for n in walk(node) if n.data in
    kinds]`. Within `indexed(tree)`, found without looking at the other subtrees."""
    for index in _INDEXES:
        found = index.of_kind(node, kinds)
        if found is not None:
            return found
    return [item for item in _walk(node) if item.data in kinds]


def _walk(node: Node) -> Iterator[Tree]:
    stack: list[Node] = [node]
    while stack:
        item = stack.pop()
        if isinstance(item, Tree):
            yield item
            stack.extend(reversed(item.children))


class TreeIndex:
    """Every subtree of one tree in pre-order (as `walk` yields them), and for each subtree
    the slice of that list its own walk is: rules and analyses walk the same file's tree and
    its subtrees dozens of times, and slicing a list is far cheaper than walking again.

    Subtrees are keyed by id() (lark trees hash and compare by value: two equal `x` variables
    are different nodes). The index keeps every node alive, so no other object can take one
    of those ids while it exists. The tree must not change while indexed."""

    __slots__ = ("order", "_starts", "_ends", "_kinds", "_names")

    def __init__(self, root: Tree) -> None:
        order: list[Tree] = []
        starts: dict[int, int] = {}
        ends: list[int] = []
        # The stack holds nodes still to visit, and (as ints) the positions of subtrees whose
        # walk ends when the stack is popped down to them. Ints rather than tuples: tens of
        # thousands of small containers per file would wake the garbage collector.
        stack: list[Node | int] = [root]
        while stack:
            item = stack.pop()
            if isinstance(item, int):
                ends[item] = len(order)
            elif isinstance(item, Tree):
                position = len(order)
                starts[id(item)] = position
                order.append(item)
                ends.append(0)
                stack.append(position)
                stack.extend(reversed(item.children))
        self.order = order
        self._starts = starts
        self._ends = ends
        # By kind: the positions in `order` of the subtrees of that kind, and the subtrees.
        self._kinds: dict[str, tuple[list[int], list[Tree]]] | None = None
        # The positions of the `variable` subtrees, and the name each reads ("" for the name
        # of a called function).
        self._names: tuple[list[int], list[str]] | None = None

    def subtrees(self, node: Node) -> list[Tree] | None:
        """`list(walk(node))` for a subtree of the indexed tree; None for any other node."""
        start = self._starts.get(id(node))
        if start is None:
            return None
        return self.order[start : self._ends[start]]

    def variable_names(self, node: Node) -> list[str] | None:
        """The names of the variables under `node`, in walk order ("" for a called function's
        name); None for a node outside the indexed tree. Two bisections and a slice: rules ask
        this of every assignment in `x = y = x = ...`, and walking each one was quadratic."""
        start = self._starts.get(id(node))
        if start is None:
            return None
        if self._names is None:
            self.of_kind(node, ())  # makes self._kinds
            assert self._kinds is not None
            positions, variables = self._kinds.get("variable", ([], []))
            heads = {id(first_child(call)) for call in self._kinds.get("call", ((), ()))[1]}
            names = ["" if id(v) in heads else Variable(v).name for v in variables]
            self._names = (positions, names)
        positions, names = self._names
        low = bisect_left(positions, start)
        return names[low : bisect_left(positions, self._ends[start], low)]

    def of_kind(self, node: Node, kinds: tuple[str, ...]) -> list[Tree] | None:
        """`walk_kind(node, *kinds)` for a subtree of the indexed tree; None for any other
        node. The subtrees of a kind under `node` are those whose positions fall in node's
        slice: two bisections of that kind's positions."""
        start = self._starts.get(id(node))
        if start is None:
            return None
        end = self._ends[start]
        if self._kinds is None:
            self._kinds = {}
            for position, item in enumerate(self.order):
                entry = self._kinds.get(item.data)
                if entry is None:
                    self._kinds[item.data] = ([position], [item])
                else:
                    entry[0].append(position)
                    entry[1].append(item)
        found: list[tuple[list[int], list[Tree]]] = []
        for kind in dict.fromkeys(kinds):  # each kind once, as the plain walk gives it
            entry = self._kinds.get(kind)
            if entry is None:
                continue
            positions, items = entry
            low = bisect_left(positions, start)
            high = bisect_left(positions, end, low)
            if low < high:
                found.append((positions[low:high], items[low:high]))
        if len(found) == 1:
            return found[0][1]
        # Several kinds: merged back into walk order by position.
        pairs = [pair for positions, items in found for pair in zip(positions, items, strict=True)]
        return [n for _, n in sorted(pairs, key=itemgetter(0))]


def _index_of(tree: Tree) -> TreeIndex | None:
    """The index of this whole tree, when an `indexed` block made one."""
    return next((index for index in _INDEXES if index.order[0] is tree), None)


# The indexes `walk` looks in: those of the trees inside an `indexed` block (one per file being
# linted; a few if linting nests). Dropped when the block ends, so nothing outlives the file.
_INDEXES: list[TreeIndex] = []


@contextmanager
def indexed(tree: Tree | None) -> Iterator[TreeIndex | None]:
    """Within the block, `walk` of the tree or any of its subtrees slices one pre-order list
    built on entry. The tree must not be changed inside the block."""
    known = _index_of(tree) if tree is not None else None
    if tree is None or known is not None:  # nothing to index, or an enclosing block did
        yield known
        return
    index = TreeIndex(tree)
    _INDEXES.append(index)
    try:
        yield index
    finally:
        _INDEXES.remove(index)


def tokens(node: Node) -> Iterator[Token]:
    """Every token under the node, in source order, without recursion."""
    stack: list[Node] = [node]
    while stack:
        item = stack.pop()
        if isinstance(item, Token):
            yield item
        else:
            stack.extend(reversed(item.children))
