"""C105 missing-return."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import CompoundStatement, FunctionDefinition

from ...analysis.flow import function_flows
from ...analysis.syntax import call_name
from ...context import LintContext, walk_kind
from ...finding import Finding
from .. import Rule, register

_LOOPS = {"for_statement": "for", "while_statement": "while", "do_statement": "do"}


@register
class MissingReturn(Rule):
    """Finds a function with a return type whose body can reach its end without `return`, and that
    the file calls: a loop that returns from inside but can finish, an `if` without an `else` that
    returns, or no `return` at all. Reported at the function's name.

    Why is this bad?
        The caller gets an undefined value: the compiler accepts the function (GLSL only warns, if
        at all) and the result is whatever the register held, different between GPUs.

    Example:
        float hit(vec3 ro, vec3 rd) {
            for (int i = 0; i < 64; i++) {
                if (map(ro) < 0.001) return 1.0;
                ro += rd * 0.1;
            }
        }

    Use instead:
        float hit(vec3 ro, vec3 rd) {
            for (int i = 0; i < 64; i++) {
                if (map(ro) < 0.001) return 1.0;
                ro += rd * 0.1;
            }
            return 0.0;
        }

    Fix safety:
        No fix: the value for the path that falls off the end is the author's choice.

    References:
        - GLSL ES 3.00 spec §6.4 (Jumps: a function with a return type returns a value)
    """

    code = "C105"
    name = "missing-return"
    default = False  # fewer than 15 judged findings on the corpus
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        flows = [f for f in function_flows(ctx) if f.returns != "void"]
        if not flows:
            return
        called = {call_name(c) for c in walk_kind(ctx.tree, "call")}  # type: ignore[arg-type]
        for flow in flows:
            if flow.name not in called or not any(e.node is None for e in flow.exits):
                continue
            definition = FunctionDefinition(flow.definition)
            name = definition.prototype.name_token
            body = CompoundStatement.cast(definition.body)
            statements = body.statements if body is not None else []
            last = statements[-1] if statements else None

            if isinstance(last, Tree) and last.data in _LOOPS:
                line = ctx.span(last)[0]
                how = f"when the {_LOOPS[last.data]} loop on line {line} finishes without returning"
            elif isinstance(last, Tree) and last.data == "if_statement":
                how = f"on a path through the if on line {ctx.span(last)[0]} that returns nothing"
            elif not any(e.node is not None for e in flow.exits):
                how = "it has no return at all"
            else:
                how = "its last statement is not a return"
            message = (
                f"{flow.name} can reach the end of its body without `return` ({how}); its caller "
                f"then gets an undefined {flow.returns}: return a value on every path"
            )
            yield self.report(ctx, name, message)
