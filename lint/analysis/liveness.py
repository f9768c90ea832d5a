"""What reaches a function's results: the variables whose values can be seen outside the
function (returned, written to an out parameter or a global, tested in a condition, passed to a
call for its side effects) and every variable they are computed from; a value that reaches none
of those is dead."""

from __future__ import annotations

from lark import Tree

from glint.compiler.glsl.ast import (
    Assignment,
    Declarator,
    DoStatement,
    ForStatement,
    JumpStatement,
    first_child,
)

from ..context import LintContext, Node, walk
from .functions import Function, out_param_map
from .syntax import call_args, call_name, names_in, root_var

_CONDITIONS = {"if_statement", "while_statement", "do_statement", "switch_statement"}


def live_names(ctx: LintContext, fn: Function) -> set[str]:
    """Variables of the function whose values can reach its results: what it returns, writes to
    an out parameter or a global, passes to a call for its side effects, or tests in a branch or
    loop condition, and (transitively) every variable those are computed from. A variable that
    is assigned but never reaches one of those is dead: its value is never seen."""
    known = ctx.memo(_live_by_function)
    cached = known.get(id(fn.node))
    if cached is not None:
        return cached
    outs = out_param_map(ctx)
    local = {n for n in fn.locals} | {p for p, (q, _) in fn.params.items() if "out" not in q}
    deps: dict[str, set[str]] = {}
    seeds: set[str] = set()

    def depend(target: str | None, reads: set[str]) -> None:
        if target is None:
            return
        if target in local:
            deps.setdefault(target, set()).update(reads)
        else:  # an out parameter or a global: the value leaves the function
            seeds.update(reads)

    for node in walk(fn.body):
        kind = node.data
        if kind == "jump_statement":
            value = JumpStatement(node).value
            if value is not None:
                seeds |= names_in(value)
        elif kind in _CONDITIONS:  # the condition or selector
            cond = DoStatement(node).condition if kind == "do_statement" else first_child(node)
            seeds |= names_in(cond)
        elif kind == "for_statement":
            cond = ForStatement(node).condition
            if cond is not None:
                seeds |= names_in(cond)
        elif kind == "ternary":
            seeds |= names_in(first_child(node))
        elif kind == "declarator":
            declarator = Declarator(node)
            init = declarator.initializer
            if init is not None:
                depend(declarator.name, names_in(init))
        elif kind == "assignment":
            assignment = Assignment(node)
            target = root_var(assignment.target)
            reads = names_in(assignment.value) | (names_in(assignment.target) - {target})
            depend(target, reads)
        elif node.data == "call":
            callee = call_name(node)
            args = call_args(node)
            if callee in outs and outs[callee]:
                reads = set().union(*(names_in(a) for a in args)) if args else set()
                for i in outs[callee]:
                    if i < len(args):
                        depend(root_var(args[i]), reads)
    live = set(seeds)
    todo = list(seeds)
    while todo:
        for name in deps.get(todo.pop(), ()):
            if name not in live:
                live.add(name)
                todo.append(name)
    known[id(fn.node)] = live
    return live


def _live_by_function(ctx: LintContext) -> dict[int, set[str]]:
    """`live_names` of each function asked about, by id of its definition."""
    return {}


def reaches_output(ctx: LintContext, node: Node, fn: Function, up: dict[int, Tree]) -> bool:
    """Whether the value of an expression can be seen outside its function (see live_names):
    it is returned, tested, or stored in a variable whose value is. Conservative: anything the
    walk does not understand counts as reaching."""
    live = live_names(ctx, fn)
    current: Node = node
    while (parent := up.get(id(current))) is not None:
        if parent.data == "declarator":
            return Declarator(parent).name in live
        if parent.data == "assignment":
            lvalue = Assignment(parent).target
            if current is lvalue:
                return True
            target = root_var(lvalue)
            local = target in fn.locals or (
                target in fn.params and "out" not in fn.params[target][0]
            )
            return not local or target in live
        if parent.data == "expression_statement":
            return any(s.data == "call" and call_name(s) not in _BUILTIN_PURE
                       for s in walk(parent))  # fmt: skip
        if parent.data in ("jump_statement", "compound_statement", "function_definition"):
            return True
        if parent.data in _CONDITIONS or parent.data == "for_statement":
            return True
        current = parent
    return True


_BUILTIN_PURE = {"dot", "max", "min", "clamp", "pow", "normalize", "length", "mix", "abs"}
