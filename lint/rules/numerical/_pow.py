"""What N001 and N020 share: the evidence that a pow base is negative, and the message."""

from __future__ import annotations

from collections.abc import Callable, Iterator

from lark import Tree

from glint.compiler.glsl import types as T

from ...analysis import witness as W
from ...analysis.model import semantic_model
from ...analysis.ranges import _num
from ...analysis.syntax import call_args, call_name
from ...analysis.values import Value
from ...context import LintContext, Node
from ._common import SLACK, builtin_calls, is_raw_dot, reaches_below

_COMPONENTS = "xyzw"


def negative_evidence(base: Value) -> str | None:
    """Why the base is negative at a reachable input, or None: a component whose whole range
    is <= 0 and below 0 somewhere, or a witness (witness.py) below 0: the first frame, sin or
    cos of an unbounded argument, a dot product with a direction."""
    n = T.size(base.type) or 1
    comps = base.parts(n)
    for i, c in enumerate(comps):
        if c.hi <= 0 and c.lo < -SLACK:
            where = f" in {_COMPONENTS[i]}" if n > 1 and i < 4 else ""
            return f"is never above 0{where} (range {c.describe()})"
    for i, (low, _) in enumerate(W.pairs(base.wit, comps)):
        if low < 0:
            assert base.wit is not None  # a constant component is caught above
            where = f" in {_COMPONENTS[i]}" if n > 1 and i < 4 else ""
            # how negative is known only where it is not a mere sign (a dot product, a ray)
            value = f" (down to {_num(low)})" if low < -W.SOME else ""
            return f"is negative{where} {base.wit.why}{value}"
    return None


# Builtins whose result is never negative, whatever their arguments (texture: no input of a
# texture is known, so nothing can witness a negative texel either).
_NEVER_NEGATIVE = frozenset(
    {"abs", "length", "distance", "sqrt", "inversesqrt", "exp", "exp2", "fract", "smoothstep",
     "step", "texture", "textureLod", "textureGrad", "textureProj", "texelFetch"}
)  # fmt: skip


def never_negative(node: Node) -> bool:
    """Whether the expression is plainly never negative, by its form alone: a literal, one of
    `_NEVER_NEGATIVE`, `max` with a literal >= 0, `clamp` with a lower bound literal >= 0."""
    if not isinstance(node, Tree):
        return False
    if node.data in ("float_literal", "int_literal"):  # a negative number is a unary minus
        return True
    if node.data != "call":
        return False
    name, args = call_name(node), call_args(node)
    if name in _NEVER_NEGATIVE:
        return True
    if name == "max" and len(args) == 2:
        return any(_literal_at_least_zero(a) for a in args)
    if name == "clamp" and len(args) == 3:
        return _literal_at_least_zero(args[1])
    return False


def _literal_at_least_zero(node: Node) -> bool:
    return isinstance(node, Tree) and node.data in ("float_literal", "int_literal")


def pow_bases(
    ctx: LintContext, skip: Callable[[Node], bool] | None = None
) -> Iterator[tuple[Tree, Node, Value]]:
    """Every builtin pow call with its base and the base's value, leaving out the bases `skip`
    accepts. The model, the expensive part, is built only for a file with a pow to judge: most
    files call none, or only on bases like `max(x, 0.0)`."""
    calls = [(call, args) for call, _ in builtin_calls(ctx, "pow")
             if len(args := call_args(call)) == 2 and not (skip and skip(args[0]))]  # fmt: skip
    if not calls:
        return
    model = semantic_model(ctx)
    for call, args in calls:
        yield call, args[0], model.value_of(args[0])


def range_reaches_negative(base: Value) -> bool:
    """The range reaches below 0 by interval arithmetic (a finite lower bound under 0), or the
    base is a raw dot product that may be negative: N020's test."""
    return reaches_below(base.range, 0.0) or (is_raw_dot(base) and base.range.may_be_negative)
