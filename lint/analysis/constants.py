"""Values known when the shader is compiled: literal expressions folded (`1.0 / 2.2`,
`8.0 * PI`), the file's `const` globals, and whether an expression is a compile-time constant
or a value the semantic model knows exactly (work the compiler folds away)."""

from __future__ import annotations

from lark import Tree

from glint.compiler.glsl.ast import (
    Field,
    Unary,
    binary_parts,
    token_text,
    variable_name,
)

from ..context import LintContext, Node
from .functions import Function
from .model import semantic_model
from .syntax import binary_op, call_args, call_name

# --- literal expressions and const globals --------------------------------------------------


def const_value(node: Node, names: dict[str, float] | None = None) -> float | None:
    """The value of a literal expression (`1.0 / 2.2`, `vec3(0.4545)`, `-2.`), else None;
    `names` gives the values of named constants (`8.0 * PI`)."""
    if not isinstance(node, Tree):
        return None
    if names and node.data == "variable":
        return names.get(str(variable_name(node)))
    if node.data in ("float_literal", "int_literal"):
        text = str(token_text(node)).rstrip("fFuU")
        try:
            return float(int(text, 0)) if node.data == "int_literal" else float(text)
        except ValueError:
            return None
    if node.data == "unary":
        unary = Unary(node)
        inner = const_value(unary.operand, names)
        sign = unary.op
        if inner is None or sign not in "+-":
            return None
        return -inner if sign == "-" else inner
    if node.data == "constructor":
        args = call_args(node)
        values = [const_value(a, names) for a in args]
        if values and all(v is not None and v == values[0] for v in values):
            return values[0]
        return None
    op = binary_op(node)
    if op in ("+", "-", "*", "/"):
        left_node, _, right_node = binary_parts(node)
        left = const_value(left_node, names)
        right = const_value(right_node, names)
        if left is None or right is None:
            return None
        if op == "+":
            return left + right
        if op == "-":
            return left - right
        if op == "*":
            return left * right
        return left / right if right else None
    return None


def global_const_inits(ctx: LintContext) -> dict[str, Node]:
    """The initializers of `const` globals, by name, in source order (made once per file)."""
    return ctx.memo(_global_const_inits)


def _global_const_inits(ctx: LintContext) -> dict[str, Node]:
    values: dict[str, Node] = {}
    if ctx.tree is not None:
        for symbol in ctx.bindings.symbols:
            init = symbol.initializer
            if symbol.kind == "global" and symbol.is_const and isinstance(init, Tree):
                values[symbol.name] = init
    return values


def global_constants(ctx: LintContext) -> dict[str, float]:
    """Values of scalar `const` globals with literal initializers (`const float PI = ...`)."""
    return ctx.memo(_global_constants)


def _global_constants(ctx: LintContext) -> dict[str, float]:
    values: dict[str, float] = {}
    for name, init in global_const_inits(ctx).items():  # in order: later ones use earlier
        value = const_value(init, values)
        if value is not None:
            values[name] = value
    return values


# --- compile-time constants ------------------------------------------------------------------


_FOLDABLE_CALLS = {
    "normalize", "length", "sqrt", "inversesqrt", "pow", "exp", "exp2", "log", "log2", "sin",
    "cos", "tan", "radians", "degrees", "abs", "min", "max", "clamp", "mix", "dot", "cross",
    "floor", "fract", "mod", "sign", "step", "smoothstep",
}  # fmt: skip


def is_compile_time(ctx: LintContext, node: Node, fn: Function | None, depth: int = 6) -> bool:
    """Whether every value the expression can take is known when the shader is compiled: it is
    built only from literals (macros are expanded already), `const` names, locals whose one
    value is such an expression, and builtin calls of those. The compiler folds it: no
    instruction runs for it."""
    if depth <= 0 or not isinstance(node, Tree):
        return False
    if node.data in ("float_literal", "int_literal", "bool_literal"):
        return True
    if node.data == "variable":
        name = str(variable_name(node))
        if fn is not None and (name in fn.locals or name in fn.params):
            value = fn.value_of(name) if name not in fn.params else None
            return value is not None and is_compile_time(ctx, value, fn, depth - 1)
        init = global_const_inits(ctx).get(name)
        return init is not None and is_compile_time(ctx, init, None, depth - 1)
    if node.data == "constructor":
        return all(is_compile_time(ctx, a, fn, depth - 1) for a in call_args(node))
    if node.data == "call":
        return call_name(node) in _FOLDABLE_CALLS and all(
            is_compile_time(ctx, a, fn, depth - 1) for a in call_args(node)
        )
    if node.data in ("binary", "unary", "field", "ternary"):
        if node.data == "field":
            kids = [Field(node).base]
        else:  # the operands, not the operator's token
            kids = [c for c in node.children if isinstance(c, Tree)]
        return bool(kids) and all(is_compile_time(ctx, k, fn, depth - 1) for k in kids)
    return False


def known_value(ctx: LintContext, node: Node) -> bool:
    """Whether the model knows the value exactly where it is read (every component a single
    number): a variable that still holds the constant it was given, as in `vec3 L =
    vec3(7.4, 5.6, 4.4); L = pow(L, vec3(5.0));`. Constant propagation folds what reads it."""
    value = semantic_model(ctx).value_of(node)
    parts = value.comps if value.comps is not None else (value.range,)
    return all(p.lo == p.hi for p in parts)


def folded(ctx: LintContext, node: Node, fn: Function | None) -> bool:
    """A compile-time constant (is_compile_time) or a value the model knows exactly."""
    return is_compile_time(ctx, node, fn) or known_value(ctx, node)
