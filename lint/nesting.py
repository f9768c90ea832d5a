"""How deeply a file nests, measured before any analysis runs: code nested past these limits is
reported (C006) rather than analysed.

Three measures, because the analyses pay for depth in different ways:

- Nesting (`MAX_NESTING`): brackets in the text, and statements inside statements in the tree
  (braced or not: `if (a) if (b) ...` nests as `if (a) { if (b) { ... } }` does). An
  `else if` continues a chain rather than nesting: it counts as no level.
- Loops inside loops (`MAX_LOOPS`): each loop's analyses read everything inside it, the loops
  inside it included, so their cost grows with the nesting of loops times the code's length:
  two thousand nested brace-less `for`s took minutes and gigabytes.
- Depth (`MAX_DEPTH`): the parse tree's deepest path, where chains count too (`a + a + ...`,
  `- - x`, `a ? b : a ? b : ...`, `x = y = ...`, `else if ...`). The analyses follow chains at
  a cost that grows linearly (tests/lint/test_lint_bounds.py holds them to it), but by
  recursion, within the runner's RECURSION_LIMIT of Python frames.

The tree is walked without recursion: the parser (LALR, with callbacks that build each node
from its children) does not recurse either, so any input that parses can be measured.
"""

from __future__ import annotations

from dataclasses import dataclass

from lark import Tree

# Deeper brackets or statements than any real shader has: the 468 shaders of the corpus nest
# brackets at most 14 deep, statements 12.
MAX_NESTING = 256
# The corpus nests loops at most 8 deep. At 64 levels of loops with bodies of ordinary code,
# 100 KB are analysed in a few seconds (at 256, in a quarter of a minute).
MAX_LOOPS = 64
# Generated code writes long sums (a few thousand terms) and else-if chains; the corpus's
# deepest tree is 35 levels. The analyses take at most 3.1 Python frames per level of the tree
# (a prefix `++` in an assignment is the hungriest), and the runner allows 20,000 frames.
MAX_DEPTH = 5_500

_LOOPS = frozenset({"for_statement", "while_statement", "do_statement"})
_CONTROL = _LOOPS | {"if_statement", "switch_statement"}
_BODY_OWNERS = _CONTROL | {"function_definition"}
_STATEMENTS = _CONTROL | {"compound_statement"}


@dataclass(frozen=True)
class Nesting:
    """How deeply one file nests, by each measure of the module's docstring."""

    brackets: int = 0
    statements: int = 0
    loops: int = 0
    depth: int = 0

    def too_deep(self) -> str:
        """Why the file is too deep to analyse ("" when it is not), for C006's message."""
        levels = max(self.brackets, self.statements)
        if levels > MAX_NESTING:
            return f"{levels} levels; glint follows {MAX_NESTING}"
        if self.loops > MAX_LOOPS:
            return f"loops nested {self.loops} deep; glint follows {MAX_LOOPS}"
        if self.depth > MAX_DEPTH:
            return f"an expression or chain {self.depth:,} levels deep; glint follows {MAX_DEPTH:,}"
        return ""


def bracket_nesting(text: str) -> int:
    """The deepest nesting of (), [] and {} (comments are already blanked by the
    preprocessor)."""
    depth = deepest = 0
    for char in text:
        if char in "([{":
            depth += 1
            deepest = max(deepest, depth)
        elif char in ")]}":
            depth = max(depth - 1, 0)
    return deepest


def tree_nesting(tree: Tree, brackets: int = 0) -> Nesting:
    """The nesting of a parse tree (`brackets`: of its text, measured before it was parsed)."""
    statements = loops = deepest = 0
    # (node, its depth, statements around it, loops around it); run on every file linted, so
    # the loop is kept lean: most nodes are expressions, which only pass their depth on.
    stack: list[tuple[Tree, int, int, int]] = [(tree, 1, 0, 0)]
    pop, push = stack.pop, stack.append
    while stack:
        node, depth, nested, looped = pop()
        if depth > deepest:
            deepest = depth
        depth += 1
        for child in node.children:
            if not isinstance(child, Tree):
                continue
            kind = child.data
            if kind not in _STATEMENTS:
                push((child, depth, nested, looped))
                continue
            level = nested + _level(node, child)
            looping = looped + (kind in _LOOPS)
            statements = max(statements, level)
            loops = max(loops, looping)
            push((child, depth, level, looping))
    return Nesting(brackets, statements, loops, deepest)


def _level(parent: Tree, child: Tree) -> int:
    """1 where `child`, a statement, is nested in its parent; 0 for the braces of a loop's, an
    if's or a function's own body, and for the `if` of an `else if`."""
    kind = child.data
    if kind == "compound_statement":
        return 0 if parent.data in _BODY_OWNERS else 1
    if kind == "if_statement" and parent.data == "if_statement":
        siblings = parent.children
        if len(siblings) == 3 and siblings[2] is child:
            return 0  # `else if`: the next link of a chain
    return 1
