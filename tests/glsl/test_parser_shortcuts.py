"""The parser's two speed-ups give the tree a plain lark parser gives.

- Binary operators are parsed as one flat chain and nested by precedence in a callback
  (parser._Shape); the tree must be the one a rule per precedence level gives, positions
  included (test_parser.py checks the nesting of every precedence level).
- Unit rules hand their child on without lark's tree-building wrappers
  (parser._pass_unit_rules_through); the tree must not change at all.

`parse` runs the fast parser (test_fast_parser.py compares it on every corpus shader), so the
comparison here covers the three together.
"""

from __future__ import annotations

from pathlib import Path

from lark import Token, Tree

from glint.compiler.glsl import parse
from glint.compiler.glsl.parser import _lark
from glint.compiler.glsl.preprocessor import preprocess

ROOT = Path(__file__).resolve().parents[2]
META = ("line", "column", "end_line", "end_column", "start_pos", "end_pos", "empty")


def _same(a: Tree | Token, b: Tree | Token) -> bool:
    if isinstance(a, Token):
        return isinstance(b, Token) and a == b and a.type == b.type
    if not isinstance(b, Tree) or a.data != b.data or len(a.children) != len(b.children):
        return False
    if any(getattr(a.meta, k, None) != getattr(b.meta, k, None) for k in META):
        return False
    return all(_same(x, y) for x, y in zip(a.children, b.children, strict=True))


def _expression(source: str) -> Tree:
    tree = parse(f"float f() {{ return {source}; }}")
    return next(tree.find_data("jump_statement")).children[1]  # type: ignore[return-value]


def test_a_parenthesised_operand_widens_its_parent_to_the_parenthesis() -> None:
    node = _expression("(a + b) * c")
    text = "float f() { return (a + b) * c; }"
    assert text[node.meta.start_pos : node.meta.end_pos] == "(a + b) * c"
    inner = node.children[0]
    assert text[inner.meta.start_pos : inner.meta.end_pos] == "a + b"


def _shaders() -> list[Path]:
    # the repository's own shader corpora: real constructs, and quick to parse twice
    return sorted((ROOT / "tests" / "corpus").rglob("*.glsl"))[:60]


def test_the_shortcuts_leave_the_tree_as_lark_builds_it() -> None:
    plain = _lark()  # the same grammar and callbacks, without the unit-rule shortcut
    compared = 0
    for path in _shaders():
        try:
            text = preprocess(path.read_text(encoding="utf-8"), str(path)).text
            expected = plain.parse(text)
        except Exception:  # noqa: BLE001 - files that do not parse are the other tests' business
            continue
        assert _same(parse(text, str(path)), expected), path
        compared += 1
    assert compared >= 20
