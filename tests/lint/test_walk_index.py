"""The tree index behind `walk` (lint/context.py): within `indexed(tree)`, walking any subtree
of the tree slices one pre-order list instead of walking again. It must give exactly what the
plain walk gives, node for node, on real trees, and leave other nodes to the plain walk."""

from __future__ import annotations

from pathlib import Path

import pytest
from lark import Token, Tree

from glint.compiler.glsl import parse, preprocess
from glint.lint.analysis.syntax import calls_in, names_in
from glint.lint.context import LintContext, TreeIndex, _walk, indexed, walk, walk_kind

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
SHADERS = sorted((CORPUS / "lint").glob("*.glsl")) + sorted((CORPUS / "valid").glob("*.glsl"))


def tree_of(path: Path) -> Tree:
    text = path.read_text(encoding="utf-8")
    return parse(preprocess(text, path.name).text, path.name)


def same_nodes(got: list[Tree], want: list[Tree]) -> bool:
    """The same node objects in the same order (lark trees compare by value, so `==` would
    accept an equal subtree found at the wrong place)."""
    return len(got) == len(want) and all(a is b for a, b in zip(got, want, strict=True))


# Single kinds, several kinds (merged back into walk order), a kind named twice, a kind that
# no tree has, and none.
KIND_SETS = [("call",), ("binary",), ("variable", "int_literal"), ("jump_statement", "binary"),
             ("call", "call"), ("no such kind",), ()]  # fmt: skip


@pytest.mark.parametrize("path", SHADERS, ids=lambda p: p.name)
def test_index_gives_the_plain_walk_of_every_subtree(path: Path) -> None:
    tree = tree_of(path)
    index = TreeIndex(tree)
    plain = list(_walk(tree))
    assert same_nodes(index.order, plain)
    with indexed(tree):
        for node in plain:
            want = list(_walk(node))
            assert same_nodes(index.subtrees(node) or [], want), node.data
            assert same_nodes(list(walk(node)), want), node.data
            for kinds in KIND_SETS:
                assert same_nodes(walk_kind(node, *kinds), [n for n in want if n.data in kinds])


@pytest.mark.parametrize("path", SHADERS, ids=lambda p: p.name)
def test_names_and_calls_under_a_node_are_the_same_indexed_or_not(path: Path) -> None:
    tree = tree_of(path)
    nodes = list(_walk(tree))
    want = [(names_in(n), calls_in(n)) for n in nodes]
    with indexed(tree):
        for node, (names, calls) in zip(nodes, want, strict=True):
            assert names_in(node) == names, node.data
            assert same_nodes(calls_in(node), calls), node.data


@pytest.mark.parametrize("path", SHADERS[:3], ids=lambda p: p.name)
def test_context_nodes_are_the_same_indexed_or_not(path: Path) -> None:
    tree = tree_of(path)
    kinds = {n.data for n in _walk(tree)} | {"no such kind"}
    plain = LintContext("x.glsl", "", tree=tree)
    want = {kind: plain.nodes(kind) for kind in kinds}
    fast = LintContext("x.glsl", "", tree=tree)
    with indexed(tree):
        for kind in sorted(kinds):
            assert same_nodes(fast.nodes(kind), want[kind]), kind
        assert fast.parents() == plain.parents()


def test_nodes_outside_the_index_are_walked_plainly() -> None:
    tree = tree_of(SHADERS[0])
    other = Tree("expression", [Tree("variable", [Token("IDENTIFIER", "x")])])
    copy = tree_of(SHADERS[0])  # equal to `tree` by value, but other node objects
    with indexed(tree) as index:
        assert index is not None
        assert index.subtrees(other) is None and index.subtrees(copy) is None
        assert same_nodes(list(walk(other)), [other, other.children[0]])
        assert same_nodes(list(walk(copy)), list(_walk(copy)))
        assert list(walk(Token("IDENTIFIER", "x"))) == []  # a token has no subtrees
        assert same_nodes(walk_kind(other, "variable"), [other.children[0]])
        with indexed(tree) as again:  # nested blocks share the enclosing index
            assert again is index
        assert index.subtrees(tree) is not None
    # Outside the block the index is gone: `walk` is the plain walk again.
    assert not isinstance(walk(tree), type(iter([])))
    assert same_nodes(list(walk(tree)), list(_walk(tree)))


def test_an_empty_block_without_a_tree() -> None:
    with indexed(None) as index:
        assert index is None
