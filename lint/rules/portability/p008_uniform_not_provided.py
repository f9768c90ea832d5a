"""P008 uniform-not-provided."""

from __future__ import annotations

import operator
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

from lark import Token, Tree

from glint.compiler.glsl.ast import (
    Declarator,
    ForStatement,
    IfStatement,
    VariableDeclaration,
    binary_parts,
    declarator_initializer,
    first_child,
    if_parts,
    leaf_text,
    loop_condition,
    operand,
    ternary_parts,
)
from glint.compiler.glsl.ast import operator as operator_of
from glint.compiler.target.shadertoy import SHADERTOY_TYPES

from ...analysis.syntax import int_value, spec_text
from ...context import LintContext, Node
from ...finding import Finding
from .. import Rule, register

# The statements (and the expression) that test a condition (_test_of).
_TESTS = frozenset(
    {"if_statement", "switch_statement", "ternary", "for_statement", "while_statement",
     "do_statement"}
)  # fmt: skip
_LOOPS = ("for_statement", "while_statement", "do_statement")
_ZERO = {"bool": "false", "int": "0", "uint": "0u", "float": "0.0"}


@register
class UniformNotProvided(Rule):
    """Finds `uniform` variables that ShaderToy does not provide (anything but `iTime`,
    `iResolution`, `iMouse`, `iChannel0`..`iChannel3` and its other inputs) and that the shader
    reads: ShaderToy never sets them, so they are always zero (false, 0, a zero vector).

    Such uniforms come from shaders written for another host (a GUI toggle such as `u_mode`, or
    glslsandbox's `time` and `resolution`) and pasted into ShaderToy. Uniforms never read and
    samplers (which ShaderToy's texture units alias) are not reported; the rule runs only for
    the ShaderToy target. The message says what the zero does: the branch or loop it kills
    (its tests evaluated with the uniform at zero, a for loop's counter at its start), else a
    division by it, else a product it wipes out, else where it is first read.

    Why is this bad?
        Nothing assigns the uniform, so every test of it takes the same way on every frame: a
        `uniform bool u_reflections` turns reflections off for good, a `uniform int u_mode`
        always selects mode 0, a `uniform float time` freezes the animation. What the author
        meant to switch on is dead code.

    Example:
        uniform bool u_shadows;
        ...
        if (u_shadows) col *= shadow(p, l);

    Use instead:
        const bool u_shadows = true;  // or #define, with the value meant
        ...
        if (u_shadows) col *= shadow(p, l);

    Fix safety:
        No fix: which value was meant is the author's choice.

    References:
        - ShaderToy's How To (https://www.shadertoy.com/howto): the inputs it declares
        - GLSL ES 3.00 spec §4.3.5 (Uniform): a uniform not set by the application is zero
    """

    code = "P008"
    name = "uniform-not-provided"
    certainty = "certain"
    category = "portability"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        if ctx.target != "shadertoy":
            return  # another host may set it
        declared: dict[str, tuple[Token, str]] = {}
        for node in ctx.tree.children:
            declaration = VariableDeclaration.cast(node)
            if declaration is None or "uniform" not in declaration.type.qualifiers:
                continue
            typ = spec_text(declaration.type.type.syntax)
            if typ.startswith(("sampler", "isampler", "usampler")) or not typ:
                continue  # a sampler reads texture unit 0, which ShaderToy binds to iChannel0
            for decl in declaration.declarators:
                if declarator_initializer(decl.syntax) is not None:
                    continue  # a uniform with a default value
                name = decl.name_token
                arrays = 1 if decl.array is not None else 0
                if str(name) not in SHADERTOY_TYPES:
                    declared[str(name)] = (name, typ + "[]" * arrays)
        if not declared:
            return
        reads = _reads(ctx, set(declared))
        for name, (token, typ) in declared.items():
            if name not in reads:
                continue  # never read: harmless
            if _falls_back(ctx, name, typ, reads[name].every):
                continue  # the shader replaces the zero itself: `u == 0.0 ? DEFAULT : u`
            zero = _ZERO.get(typ, f"{typ}(0)")
            message = (
                f"uniform {typ} {name} is never set by ShaderToy: it is always {zero}"
                f"{_effect(ctx, name, typ, zero, reads[name])}; "
                "make it a const or a #define with the value meant"
            )
            yield self.report(ctx, token, message)


@dataclass
class _Reads:
    """How the shader reads one uniform: its first read, the tests (conditions of an if, a
    loop, a switch or a ?:) that read it with their statements, the first division by it."""

    first: Tree
    every: list[Tree] = field(default_factory=list)
    tests: list[tuple[Tree, Tree]] = field(default_factory=list)
    divisor: Tree | None = None
    product: Tree | None = None


def _effect(ctx: LintContext, name: str, typ: str, zero: str, reads: _Reads) -> str:
    """What the zero value does, most telling first: a branch or loop it kills, a division by
    it, a test that merely reads it, else where it is first read."""
    told: list[str] = []
    for test, statement in reads.tests:
        value = _value(test, _bindings(name, typ, statement))
        if statement.data == "for_statement" and value is True:
            value = None  # true on the first iteration only: the counter moves on
        dead = _dead(ctx, test, statement, value)
        if dead:
            return dead
        told.append(_shown(ctx, test, statement, value, zero))
    if reads.divisor is not None:
        shown = _short(ctx.node_text(reads.divisor))
        return f", so `{shown}` at line {ctx.span(reads.divisor)[0]} divides by zero"
    if reads.product is not None:
        shown = _short(ctx.node_text(reads.product))
        return f", so `{shown}` at line {ctx.span(reads.product)[0]} is always zero"
    if told:
        return told[0]
    return f" wherever it is read (first at line {ctx.span(reads.first)[0]})"


def _dead(ctx: LintContext, test: Tree, statement: Tree, value: object) -> str | None:
    """The code the test's constant value makes unreachable, said in words; None if none."""
    if not isinstance(value, bool):
        return None
    shown = _short(ctx.node_text(test))
    line = ctx.span(test)[0]
    kind = statement.data
    if kind == "if_statement":
        if not value:
            return f", so the branch of `if ({shown})` at line {line} never runs"
        other = IfStatement(statement).else_branch
        if other is not None:
            else_line = ctx.span(other)[0]
            return f", so the else branch of `if ({shown})` (line {else_line}) never runs"
        return None
    if kind in ("for_statement", "while_statement") and not value:
        return f", so the loop at line {line} never runs: `{shown}` is false from the start"
    if kind == "ternary":
        which = "first" if value else "second"
        return f", so `{shown} ? ... : ...` at line {line} always takes its {which} value"
    return None


def _shown(ctx: LintContext, test: Tree, statement: Tree, value: object, zero: str) -> str:
    """The test with what it reads when it kills nothing (or its value is unknown)."""
    shown = _short(ctx.node_text(test))
    line = ctx.span(test)[0]
    if isinstance(value, bool):
        return f", so `{shown}` at line {line} is always {'true' if value else 'false'}"
    if statement.data == "switch_statement" and value is not None:
        return f", so `switch ({shown})` at line {line} always switches on {zero}"
    return f", so the test `{shown}` at line {line} always reads it as {zero}"


def _short(text: str) -> str:
    shown = " ".join(text.split())
    return shown if len(shown) <= 40 else shown[:37] + "..."


# The zero of each scalar type, as _value computes with it (vectors: not evaluated).
_ZERO_VALUE: dict[str, object] = {"bool": False, "int": 0, "uint": 0, "float": 0.0}


def _bindings(name: str, typ: str, statement: Tree) -> dict[str, object]:
    """The values known when the test is first evaluated: the uniform is zero and a for loop's
    counter holds its literal initial value (on the first iteration)."""
    values: dict[str, object] = {}
    if typ in _ZERO_VALUE:
        values[name] = _ZERO_VALUE[typ]
    if statement.data == "for_statement":
        init = ForStatement(statement).init
        for decl in init.find_data("declarator"):
            initializer = declarator_initializer(decl)
            if initializer is not None and Declarator(decl).array is None:
                value = _value(initializer, {})
                if value is not None:
                    values[Declarator(decl).name] = value
    return values


_COMPARE: dict[str, Callable[[Any, Any], bool]] = {
    "==": operator.eq,
    "!=": operator.ne,
    "<": operator.lt,
    "<=": operator.le,
    ">": operator.gt,
    ">=": operator.ge,
}
_ARITHMETIC: dict[str, Callable[[Any, Any], Any]] = {
    "+": operator.add,
    "-": operator.sub,
    "*": operator.mul,
}


def _value(node: Node, values: dict[str, object]) -> object:
    """The node's constant value (bool, int or float) given the known variables; None where
    anything else decides it. `a && b` is false when either side is, whatever the other."""
    if not isinstance(node, Tree):
        return None
    kind = node.data
    if kind == "variable":
        return values.get(leaf_text(node))
    if kind == "bool_literal":
        return leaf_text(node) == "true"
    if kind == "int_literal":
        return int_value(leaf_text(node))
    if kind == "float_literal":
        try:
            return float(leaf_text(node).rstrip("fFlL"))
        except ValueError:
            return None
    if kind == "unary":
        op, value = operator_of(node), _value(operand(node), values)
        if op == "!" and isinstance(value, bool):
            return not value
        if op == "-" and isinstance(value, (int, float)) and not isinstance(value, bool):
            return -value
        return value if op == "+" else None
    if kind != "binary":
        return None
    left_node, op, right_node = binary_parts(node)
    left, right = _value(left_node, values), _value(right_node, values)
    if op in ("&&", "||"):
        absorbing = op == "||"  # true absorbs an or, false an and
        if left is absorbing or right is absorbing:
            return absorbing
        if isinstance(left, bool) and isinstance(right, bool):
            return not absorbing
        return None
    if left is None or right is None:
        return None
    if op in _COMPARE:
        return _COMPARE[op](left, right)
    if op in _ARITHMETIC and not isinstance(left, bool) and not isinstance(right, bool):
        return _ARITHMETIC[op](left, right)
    return None


def _reads(ctx: LintContext, names: set[str]) -> dict[str, _Reads]:
    """For each name read in a function: its first read, the tests that read it (with their
    statement) and the first division by it."""
    parents = ctx.parents()
    found: dict[str, _Reads] = {}
    for node in ctx.nodes("variable"):
        name = leaf_text(node)
        if name not in names:
            continue
        symbol = ctx.bindings.symbol_of(node)
        if symbol is not None and "uniform" not in symbol.qualifiers:
            continue  # a local or parameter of the same name hides the uniform here
        reads = found.setdefault(name, _Reads(node))
        reads.every.append(node)
        test = _condition_of(node, parents)
        if test is not None:
            reads.tests.append(test)
        parent = parents.get(id(node))
        if reads.divisor is None and parent is not None and _divides_by(parent, node):
            reads.divisor = parent
        if reads.product is None and parent is not None and _multiplies_by(parent, node):
            reads.product = parent
    return found


def _falls_back(ctx: LintContext, name: str, typ: str, reads: list[Tree]) -> bool:
    """Whether the shader handles the unset value itself: every read of the uniform is in a
    `?:` or an `if` whose condition, with the uniform zero, picks the branch that does not read
    it while the other branch does (`float b = uBrightness == 0.0 ? DEFAULT_BRIGHTNESS :
    uBrightness;`), or in such a condition. A mode switch (`if (u_mode == 0) A else B`) is no
    fallback: the zero still picks the mode."""
    if typ not in _ZERO_VALUE:
        return False
    zero = {name: _ZERO_VALUE[typ]}
    parents = ctx.parents()
    guarded: set[int] = set()  # the reads inside a guard that handles the zero
    for node in reads:
        current: Node = node
        while (parent := parents.get(id(current))) is not None:
            if parent.data in ("ternary", "if_statement"):
                test, yes, no = (
                    ternary_parts(parent) if parent.data == "ternary" else if_parts(parent)
                )
                value = _value(test, zero)
                taken, other = (yes, no) if value is True else (no, yes)
                if (
                    value is not None
                    and _uses_value(other, name, parents)
                    and not _reads_name(taken, name)
                ):
                    guarded |= {id(r) for r in reads if _inside(r, parent, parents)}
                    break
            current = parent
    return bool(reads) and all(id(r) in guarded for r in reads)


def _reads_name(node: Node | None, name: str) -> bool:
    return isinstance(node, Tree) and any(leaf_text(v) == name for v in node.find_data("variable"))


def _uses_value(node: Node | None, name: str, parents: dict[int, Tree]) -> bool:
    """Whether the node uses the uniform's value, not only tests it (an else-if chain on a
    mode tests it in every branch)."""
    if not isinstance(node, Tree):
        return False
    reads = [v for v in node.find_data("variable") if leaf_text(v) == name]
    return any(_condition_of(v, parents) is None for v in reads)


def _inside(node: Tree, ancestor: Tree, parents: dict[int, Tree]) -> bool:
    current: Node = node
    while (parent := parents.get(id(current))) is not None:
        if parent is ancestor:
            return True
        current = parent
    return False


def _divides_by(parent: Tree, node: Tree) -> bool:
    """Whether the parent divides by the node: `a / node` or `a /= node`."""
    if parent.data not in ("binary", "assignment"):
        return False
    _, op, right = binary_parts(parent)
    return right is node and op in ("/", "/=")


def _multiplies_by(parent: Tree, node: Tree) -> bool:
    """Whether the parent multiplies something by the node, `a * node` or `node * a`: the zero
    wipes out `a` (a scale by a literal, `2.0 * node`, wipes out nothing worth naming)."""
    if parent.data != "binary":
        return False
    left, op, right = binary_parts(parent)
    if op != "*":
        return False
    other = right if left is node else left
    return not (isinstance(other, Tree) and other.data in ("int_literal", "float_literal"))


def _test_of(statement: Tree) -> Node | None:
    """The condition a statement tests (a switch: its selector): for a for loop the parser's
    condition, None in `for (;; i++)` (whose lone middle part is the update)."""
    if statement.data in _LOOPS:
        return loop_condition(statement)
    return first_child(statement)  # an if, a switch or a ?:


def _condition_of(node: Tree, parents: dict[int, Tree]) -> tuple[Tree, Tree] | None:
    """The condition expression the node is part of and its statement (if, loop, switch or
    ?:), if it is in one."""
    current: Tree = node
    while (parent := parents.get(id(current))) is not None:
        if parent.data in _TESTS:
            return (current, parent) if _test_of(parent) is current else None
        if parent.data in ("compound_statement", "function_definition"):
            return None
        current = parent
    return None
