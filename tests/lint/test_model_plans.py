"""The semantic model's `record` goes through a plan of each expression, made once (its regions
of nodes that share an environment, its call sites and its branches): it must remember the very
environments, and gather the call sites in the very order, that walking the expression node by
node at every pass does."""

from __future__ import annotations

import pytest
from lark import Tree

from glint.lint.analysis import Model
from glint.lint.analysis.syntax import is_tree
from glint.lint.analysis.values import Env
from glint.lint.context import Node, walk
from glint.lint.options import Options
from glint.lint.precision import CORPUS, valid_files
from glint.lint.runner import build_context

BRANCHES = """
float f(float x, float y) { return x / y; }
float g(float x) { return sqrt(x); }
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float a = fragCoord.x - 0.5, b = dot(vec2(a), vec2(0.3));
    float c = a > 0.0 ? f(a, b) : g(-a) + f(b, a > 1.0 ? a : 2.0);
    bool d = a > 0.0 && b < 1.0 && f(a, b) > 0.0 || g(a) < 0.5 && f(b, a) > 0.0;
    fragColor = vec4(d ? f(c, a) : g(b), f(a, c), g(c), 1.0);
}
"""


class _NodeByNode(Model):
    """`record` as a walk over every node at every pass (the model before its plans)."""

    def record(self, expr: Node, env: Env, seen: object = None) -> None:
        stack: list[tuple[Node, Env]] = [(expr, env)]
        while stack:
            node, here = stack.pop()
            if not isinstance(node, Tree):
                continue
            self._env_of[id(node)] = here
            kids = node.children
            if node.data == "ternary":
                stack += [(kids[0], here), (kids[1], self.refine(here, kids[0], True)),
                          (kids[2], self.refine(here, kids[0], False))]  # fmt: skip
                continue
            if node.data == "binary" and str(kids[1]) in ("&&", "||"):
                stack += self._operands(node, here)
                continue
            if node.data == "call" and self._collecting:
                self._call_site(node, here, None)
            stack.extend((child, here) for child in kids)

    def _operands(self, node: Tree, env: Env) -> list[tuple[Node, Env]]:
        op = str(node.children[1])
        spine = [node]
        first = node.children[0]
        while is_tree(first, "binary") and str(first.children[1]) == op:  # type: ignore
            spine.append(first)  # type: ignore[arg-type]
            self._env_of[id(first)] = env
            first = first.children[0]  # type: ignore[union-attr]
        out: list[tuple[Node, Env]] = [(first, env)]
        before = first
        for link in reversed(spine):
            env = self.refine(env, before, op == "&&")
            before = link.children[2]
            out.append((before, env))
        return out


def _facts(model: Model) -> tuple[list[object], object]:
    return [model.value_of(node) for node in walk(model.tree)], model._params


def _assert_same(text: str, file: str) -> None:
    ctx = build_context(text, file, Options(glslang=False))
    assert ctx.tree is not None, file
    assert _facts(Model(ctx.tree)) == _facts(_NodeByNode(ctx.tree)), file


def test_plans_record_what_a_walk_records() -> None:
    _assert_same(BRANCHES, "branches.glsl")


@pytest.mark.skipif(not (CORPUS / "glslang-valid.txt").is_file(), reason="no corpus beside")
def test_plans_record_what_a_walk_records_on_real_shaders() -> None:
    for path in valid_files()[5::12]:  # every 12th: 36 files, a few seconds
        _assert_same(path.read_text(encoding="utf-8", errors="replace"), str(path))
