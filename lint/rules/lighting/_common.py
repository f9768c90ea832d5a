"""Helpers shared by the lighting rules: how a cosine or an expression is shown in a message, the
mainImage function and what it writes to its colour (ColourOutput, for L005-L007), and the
factors and lobes of a lighting sum (L007, L008)."""

from __future__ import annotations

import re

from lark import Tree

from glint.compiler.glsl.ast import (
    Assignment,
    Binary,
    Declarator,
    Field,
    IfStatement,
    JumpStatement,
    variable_name,
)

from ...analysis.constants import const_value, global_constants, is_compile_time
from ...analysis.expression_types import expression_types
from ...analysis.functions import Function, function_map, functions, resolve
from ...analysis.model import semantic_model
from ...analysis.syntax import (
    binary_op,
    call_args,
    call_name,
    calls_in,
    operands,
    root_var,
    var_name,
)
from ...context import LintContext, Node, walk_kind
from ._terms import cosine_of, vector_role

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


def is_colour(ctx: LintContext, node: Node) -> bool:
    """Whether the expression can be a colour: a vec3 or vec4 by its type (unknown
    counts), not a vec2 or a scalar."""
    return expression_types(ctx).type_of(node) in (None, "vec3", "vec4")


def macros_used(ctx: LintContext, node: Node) -> set[str]:
    """The names of the macros expanded on the node's lines (the user wrote these names)."""
    if ctx.pre is None or not isinstance(node, Tree) or node.meta.empty:
        return set()
    names: set[str] = set()
    for line in range(node.meta.line, node.meta.end_line + 1):
        names |= ctx.pre.expansions.get(line, set())
    return names


def is_vector(ctx: LintContext, node: Node) -> bool:
    """Whether the expression is a vector (a colour), by its type."""
    return (expression_types(ctx).type_of(node) or "").startswith("vec")


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
        for node in walk_kind(fn.body, "jump_statement"):
            returned = JumpStatement(node).value
            if returned is not None:
                value = self._peel(resolve(returned, fn))
                if self.gamma_of(value, fn, direct=True) is not None:
                    return True
        return False

    def _peel(self, node: Node) -> Node:
        while isinstance(node, Tree) and node.data == "constructor" and call_args(node):
            node = call_args(node)[0]
        return node

    def gamma_of(self, node: Node, fn: Function | None, direct: bool = False) -> Node | None:
        """For a display encoding (pow by about 1/2.2, sqrt of a colour, a call of an encoding
        function) the colour it encodes, else None.

        A colour is a vec3 or vec4: a sqrt or pow of a vec2 or of a float mask is a shape
        function. An exponent named gamma
        encodes when its value is in the encoding window, or, unknown, when it is `1.0 / gamma`
        or a bare name; `1.0 - gamma` or a value outside the window is a grade or a decode."""
        name = call_name(node)
        if name is None:
            return None
        args = call_args(node)  # type: ignore[arg-type]
        if name in ("pow", "sqrt") and not (args and is_colour(self.ctx, args[0])):
            return None
        if name == "pow" and len(args) == 2:
            value = self._exponent(args[1])
            if value is not None:
                return args[0] if 0.38 <= value <= 0.5 else None
            if "gamma" in self.ctx.node_text(args[1]).lower() and self._encoding_form(args[1]):
                return args[0]
        if name == "sqrt" and len(args) == 1:
            return args[0]
        if not direct and name in self.encoders and args:
            return args[0]
        return None

    def _exponent(self, node: Node) -> float | None:
        """The exponent's value: a constant, or the model's range when it is one number."""
        value = const_value(node, global_constants(self.ctx))
        if value is not None:
            return value
        known = semantic_model(self.ctx).range_of(node)
        return known.lo if known.lo == known.hi else None

    def _encoding_form(self, node: Node) -> bool:
        while isinstance(node, Tree) and node.data == "constructor" and len(call_args(node)) == 1:
            node = call_args(node)[0]
        op = binary_op(node)
        if op == "/":
            return const_value(Binary(node).left) == 1.0  # type: ignore[arg-type]
        return op is None and call_name(node) is None  # a bare name: gamma, invGamma

    def curve_of(self, node: Node, fn: Function | None) -> Node | None:
        """For an output curve the author chose, the colour it shapes, else None: an encoding
        (gamma_of), a pow of a colour by a constant exponent in (0, 1) (a gentler gamma,
        `pow(col, vec3(0.8))`, is still a deliberate transfer), or a pow by an exponent named
        gamma as the user wrote it (`vec3(GAMMA)` with `#define GAMMA 1.3`)."""
        inner = self.gamma_of(node, fn)
        if inner is not None:
            return inner
        if call_name(node) != "pow" or len(call_args(node)) != 2:  # type: ignore[arg-type]
            return None
        base, exponent = call_args(node)  # type: ignore[arg-type]
        if not is_colour(self.ctx, base):
            return None
        value = self._exponent(exponent)
        if value is not None and 0.0 < value < 1.0:
            return base
        if any("gamma" in m.lower() for m in macros_used(self.ctx, exponent)):
            return base
        return None

    def any_curve(self) -> bool:
        if self.encoders:
            return True
        return any(self.curve_of(n, fn) is not None for fn in functions(self.ctx)
                   for n in calls_in(fn.body))  # fmt: skip

    def any_gamma(self) -> bool:
        if self.encoders:
            return True
        return any(self.gamma_of(n, fn) is not None for fn in functions(self.ctx)
                   for n in calls_in(fn.body))  # fmt: skip

    def any_tonemap(self) -> bool:
        for fn in functions(self.ctx):
            if TONEMAP_NAME.search(fn.name):
                return True
            # Only calls have a name and only binary operators have a tone-mapping form.
            for node in walk_kind(fn.body, "call", "binary"):
                if TONEMAP_NAME.search(call_name(node) or "") or self._tonemap_form(node):
                    return True
        return False

    def _tonemap_form(self, node: Tree) -> bool:
        text = self.ctx.node_text
        op = binary_op(node)
        if op == "/":
            ratio = Binary(node)
            top = " ".join(text(ratio.left).split())
            parts = operands(ratio.right, "+")
            # x / (1 + x), x / (x + k): Reinhard and its variants
            if len(parts) >= 2 and top in {" ".join(text(p).split()) for p in parts}:
                return True
        if op == "-":
            difference = Binary(node)
            if const_value(difference.left) == 1.0:
                return call_name(difference.right) == "exp"  # 1 - exp(-k x): exponential
        if call_name(node) in ("clamp", "min", "saturate", "smoothstep"):
            return False
        return False


def output_writes(fn: Function, out: str) -> list[Tree]:
    return [n for n in walk_kind(fn.body, "assignment") if root_var(Assignment(n).target) == out]


def product_factors(node: Node) -> tuple[list[Node], list[Node]]:
    """Numerators and denominators of a chain of * and / (`a * b / c` -> [a, b], [c])."""
    top: list[Node] = []
    bottom: list[Node] = []
    stack: list[tuple[Node, bool]] = [(node, True)]
    while stack:
        item, up = stack.pop()
        op = binary_op(item)
        if op in ("*", "/"):
            product = Binary(item)  # type: ignore[arg-type]
            stack.append((product.left, up))
            stack.append((product.right, up if op == "*" else not up))
        else:
            (top if up else bottom).append(item)
    return top, bottom


def is_lobe(node: Node, fn: Function) -> bool:
    if call_name(node) == "pow":
        return cosine_of(call_args(node)[0], fn) in ("NH", "LV")  # type: ignore[arg-type]
    return False


def rough_bound(node: Node, fn: Function, names: dict[str, float], depth: int = 6) -> float | None:
    """A rough upper bound of a light term from its constants: cosines, lobes and values the
    code does not say are taken as at most 1, so only explicit intensities raise it; None
    when a divisor is not a constant."""
    if depth <= 0 or not isinstance(node, Tree):
        return 1.0
    value = const_value(node, names)
    if value is not None:
        return abs(value)
    if node.data == "constructor":
        values = [const_value(a) for a in call_args(node)]
        known = [abs(v) for v in values if v is not None]
        return max(known) if known and len(known) == len(values) else 1.0
    if node.data == "variable":
        resolved = resolve(node, fn, 1)
        return 1.0 if resolved is node else rough_bound(resolved, fn, names, depth - 1)
    op = binary_op(node)
    if op in ("*", "/"):
        top, bottom = product_factors(node)
        result = 1.0
        for factor in top:
            b = rough_bound(factor, fn, names, depth - 1)
            if b is None:
                return None
            result *= b
        for factor in bottom:
            divisor = const_value(factor, names)
            if divisor is None:
                plus = binary_op(factor) == "+"
                divisor = rough_bound(factor, fn, names, depth - 1) if plus else None
            if not divisor:
                return None
            result /= divisor
        return result
    if op == "+":
        parts = [rough_bound(p, fn, names, depth - 1) for p in operands(node, "+")]
        return None if any(p is None for p in parts) else sum(parts)  # type: ignore[arg-type]
    if op == "-":
        return rough_bound(Binary(node).left, fn, names, depth - 1)
    if call_name(node) == "mix" and len(call_args(node)) == 3:
        ends = [rough_bound(a, fn, names, depth - 1) for a in call_args(node)[:2]]
        return None if None in ends else max(ends)  # type: ignore[type-var]
    if call_name(node) == "clamp" and len(call_args(node)) == 3:
        hi = const_value(call_args(node)[2])
        return abs(hi) if hi is not None else 1.0
    return 1.0


def _alpha_of(ctx: LintContext, fn: Function, write: Tree) -> Node | None:
    """The alpha a write of the output (or of the variable it copies) stores, when it says."""
    assignment = Assignment(write)
    target, value = assignment.target, assignment.value
    if assignment.op != "=":
        return None
    field = Field.cast(target)
    if field is not None:
        return value if field.name in ("w", "a") else None
    if isinstance(value, Tree) and value.data == "constructor":
        args = call_args(value)
        if len(args) in (2, 4) and expression_types(ctx).type_of(args[-1]) in ("float", "int"):
            return args[-1]
    return None


def _non_constant(ctx: LintContext, node: Node) -> bool:
    if const_value(node, global_constants(ctx)) is not None:
        return False
    known = semantic_model(ctx).range_of(node)
    return known.lo != known.hi


def _state_store(fn: Function, coord: str | None) -> bool:
    """`if (ivec2(fragCoord) == ivec2(0)) fragColor = ...;`: a texel keeps data for the next
    frame (a buffer pass)."""
    if coord is None:
        return False
    for node in walk_kind(fn.body, "if_statement"):
        branch = IfStatement(node)
        cond = branch.condition
        if not any(binary_op(c) == "==" for c in walk_kind(cond, "binary")):
            continue
        if coord not in names_of(cond):
            continue
        if walk_kind(branch.then_branch, "assignment"):
            return True
    return False


def names_of(node: Node) -> set[str]:
    if not isinstance(node, Tree):
        return set()
    return {str(variable_name(s)) for s in walk_kind(node, "variable")}


def _packed_normal(node: Node, fn: Function) -> bool:
    """`n * 0.5 + 0.5` (or 0.5 + 0.5 * n) of a normal: a normal stored as data."""
    for sub in walk_kind(node, "binary"):
        if binary_op(sub) != "+":
            continue
        parts = operands(sub, "+")
        if not any(const_value(p) == 0.5 for p in parts):
            continue
        for p in parts:
            top, _ = product_factors(p)
            if any(const_value(f) == 0.5 for f in top) and any(
                vector_role(f, fn) == "N" for f in top
            ):
                return True
    return False


def _sources(ctx: LintContext, fn: Function, value: Node) -> list[tuple[Function, Tree]]:
    """The plain assignments that build the value written: itself, the writes of a variable it
    copies, and those of the variable a called function of the shader returns."""
    found: list[tuple[Function, Tree]] = []
    defined = function_map(ctx)
    name = var_name(value)
    if name is not None and name in fn.locals:
        found += [(fn, w) for w in output_writes(fn, name)]
    callee = call_name(value)
    if callee in defined:
        other = defined[callee]
        for node in walk_kind(other.body, "jump_statement"):
            value = JumpStatement(node).value
            if value is not None:
                returned = var_name(value)
                if returned is not None and returned in other.locals:
                    found += [(other, w) for w in output_writes(other, returned)]
    return found


def _palette(ctx: LintContext, node: Node, fn: Function, depth: int = 10) -> bool:
    """A colour picked from constant colours: a constant, a mix of palette colours (by any
    key, such as a dither threshold), a palette colour scaled by a constant, or a local whose
    every value is one (an ink/paper palette). Its colours are display values already."""
    if depth <= 0:
        return False
    if is_compile_time(ctx, node, fn):
        return True
    name = call_name(node)
    args = call_args(node) if name else []  # type: ignore[arg-type]
    if name == "mix" and len(args) == 3:
        return all(_palette(ctx, a, fn, depth - 1) for a in args[:2])
    if isinstance(node, Tree) and node.data == "constructor":
        return all(_palette(ctx, a, fn, depth - 1) for a in call_args(node))
    if binary_op(node) == "*":
        parts = operands(node, "*")
        return all(_palette(ctx, p, fn, depth - 1) for p in parts)
    callee = function_map(ctx).get(name or "")
    if callee is not None:  # a function of the shader that returns palette colours only
        returned = [v for r in walk_kind(callee.body, "jump_statement")
                    if (v := JumpStatement(r).value) is not None]  # fmt: skip
        return bool(returned) and all(_palette(ctx, r, callee, depth - 1) for r in returned)
    local = var_name(node)
    if local is None or local not in fn.locals:
        return False
    values: list[Node] = []
    for sub in walk_kind(fn.body, "declarator", "assignment"):
        if sub.data == "declarator":
            declarator = Declarator(sub)
            init = declarator.initializer
            if declarator.name == local and init is not None:
                values.append(init)
        elif sub.data == "assignment":
            assignment = Assignment(sub)
            if root_var(assignment.target) != local:
                continue
            if assignment.op != "=" or variable_name(assignment.target) is None:
                return False
            values.append(assignment.value)
    return bool(values) and all(_palette(ctx, v, fn, depth - 1) for v in values)


# A written value at least this far above 1, with no tone map, is not meant for the display:
# a real image pass would be a white screen, so a later pass exposes and encodes it.
RADIANCE = 10.0


def data_output(ctx: LintContext) -> str:
    """Why the output is data for another pass rather than a displayed image, or "": a
    non-constant alpha (a depth, a blur strength, a sample count: the Image pass ignores
    alpha), a texel that stores state (`if (ivec2(fragCoord) == ivec2(0))`), a normal packed
    as n * 0.5 + 0.5, or radiance far above 1 (a real image pass would be a white screen)."""
    found = main_image(ctx)
    if found is None:
        return ""
    fn, out = found
    coord = next((p for p in fn.param_order if p != out), None)
    writes = output_writes(fn, out)
    alphas: list[Node] = []
    sources: list[tuple[Function, Tree]] = []
    for write in writes:
        alpha = _alpha_of(ctx, fn, write)
        if alpha is not None:
            alphas.append(alpha)
        assignment = Assignment(write)
        if assignment.op == "=":
            sources += [(fn, write)] + _sources(ctx, fn, assignment.value)
    if not alphas:  # the alpha of what the output copies
        for owner, source in sources:
            if owner is not fn or source not in writes:
                alpha = _alpha_of(ctx, owner, source)
                if alpha is not None:
                    alphas.append(alpha)
    if alphas and _non_constant(ctx, alphas[-1]):
        return "it stores data in alpha"
    if _state_store(fn, coord):
        return "it stores state in a texel"
    if any(_packed_normal(Assignment(s).value, owner) for owner, s in sources):
        return "it packs a normal as data"
    if writes and all(_palette(ctx, Assignment(w).value, fn) for w in writes):
        return "it writes a palette of constant colours"
    if not ColourOutput(ctx).any_tonemap():
        names = global_constants(ctx)
        for write in writes:
            value = ColourOutput(ctx)._peel(Assignment(write).value)
            hi = rough_bound(value, fn, names)
            if hi is not None and hi >= RADIANCE:
                return "it writes radiance far above 1 without a tone map (a later pass shows it)"
    return ""
