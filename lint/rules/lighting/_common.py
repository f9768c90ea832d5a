"""Helpers shared by the lighting rules: how a cosine or an expression is shown in a message, the
mainImage function and what it writes to its colour (ColourOutput, for L005-L007), and the
factors and lobes of a lighting sum (L007, L008)."""

from __future__ import annotations

import re

from lark import Tree

from ...analysis.model import semantic_model
from ...context import LintContext, Node, walk
from ._terms import (
    Function,
    binary_op,
    call_args,
    call_name,
    calls_in,
    const_value,
    cosine_of,
    function_map,
    functions,
    operands,
    resolve,
    root_var,
)

COSINE_TEXT = {"NL": "N·L", "NH": "N·H", "NV": "N·V", "VH": "V·H", "LV": "L·V"}


def short_text(ctx: LintContext, node: Node, limit: int = 50) -> str:
    """The node's text for a message: as the user wrote it (macros unexpanded) when the node
    sits on one line without expansions, else as preprocessed."""
    text = ctx.node_text(node)
    if not ctx.has_macros(node):
        line, col, end_line, end_col = ctx.span(node)
        if line == end_line and 0 < line <= len(ctx.lines):
            text = ctx.lines[line - 1][col - 1 : end_col - 1]
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 3] + "..."


ENCODE_NAME = re.compile(r"gamma|srgb|outputtransfer|encode|todisplay", re.I)


DECODE_NAME = re.compile(r"tolinear|linearize|degamma|decode|srgb2lin|srgbtolin|removegamma", re.I)


TONEMAP_NAME = re.compile(
    r"tone_?map|aces|reinhard|filmic|uncharted|hable|agx|lottes|uchimura|exposure", re.I
)


def main_image(ctx: LintContext) -> tuple[Function, str] | None:
    """mainImage and the name of its colour output."""
    for fn in functions(ctx):
        if fn.name == "mainImage":
            for name in fn.param_order:
                if "out" in fn.params[name][0]:
                    return fn, name
    return None


def is_vector(ctx: LintContext, node: Node) -> bool:
    """Whether the expression is a vector (a colour), by the model's type."""
    return (semantic_model(ctx).type_of(node) or "").startswith("vec")


class ColourOutput:
    """What a shader does to colour on its way out: which functions encode for the display
    (gamma/sRGB), and whether something tone maps."""

    def __init__(self, ctx: LintContext) -> None:
        self.ctx = ctx
        self.defined = function_map(ctx)
        self.encoders = {f.name for f in functions(ctx) if self._encoder(f)}

    def _encoder(self, fn: Function) -> bool:
        if DECODE_NAME.search(fn.name):
            return False
        if ENCODE_NAME.search(fn.name) and fn.name != "mainImage":
            return True
        for node in walk(fn.body):
            if node.data == "jump_statement" and len(node.children) == 2:
                value = self._peel(resolve(node.children[1], fn))
                if self.gamma_of(value, fn, direct=True) is not None:
                    return True
        return False

    def _peel(self, node: Node) -> Node:
        while isinstance(node, Tree) and node.data == "constructor" and call_args(node):
            node = call_args(node)[0]
        return node

    def gamma_of(self, node: Node, fn: Function | None, direct: bool = False) -> Node | None:
        """For a display encoding (pow by about 1/2.2, sqrt of a colour, a call of an encoding
        function) the colour it encodes, else None."""
        name = call_name(node)
        if name is None:
            return None
        args = call_args(node)  # type: ignore[arg-type]
        if name == "pow" and len(args) == 2:
            value = const_value(args[1])
            text = self.ctx.node_text(args[1]).lower()
            if (value is not None and 0.38 <= value <= 0.5) or "gamma" in text:
                return args[0]
        if name == "sqrt" and len(args) == 1 and is_vector(self.ctx, args[0]):
            return args[0]
        if not direct and name in self.encoders and args:
            return args[0]
        return None

    def any_gamma(self) -> bool:
        if self.encoders:
            return True
        return any(self.gamma_of(n, fn) is not None for fn in functions(self.ctx)
                   for n in calls_in(fn.body))  # fmt: skip

    def any_tonemap(self) -> bool:
        for fn in functions(self.ctx):
            if TONEMAP_NAME.search(fn.name):
                return True
            for node in walk(fn.body):
                if TONEMAP_NAME.search(call_name(node) or "") or self._tonemap_form(node):
                    return True
        return False

    def _tonemap_form(self, node: Tree) -> bool:
        text = self.ctx.node_text
        if binary_op(node) == "/":
            top = " ".join(text(node.children[0]).split())
            parts = operands(node.children[2], "+")
            # x / (1 + x), x / (x + k): Reinhard and its variants
            if len(parts) >= 2 and top in {" ".join(text(p).split()) for p in parts}:
                return True
        if binary_op(node) == "-" and const_value(node.children[0]) == 1.0:
            return call_name(node.children[2]) == "exp"  # 1 - exp(-k x): exponential
        if call_name(node) in ("clamp", "min", "saturate", "smoothstep"):
            return False
        return False


def output_writes(fn: Function, out: str) -> list[Tree]:
    return [n for n in walk(fn.body) if n.data == "assignment" and root_var(n.children[0]) == out]


def product_factors(node: Node) -> tuple[list[Node], list[Node]]:
    """Numerators and denominators of a chain of * and / (`a * b / c` -> [a, b], [c])."""
    top: list[Node] = []
    bottom: list[Node] = []
    stack: list[tuple[Node, bool]] = [(node, True)]
    while stack:
        item, up = stack.pop()
        op = binary_op(item)
        if op in ("*", "/"):
            assert isinstance(item, Tree)
            stack.append((item.children[0], up))
            stack.append((item.children[2], up if op == "*" else not up))
        else:
            (top if up else bottom).append(item)
    return top, bottom


def is_lobe(node: Node, fn: Function) -> bool:
    if call_name(node) == "pow":
        return cosine_of(call_args(node)[0], fn) in ("NH", "LV")  # type: ignore[arg-type]
    return False
