"""Shared by the copy-paste rules (C108, C109): when two names are twins (written by copying one
and changing a digit, an axis letter or adding a "saved copy" suffix), and a statement's shape
as a flat sequence to compare two statements position by position."""

from __future__ import annotations

import re

from lark import Token, Tree

from ...context import Node

# Letters that name one of a family of parallel values: axes, texture coordinates, colours.
_AXES = (frozenset("xyzw"), frozenset("uv"), frozenset("rgba"), frozenset("st"))
# Suffixes of a copy kept of a value before it changes.
COPY_SUFFIX = re.compile(r"^_?(save|saved|old|prev|orig|original|copy|backup|bak)$", re.I)


def copy_suffix(copy: str, of: str) -> str | None:
    """The suffix that makes `copy` a saved copy of `of` (`glowSave` of `glow`), else None."""
    if len(copy) > len(of) and copy.startswith(of) and COPY_SUFFIX.match(copy[len(of) :]):
        return copy[len(of) :]
    return None


def twin_kind(a: str, b: str) -> str | None:
    """How two different names are twins: "digit" (`p1`/`p2`, `t`/`t2`), "axis" (`ddx`/`ddy`,
    at least two characters long) or "copy" (`glow2`/`glow2Save`); None when they are not."""
    if a == b:
        return None
    if len(a) == len(b):
        diff = [i for i in range(len(a)) if a[i] != b[i]]
        if len(diff) != 1:
            return None
        x, y = a[diff[0]], b[diff[0]]
        if x.isdigit() and y.isdigit():
            return "digit"
        if len(a) >= 2 and any(x in s and y in s for s in _AXES):
            return "axis"
        return None
    short, long = (a, b) if len(a) < len(b) else (b, a)
    tail = long[len(short) :]
    if long.startswith(short) and len(tail) == 1 and tail.isdigit() and not short[-1:].isdigit():
        return "digit"
    if copy_suffix(long, short):
        return "copy"
    return None


def shape(node: Node) -> list[tuple[str, str]]:
    """The node flattened in source order: ("T", rule) for each subtree, with its child count,
    and (token type, text) for each token. Two statements of one shape differ only in names,
    numbers and operators at the same positions."""
    out: list[tuple[str, str]] = []
    stack: list[Node] = [node]
    while stack:
        item = stack.pop()
        if isinstance(item, Token):
            out.append((item.type, str(item)))
        else:
            out.append(("T", f"{item.data}/{len(item.children)}"))
            stack.extend(reversed(item.children))
    return out


def subtrees(node: Tree) -> list[Node]:
    """The node's subtrees and tokens in the same order as `shape`."""
    out: list[Node] = []
    stack: list[Node] = [node]
    while stack:
        item = stack.pop()
        out.append(item)
        if isinstance(item, Tree):
            stack.extend(reversed(item.children))
    return out
