"""PF002 loop-invariant-work."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from ...context import LintContext, Node, walk
from ...finding import Finding
from .. import Rule, register
from ..lighting._terms import (
    Function,
    call_name,
    functions,
    names_in,
    out_param_map,
    writes_of,
)
from ._common import BUILTINS

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
    """Finds expensive work inside a loop that gives the same value on every iteration: a call to
    normalize, length, a trigonometric or exponential function or a texture fetch whose inputs are
    not changed by the loop.

    What counts as invariant: every variable the expression reads is neither written in the loop
    (assignment, ++/--, an out argument), nor declared inside it, nor a global that any function
    writes. Calls of the shader's own functions are never counted (they may be expensive, but
    proving them pure is out of scope), and expressions of constants only are left to the compiler,
    which folds them.

    Why is this bad?
        A raymarch or shadow loop runs up to hundreds of times per pixel; a normalize or texture
        fetch of loop-invariant inputs is paid on every step. Compilers hoist some of it, but not
        across a `break` or through a texture fetch.

    Example:
        for (int i = 0; i < 64; i++) {
            float h = map(ro + rd * t);
            res = min(res, h / t * length(lightPos - ro));
            t += h;
        }

    Use instead:
        float dist = length(lightPos - ro);
        for (int i = 0; i < 64; i++) { ... res = min(res, h / t * dist); ... }

    Fix safety:
        No fix: the hoisted value needs a name and a type, and the loop may be inside an expression
        the fix cannot move code out of.

    References:
        - Muchnick, Advanced Compiler Design and Implementation, 1997, §13.2 (Loop-Invariant Code
          Motion)
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
                if name is None or name not in BUILTINS:
                    return False  # the shader's own function, or a call through an expression
                costly = costly or name in _EXPENSIVE
        return costly
