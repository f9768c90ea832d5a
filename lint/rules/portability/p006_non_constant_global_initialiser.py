"""P006 non-constant-global-initialiser."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import Call, Variable, VariableDeclaration
from glint.compiler.glsl.binder import Bindings, Symbol
from glint.compiler.target.shadertoy import UNIFORM_NAMES

from ...context import LintContext, walk
from ...finding import Finding
from .. import Rule, register

_NOT_CONSTANT_CALLS = ("texture", "texel", "dFd", "fwidth")


@register
class NonConstantGlobal(Rule):
    """Finds a global variable initialised with something that is not a constant expression: a
    uniform (`iTime`, `iResolution`), another non-const global, a call to a function of the file, a
    texture lookup.

    Why is this bad?
        GLSL ES 3.00 only allows constant expressions in global initialisers (desktop GL and some
        drivers allow more); ShaderToy rejects the shader with "non-constant global initializer".

    Example:
        vec2 res = iResolution.xy;
        void mainImage(out vec4 fragColor, in vec2 fragCoord) { ... fragCoord / res ... }

    Use instead:
        vec2 res;
        void mainImage(out vec4 fragColor, in vec2 fragCoord) {
            res = iResolution.xy;
            ...
        }

    Fix safety:
        No fix: the assignment has to move to where the value is first needed, which may be before
        mainImage calls anything that reads it.

    References:
        - GLSL ES 3.00 spec §4.3 (Storage Qualifiers: global initialisers must be constant
          expressions) and §4.3.3 (Constant Expressions)
    """

    code = "P006"
    name = "non-constant-global-initialiser"
    judged = False  # it reports what the compiler or the target rejects
    certainty = "certain"
    category = "portability"
    severity = "error"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        assert ctx.tree is not None
        bindings = ctx.bindings
        functions = {f.name for f in bindings.functions}
        for node in ctx.tree.children:
            declaration = VariableDeclaration.cast(node)
            if declaration is None:
                continue
            words = set(declaration.type.qualifiers)
            if words & {"uniform", "in", "out"}:
                continue
            for decl in declaration.declarators:
                init = decl.initializer
                if isinstance(init, Tree):
                    reason = _not_constant(init, bindings, functions)
                    if reason is not None:
                        message = (f"global `{decl.name}` is initialised with {reason}, which "
                                   "is not a constant expression in GLSL ES 3.00; declare it "
                                   "without a value and assign it in mainImage")  # fmt: skip
                        yield self.report(ctx, init, message)


def _is_variable(symbol: Symbol | None) -> bool:
    """A global that holds a value at run time: not const, not an input of the stage."""
    return (
        symbol is not None
        and symbol.kind == "global"
        and not {"const", "uniform", "in", "out"} & set(symbol.qualifiers)
    )


def _not_constant(init: Tree, bindings: Bindings, functions: set[str]) -> str | None:
    """What makes an initialiser non-constant, or None (also when unsure)."""
    callees: set[int] = set()
    for node in walk(init):
        if node.data == "call":
            call = Call(node)
            callees.add(id(call.callee))
            name = call.callee_name  # type: ignore[assignment]
            if name is not None:
                if name in functions:
                    return f"a call to `{name}` (functions cannot run at global scope)"
                if name.startswith(_NOT_CONSTANT_CALLS):
                    return f"`{name}(...)`"
        elif node.data == "variable" and id(node) not in callees:
            name = Variable(node).name
            if name in UNIFORM_NAMES or name in ("gl_FragCoord", "gl_FrontFacing"):
                return f"the uniform `{name}`"
            if _is_variable(bindings.symbol_of(node)):
                return f"the non-const global `{name}`"
    return None
