"""The fast parser (parser._FastParser) builds exactly the tree plain lark builds.

It runs lark's tables with loops of its own (lexer, retyper, LALR, tree shaping), so every
corpus shader is parsed both ways and the trees compared: node names, children, token
values and types, and every position lark puts on a node or token, the container positions
that `_nest` and the parents' spans are computed from included.
"""

from __future__ import annotations

import copy
from pathlib import Path

import pytest
from lark import Token, Tree

from glint.compiler.glsl import GLSLSyntaxError, parse
from glint.compiler.glsl.parser import _fast_parser, _lark
from glint.compiler.glsl.preprocessor import preprocess

ROOT = Path(__file__).resolve().parents[2]
SHADERTOY = Path("/work/shared/corpus/shadertoy")
TOKEN_FIELDS = ("type", "start_pos", "line", "column", "end_line", "end_column", "end_pos")


def _difference(fast: Tree | Token, plain: Tree | Token, path: str = "") -> str | None:
    """Where two trees differ, or None."""
    if isinstance(plain, Token):
        if type(fast) is not Token or fast != plain:
            return f"{path}: {fast!r} is not {plain!r}"
        for field in TOKEN_FIELDS:
            mine, lark_s = getattr(fast, field), getattr(plain, field)
            if mine != lark_s:
                return f"{path} {plain!r}: {field} {mine} != {lark_s}"
        return None
    if not isinstance(fast, Tree) or fast.data != plain.data or type(fast.data) is not str:
        return f"{path}: {fast!r:.60} is not a {plain.data} node"
    path = f"{path}/{plain.data}"
    if vars(fast.meta) != vars(plain.meta):  # positions, container positions, empty
        return f"{path}: meta {vars(fast.meta)} != {vars(plain.meta)}"
    if len(fast.children) != len(plain.children):
        return f"{path}: {len(fast.children)} children, not {len(plain.children)}"
    for index, (a, b) in enumerate(zip(fast.children, plain.children, strict=True)):
        found = _difference(a, b, f"{path}[{index}]")
        if found:
            return found
    return None


def _shaders() -> list[Path]:
    return sorted(SHADERTOY.glob("*.glsl")) + sorted((ROOT / "tests" / "corpus").rglob("*.glsl"))


def test_the_fast_parser_builds_the_tree_plain_lark_builds() -> None:
    fast, plain = _fast_parser(), _lark()
    assert fast is not None, "the fast parser cannot read this lark's tables"
    compared = rejected = 0
    for path in _shaders():
        try:
            text = preprocess(path.read_text(encoding="utf-8"), str(path)).text
        except Exception:  # noqa: BLE001 - preprocessor errors are the other tests' business
            continue
        try:
            expected = plain.parse(text)
        except Exception:  # noqa: BLE001 - lark rejects it: so must the fast parser
            assert fast.parse(text) is None, path
            rejected += 1
            continue
        tree = fast.parse(text)
        assert tree is not None, f"{path}: the fast parser fails where lark parses"
        assert _difference(tree, expected) is None, f"{path}: {_difference(tree, expected)}"
        compared += 1
    assert compared >= (400 if SHADERTOY.is_dir() else 40)


def test_the_comparison_sees_a_moved_container() -> None:
    text = "float f(float a) { return (a + 1.0) * 2.0; }"
    fast = _fast_parser()
    assert fast is not None
    tree, expected = fast.parse(text), _lark().parse(text)
    assert tree is not None and _difference(tree, expected) is None
    moved = copy.deepcopy(tree)
    binary = next(moved.find_data("binary")).children[0]
    assert isinstance(binary, Tree)
    binary.meta.container_column += 1  # type: ignore[attr-defined]
    assert _difference(moved, expected) is not None


@pytest.mark.parametrize(
    "source",
    [
        "float f() { return 1.0 @ 2.0; }",  # a character no terminal matches
        "float f() { return 1.0 2.0; }",  # a token the table has no action for
        "float f() { return 1.0;",  # the end too early
        "float f() { float input = 1.0; return input; }",  # a reserved word
    ],
)
def test_bad_input_gets_lark_s_error(source: str) -> None:
    fast = _fast_parser()
    assert fast is not None and fast.parse(source) is None
    with pytest.raises(GLSLSyntaxError):
        parse(source)
