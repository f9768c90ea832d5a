"""Performance: work the GPU does for nothing (pow for a square, loop-invariant calls inside
a march loop, normalize of what is already unit length). Findings are advice (info)."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from ..context import LintContext, Node, walk
from ..finding import Finding, Fix
from . import Rule, register
from ._lighting_terms import (
    Function,
    call_args,
    call_name,
    const_value,
    functions,
    is_simple,
    is_unit,
    names_in,
    out_param_map,
    parents,
    resolve,
    var_name,
    writes_of,
)

# Parents in which `a * b` needs no parentheses: it is a whole argument, initializer, right
# side or statement, or an operand of + / - (which bind more loosely than *).
_OPEN_PARENTS = {"arguments", "declarator", "jump_statement", "expression_statement", "ternary"}


def _needs_parens(node: Node, parent: Tree | None) -> bool:
    if parent is None or parent.data in _OPEN_PARENTS:
        return False
    if parent.data == "assignment":
        return parent.children[0] is node
    if parent.data == "index":
        return parent.children[0] is node
    if parent.data == "binary":
        op = str(parent.children[1])
        # a*a + b, b - a*a, a*a * b and a*a / b group as written (left associative)
        return not (op in ("+", "-") or (op in ("*", "/") and parent.children[0] is node))
    return True


@register
class PowSmallInteger(Rule):
    """Finds `pow(x, 2.0)` to `pow(x, 5.0)` of a plain variable or swizzle, where a few
    multiplies say the same thing.

    Why it matters: pow is exp2(y·log2(x)) on most GPUs, two transcendental operations and a
    multiply, and less accurate than x·x. Many drivers rewrite small constant exponents
    themselves, but not all (and not at every precision), so spelling out the product is never
    slower. Only plain variables and swizzles are reported, where the product repeats no work
    and no side effect: `pow(clamp(1.0 - c, 0.0, 1.0), 5.0)` would need a temporary of a type
    the fix cannot always name, so it is left alone.

    The fix is safe: for x ≥ 0 the product is the same value (more exact); for x < 0, pow is
    undefined in GLSL while the product is defined, so only code that was already wrong can
    change.

    Example:
        float spec = pow(NoH, 2.0) * k;

    Fix:
        float spec = NoH * NoH * k;
    """

    code = "PF001"
    name = "pow-small-integer"
    category = "performance"
    severity = "info"
    fixable = "safe"

    _FORMS = {
        2: "{x} * {x}",
        3: "{x} * {x} * {x}",
        4: "({x} * {x}) * ({x} * {x})",
        5: "{x} * {x} * {x} * {x} * {x}",
    }

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        up = parents(ctx.tree)
        for node in ctx.nodes("call"):
            if call_name(node) != "pow":
                continue
            args = call_args(node)
            if len(args) != 2 or not is_simple(args[0]):
                continue
            exponent = const_value(args[1])
            if exponent not in (2.0, 3.0, 4.0, 5.0):
                continue
            n = int(exponent)  # type: ignore[arg-type]
            base = ctx.node_text(args[0])
            product = self._FORMS[n].format(x=base)
            text = f"({product})" if _needs_parens(node, up.get(id(node))) else product
            edit = ctx.replace(node, text)
            fix = Fix(f"write {product}", (edit,)) if edit else None
            yield self.report(
                ctx,
                node,
                f"pow({base}, {n}.0) costs two transcendentals; {product} is exact and cheaper",
                fix,
            )


# Builtins worth hoisting: transcendental, square roots, texture fetches, normalisation.
_EXPENSIVE = {
    "normalize",
    "length",
    "distance",
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "sinh",
    "cosh",
    "tanh",
    "pow",
    "exp",
    "exp2",
    "log",
    "log2",
    "sqrt",
    "inversesqrt",
    "texture",
    "textureLod",
    "textureGrad",
    "texelFetch",
    "textureProj",
    "inverse",
    "determinant",
    "reflect",
    "refract",
}
# Expression nodes a hoisted value can be (statements and declarations are not).
_EXPRESSIONS = {"call", "binary", "unary", "constructor", "field", "index", "ternary"}
_LOOPS = {"for_statement", "while_statement", "do_statement"}


def _global_names(ctx: LintContext) -> tuple[set[str], set[str]]:
    """Names of global constants (and uniforms), and of other globals."""
    constant: set[str] = set()
    other: set[str] = set()
    assert ctx.tree is not None
    for node in ctx.tree.children:
        if not (isinstance(node, Tree) and node.data == "variable_declaration"):
            continue
        qual = ""
        for child in node.children:
            if isinstance(child, Tree) and child.data == "fully_specified_type":
                qual = (
                    " ".join(str(t) for t in child.children[0].children)
                    if (
                        isinstance(child.children[0], Tree)
                        and child.children[0].data == "type_qualifier"
                    )
                    else ""
                )
            elif isinstance(child, Tree) and child.data == "declarator":
                name = str(child.children[0])
                (constant if ("const" in qual or "uniform" in qual) else other).add(name)
    return constant, other


def _local_consts(fn: Function) -> set[str]:
    found = set()
    for node in walk(fn.body):
        if node.data != "variable_declaration":
            continue
        spec = node.children[0]
        if (isinstance(spec, Tree) and isinstance(spec.children[0], Tree)
                and spec.children[0].data == "type_qualifier"
                and "const" in [str(t) for t in spec.children[0].children]):  # fmt: skip
            found |= {str(c.children[0]) for c in node.children[1:]
                      if isinstance(c, Tree) and c.data == "declarator"}  # fmt: skip
    return found


@register
class LoopInvariant(Rule):
    """Finds expensive work inside a loop that gives the same value on every iteration: a call
    to normalize, length, a trigonometric or exponential function or a texture fetch whose
    inputs are not changed by the loop.

    Why it matters: a raymarch or shadow loop runs up to hundreds of times per pixel; a
    normalize or texture fetch of loop-invariant inputs is paid on every step. Compilers hoist
    some of it, but not across a `break` or through a texture fetch.

    What counts as invariant: every variable the expression reads is neither written in the
    loop (assignment, ++/--, an out argument), nor declared inside it, nor a global that any
    function writes. Calls of the shader's own functions are never counted (they may be
    expensive, but proving them pure is out of scope), and expressions of constants only are
    left to the compiler, which folds them.

    Example:
        for (int i = 0; i < 64; i++) {
            float h = map(ro + rd * t);
            res = min(res, h / t * length(lightPos - ro));
            t += h;
        }

    Fix:
        float dist = length(lightPos - ro);
        for (int i = 0; i < 64; i++) { ... res = min(res, h / t * dist); ... }
    """

    code = "PF002"
    name = "loop-invariant-work"
    category = "performance"
    severity = "info"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        constants, other_globals = _global_names(ctx)
        outs = out_param_map(ctx)
        global_writes = set().union(*(f.written for f in functions(ctx))) & other_globals
        reported: list[tuple[int, int]] = []
        for fn in functions(ctx):
            fixed = constants | _local_consts(fn)
            for loop in walk(fn.body):
                if loop.data not in _LOOPS:
                    continue
                varying = set(global_writes)
                for node in walk(loop):
                    varying |= writes_of(node, outs)
                    if node.data == "declarator":
                        varying.add(str(node.children[0]))
                    elif node.data == "condition_declaration":
                        varying.add(str(node.children[1]))
                for expr in self._candidates(loop, varying, fixed, fn):
                    span = (expr.meta.start_pos, expr.meta.end_pos)
                    if any(a <= span[0] and span[1] <= b for a, b in reported):
                        continue
                    reported.append(span)
                    text = " ".join(ctx.node_text(expr).split())
                    if len(text) > 60:
                        text = text[:57] + "..."
                    yield self.report(
                        ctx,
                        expr,
                        f"`{text}` gives the same value on every iteration of the "
                        "loop; compute it once before the loop",
                    )

    def _candidates(
        self, loop: Tree, varying: set[str], fixed: set[str], fn: Function
    ) -> Iterator[Tree]:
        # The for-init runs once: only the condition, the increment and the body repeat.
        parts = loop.children[1:] if loop.data == "for_statement" else loop.children
        stack: list[Node] = list(reversed(parts))
        while stack:
            node = stack.pop()
            if not isinstance(node, Tree):
                continue
            if node.data == "assignment":
                stack.append(node.children[2])  # the target is written, never hoisted
                continue
            if node.data in _EXPRESSIONS and self._invariant(node, varying, fixed, fn):
                yield node
                continue
            stack.extend(reversed(node.children))

    def _invariant(self, node: Tree, varying: set[str], fixed: set[str], fn: Function) -> bool:
        names = names_in(node)
        if not names or names & varying:
            return False
        if names <= fixed:  # constants only: the compiler folds it
            return False
        costly = False
        for sub in walk(node):
            if sub.data in ("assignment", "prefix", "postfix"):
                return False
            if sub.data == "call":
                name = call_name(sub)
                if name is None or name not in _BUILTINS:
                    return False  # the shader's own function, or a call through an expression
                costly = costly or name in _EXPENSIVE
        return costly


_BUILTINS: set[str] = set()


def _load_builtins() -> None:
    from glint.compiler.glsl.builtins import BUILTIN_FUNCTIONS

    _BUILTINS.update(BUILTIN_FUNCTIONS)


_load_builtins()


def _unit_by_form(node: Node, fn: Function | None, consts: dict[str, Node], depth: int = 4) -> bool:
    """Unit length by construction: normalize(...), reflect of unit vectors, a negated unit
    vector, or a local or global constant whose one value is one of those."""
    if depth <= 0 or not isinstance(node, Tree):
        return False
    name = call_name(node)
    if name == "normalize":
        return True
    if name == "reflect":
        return all(_unit_by_form(a, fn, consts, depth - 1) for a in call_args(node))
    if node.data == "unary" and str(node.children[0]) in "+-":
        return _unit_by_form(node.children[1], fn, consts, depth - 1)
    variable = var_name(node)
    if variable is not None:
        value = resolve(node, fn, 1)
        if value is not node:
            return _unit_by_form(value, fn, consts, depth - 1)
        local = fn is not None and (variable in fn.locals or variable in fn.params)
        if not local and variable in consts:
            return _unit_by_form(consts[variable], None, consts, depth - 1)
    return False


def _const_values(ctx: LintContext) -> dict[str, Node]:
    values: dict[str, Node] = {}
    assert ctx.tree is not None
    for node in ctx.tree.children:
        if not (isinstance(node, Tree) and node.data == "variable_declaration"):
            continue
        spec = node.children[0]
        qual = spec.children[0] if isinstance(spec, Tree) else None
        if not (isinstance(qual, Tree) and qual.data == "type_qualifier"
                and "const" in [str(t) for t in qual.children]):  # fmt: skip
            continue
        for child in node.children[1:]:
            if isinstance(child, Tree) and child.data == "declarator":
                init = child.children[-1]
                if isinstance(init, Tree) and init.data != "array_specifier":
                    values[str(child.children[0])] = init
    return values


@register
class RedundantNormalize(Rule):
    """Finds normalize() of a vector that is already unit length: normalize(normalize(x)), a
    variable whose only value came from normalize, a reflect of unit vectors.

    Why it matters: normalize is a dot product, an inverse square root and a multiply; doing
    it twice is waste, and usually a sign that the code is unsure where its vectors are
    normalized. Only vectors that are unit by construction are reported, never parameters
    (whose callers may pass anything).

    The fix is safe: renormalizing a unit vector changes it by rounding only.

    Example:
        vec3 rd = normalize(dir);
        vec3 r = normalize(rd);

    Fix:
        vec3 rd = normalize(dir);
        vec3 r = rd;
    """

    code = "PF003"
    name = "redundant-normalize"
    category = "performance"
    severity = "info"
    fixable = "safe"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        up = parents(ctx.tree)
        consts = _const_values(ctx)
        for fn in functions(ctx):
            for node in walk(fn.body):
                if call_name(node) != "normalize":
                    continue
                args = call_args(node)
                if len(args) != 1:
                    continue
                inner = args[0]
                # The model's unit facts about parameters come from today's callers; a
                # normalize that guards a parameter is kept for tomorrow's.
                modelled = not (names_in(inner) & set(fn.params)) and is_unit(ctx, inner)
                if not (_unit_by_form(inner, fn, consts) or modelled):
                    continue
                text = ctx.node_text(inner)
                simple = isinstance(inner, Tree) and inner.data in (
                    "call",
                    "variable",
                    "field",
                    "index",
                    "constructor",
                )
                if not simple and _needs_parens(node, up.get(id(node))):
                    text = f"({text})"
                edit = ctx.replace(node, text)
                fix = Fix("drop the outer normalize", (edit,)) if edit else None
                shown = " ".join(ctx.node_text(inner).split())
                if len(shown) > 50:
                    shown = shown[:47] + "..."
                yield self.report(
                    ctx, node, f"`{shown}` is already unit length; normalize does nothing", fix
                )
