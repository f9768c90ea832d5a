"""Keep only what `mainImage` reaches.

The resolver takes whole units, but a unit may define more than the scene uses: `core.surface`
defines `lightDots` for scenes with a direct light, the parameter block a `#define` for every
knob of every unit taken. Here every top-level item that `mainImage` does not reach is removed:
functions with their prototypes, `#define`s, global constants and variables, structs. The graph
is the GLSL front end's (`symbols.deps`): a function needs what it calls and names, a macro what
its replacement names. Each unit is read on its own and its reading cached by its text, so a
snippet is parsed once per process, not once per composition (the default scene composed in
20 ms, 88 % of it parsing back the whole program; now in about 3 ms once the catalog is read);
a name one unit uses and another defines meets its definition in the graph, by name.

Comment lines directly above a run of items (no blank line between) describe that run and go
when all of its items go. A unit left with no code goes entirely. A unit cut into pieces gets
a `// source: FILE:LINE` marker before each piece after the first, so that every emitted line
still maps to its line in the snippet file.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from functools import lru_cache

from lark import Tree

from glint.compiler.compose.units import GENERATED, Unit
from glint.compiler.glsl import parse_source, reach, symbols_of
from glint.compiler.glsl.ast import FunctionDefinition, FunctionPrototype, VariableDeclaration
from glint.compiler.target.shadertoy import UNIFORM_NAMES
from glint.compiler.target.sourcemap import source_marker

ROOTS = frozenset({"mainImage"})

_DEFINE = re.compile(r"^\s*#\s*define\s+(\w+)")
# A macro tested by #if/#ifdef decides which code exists, so it counts as used.
_CONDITIONAL = re.compile(r"^\s*#\s*(?:if|ifdef|ifndef|elif)\b(.*)")


@dataclass(frozen=True)
class _Item:
    """A top-level declaration: the names it defines and its lines (0-based, inclusive)."""

    names: frozenset[str]
    first: int
    last: int

    @property
    def lines(self) -> range:
        return range(self.first, self.last + 1)


def prune_unreachable(units: list[Unit], roots: frozenset[str] = ROOTS) -> list[Unit]:
    """The units, in order, less every top-level item that `roots` do not reach."""
    lines: list[str] = []
    items: list[_Item] = []
    comments: set[int] = set()
    deps: dict[str, set[str]] = {}
    tested: set[str] = set()
    starts: list[int] = []  # where each unit's body begins among `lines`
    for unit in units:
        start = len(lines)
        starts.append(start)
        lines += unit.body.split("\n")
        # Each unit on its own, its analysis cached by its text: a snippet's body is read once
        # per process, not once per composition. A name one unit uses and another defines
        # meets its definition in the graph below, by name.
        analysis = _analysis(unit.body)
        items += [replace(item, first=item.first + start, last=item.last + start)
                  for item in analysis.items]  # fmt: skip
        comments |= {line + start for line in analysis.comments}
        for name, names in analysis.deps.items():
            deps.setdefault(name, set()).update(names)
        tested |= analysis.tested
    keep = reach(deps, set(roots) | tested)
    removed = _removed_lines(items, keep, comments)
    cut = (
        _cut(unit, start, lines, removed, comments)
        for unit, start in zip(units, starts, strict=True)
    )
    return [unit for unit in cut if unit is not None]


@dataclass(frozen=True)
class _Analysis:
    """One unit's body read on its own (lines counted from its first)."""

    items: tuple[_Item, ...]  # its top-level declarations
    deps: dict[str, frozenset[str]]  # what each name it defines names (symbols.deps)
    comments: frozenset[int]  # its comment lines
    tested: frozenset[str]  # names its #if lines test, which decide what code exists


@lru_cache(maxsize=2048)
def _analysis(body: str) -> _Analysis:
    lines = body.split("\n")
    tree, pre = parse_source(body, "<unit>")
    symbols = symbols_of(tree, pre, provided=UNIFORM_NAMES)
    # The preprocessor blanks comments and directives, keeping one line per line.
    code = pre.text.split("\n")
    comments = {
        i
        for i, line in enumerate(lines)
        if line.strip() and not code[i].strip() and not line.lstrip().startswith("#")
    }
    deps = {name: frozenset(names) for name, names in symbols.deps.items()}
    return _Analysis(
        tuple(_items(tree, lines)), deps, frozenset(comments), frozenset(_conditional_names(lines))
    )


def _conditional_names(lines: list[str]) -> set[str]:
    tested = (m.group(1) for line in lines if (m := _CONDITIONAL.match(line)))
    return {name for text in tested for name in re.findall(r"\w+", text)}


def _items(tree: Tree, lines: list[str]) -> list[_Item]:
    """Functions, prototypes and declarations from the tree; `#define`s from the text, as the
    parser never sees them."""
    items = []
    for node in tree.children:
        names = _declared(node) if isinstance(node, Tree) else set()
        if names:
            items.append(_Item(frozenset(names), node.meta.line - 1, node.meta.end_line - 1))
    for i, line in enumerate(lines):
        if match := _DEFINE.match(line):
            last = i
            while lines[last].endswith("\\") and last + 1 < len(lines):
                last += 1
            items.append(_Item(frozenset({match.group(1)}), i, last))
    return items


def _declared(node: Tree) -> set[str]:
    """Names a top-level node defines; none for what always stays (precision statements)."""
    if node.data == "function_definition":
        return {FunctionDefinition(node).name}
    if node.data == "function_prototype":
        return {FunctionPrototype(node).name}
    if node.data != "variable_declaration":
        return set()
    declaration = VariableDeclaration(node)
    names = {declarator.name for declarator in declaration.declarators}
    struct = declaration.type.type.struct
    if struct is not None and struct.name is not None:
        names.add(struct.name)
    return names


def _removed_lines(items: list[_Item], keep: set[str], comments: set[int]) -> set[int]:
    """Lines of unreached items, and of comments that describe only unreached items."""
    dead = [item for item in items if not item.names & keep]
    live = [item for item in items if item.names & keep]
    # A line that a kept item shares (two declarations on one line) stays.
    removed = {i for item in dead for i in item.lines} - {i for item in live for i in item.lines}
    owner = {i: item for item in items for i in item.lines}
    for line in comments - owner.keys():
        below = line
        while below in comments and below not in owner:
            below += 1
        described = _run_of_items(owner, below)
        if described and all(item in dead for item in described):
            removed.add(line)
    return removed


def _run_of_items(owner: dict[int, _Item], line: int) -> list[_Item]:
    """The items on the lines from `line` on, up to the first line that is in none."""
    run: list[_Item] = []
    while line in owner:
        if owner[line] not in run:
            run.append(owner[line])
        line += 1
    return run


def _cut(
    unit: Unit, start: int, lines: list[str], removed: set[int], comments: set[int]
) -> Unit | None:
    """The unit without its removed lines; None when nothing but comments is left."""
    span = range(start, start + unit.body.count("\n") + 1)
    if removed.isdisjoint(span):
        return unit
    left = [i for i in span if i not in removed]
    if all(not lines[i].strip() or i in comments for i in left):
        return None
    out: list[str] = []
    first = start
    blank_between = False  # whether the source had a blank line where the gap is
    for run in _runs(left):
        filled = [i for i in run if lines[i].strip()]
        if not filled:
            blank_between = True
            continue
        piece = run[run.index(filled[0]) : run.index(filled[-1]) + 1]
        if not out:
            first = piece[0]
        else:
            if blank_between or piece[0] != run[0]:
                out.append("")
            if unit.origin != GENERATED:  # generated lines map to the composed file anyway
                out.append(source_marker(unit.origin, unit.line + piece[0] - start))
        out += [lines[i] for i in piece]
        blank_between = piece[-1] != run[-1]
    return replace(unit, body="\n".join(out) + "\n", line=unit.line + first - start)


def _runs(indices: list[int]) -> list[list[int]]:
    """Ascending indices split where they skip: the lines of a unit that stay together."""
    runs: list[list[int]] = []
    for i in indices:
        if runs and runs[-1][-1] == i - 1:
            runs[-1].append(i)
        else:
            runs.append([i])
    return runs
