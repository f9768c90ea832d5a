"""C103 used-before-initialised."""

from __future__ import annotations

from collections.abc import Iterator

from lark import Tree

from glint.compiler.glsl.ast import binary_parts, field_name, first_child

from ...analysis.expression_types import expression_types
from ...analysis.flow import FunctionFlow, Read, Var, function_flows, mask_names
from ...context import LintContext
from ...finding import Finding
from .. import Rule, register
from ._data_flow import by_variable, line_list, write_lines

_FIX = "GLSL does not zero local variables: give it a value where it is declared"


@register
class UsedBeforeInitialised(Rule):
    """Finds a local variable read before it is given a value on some path: declared without an
    initialiser and read at once, assigned only in some branches or in a loop that may not run, or
    a struct whose member is read (here, or by a function it is passed to) but written only on some
    paths. One finding per variable: at its read when one read is affected, else at its
    declaration with the lines that read it; a member that a called function reads is reported
    there, with the call that passes the struct.

    The analysis follows if/else, loops that may run zero times (or surely run, from their
    bounds), `return`, `break`, `discard`, calls that write `out` arguments, and vector components
    through swizzles. A loop that surely runs is followed through its first iteration with the
    values set before it: a march whose first step cannot stop (`d = 2.0 * EPS`, `t = 0.0`) runs
    its body. A nearest-point search in loops with constant bounds writes what it keeps when
    some cell's candidate surely beats the starting bound (`md = 8.0` against a distance below
    2 in the middle cell, which `md` can only have lowered before). It stays quiet where the
    author ruled the path out: a read under a condition tied to the write's (`if (hit) n = ...;`
    then `if (hit) use(n)`, or a flag set together with the value), a flag set where the value
    is left to a later `if (flag) v = ...;`, and a case analysis of one value (`if (n == 0) ...
    if (n == 1) ... if (n == 2)`, or an else-if chain of comparisons of one value) taken as
    exhaustive. A struct member that no code of the file reads (only written, or never named)
    does not count: `return s;` with `s.unused` unset hands back nothing anyone looks at.

    Why is this bad?
        GLSL does not zero local variables. An uninitialised value is whatever the register held, so
        the shader looks right on one GPU and flickers on another.

    Example:
        float d;
        if (hit) d = t;
        col *= exp(-d);

    Use instead:
        float d = 1e10;
        if (hit) d = t;
        col *= exp(-d);

    Fix safety:
        No fix: the right initial value depends on what the variable means.

    References:
        - GLSL ES 3.00 spec §4.3 (Storage Qualifiers: a local without an initialiser is
          undefined)
        - CWE-457, Use of Uninitialized Variable
    """

    code = "C103"
    name = "used-before-initialised"
    default = False  # below 80% worth acting on in the labelled corpus sample
    category = "correctness"
    severity = "warning"

    def check(self, ctx: LintContext) -> Iterator[Finding]:
        for flow in function_flows(ctx):
            reads = [r for r in flow.reads if r.var.kind == "local" and not r.correlated]
            through = [r for r in reads if r.origins]
            # a struct's members that nothing in the file reads do not count: `return s;`
            # with `s.unused` unset hands back nothing anyone looks at
            direct = [r for r in reads if not r.origins and r.missing & _read(ctx, r.var)]
            for group in by_variable(direct).values():
                yield self.variable(ctx, flow, group)
            yield from self.members(ctx, flow, through)

    def variable(self, ctx: LintContext, flow: FunctionFlow, group: list[Read]) -> Finding:
        var = group[0].var
        missing = 0
        for read in group:
            missing |= read.missing & _read(ctx, var)
        what = f"`{var.name}{mask_names(var, missing)}`"
        declared = ctx.span(var.token)[0]
        first = ctx.span(group[0].node)[0]
        writes = [n for n in write_lines(ctx, flow, var) if n < first]
        if not writes:
            path = f"nothing gives it a value before line {first}"
        else:
            path = f"a path can skip the writes on line{'s' if len(writes) > 1 else ''} "
            path += line_list(writes)
        if len(group) == 1:
            message = (
                f"{what} may be read here before it is given a value (declared without one on "
                f"line {declared}; {path}); {_FIX}"
            )
            return self.report(ctx, group[0].node, message)
        lines = sorted({ctx.span(r.node)[0] for r in group})
        message = (
            f"{what} is declared without a value and may be read before it is given one, on "
            f"lines {line_list(lines)} ({path}); {_FIX}"
        )
        return self.report(ctx, var.token, message)

    def members(self, ctx: LintContext, flow: FunctionFlow, reads: list[Read]) -> Iterator[Finding]:
        """A struct passed to a function that reads a member the caller may not have written:
        reported at the callee's read (its first one of the member), once."""
        for read in reads:
            for component, origin in sorted(read.origins.items(), key=lambda item: item[0]):
                if not read.missing >> component & 1:
                    continue
                reported = ctx.memo(_reported_member_reads)
                if id(origin) in reported:
                    continue
                reported.add(id(origin))
                var = read.var
                member = var.fields[component] if var.fields else var.name
                call_line = ctx.span(read.node)[0]
                message = (
                    f"`{ctx.node_text(origin)}` may be unset here: {flow.name} passes "
                    f"`{var.name}` on line {call_line} without writing its member `{member}` on "
                    f"every path (declared on line {ctx.span(var.token)[0]}); {_FIX}"
                )
                yield self.report(ctx, origin, message)


def _reported_member_reads(ctx: LintContext) -> set[int]:
    """The callee reads (ids) of struct members already reported for this file: once each."""
    return set()


def _read(ctx: LintContext, var: Var) -> int:
    """The mask of `var`'s components that some code may read: for a struct, the members that
    the file reads somewhere on a value of its type (or of a type it cannot tell); everything
    for any other variable."""
    if not var.fields:
        return var.full
    read = ctx.memo(_read_members)
    if (var.struct, "") in read:  # compared whole
        return var.full
    mask = 0
    for i, member in enumerate(var.fields):
        if (var.struct, member) in read or ("", member) in read:
            mask |= 1 << i
    return mask


def _read_members(ctx: LintContext) -> frozenset[tuple[str, str]]:
    """(struct type, member) of each member the file reads (a field that is not only the target
    of `=`), the type "" where it cannot be told; (struct type, "") for a struct compared with
    `==` or `!=`, which reads every member."""
    types = expression_types(ctx)
    assigned: set[int] = set()  # ids of fields that an `=` only writes (`s.m = `, `s.m.x = `)
    for node in ctx.nodes("assignment"):
        target, op, _ = binary_parts(node)
        while op == "=" and isinstance(target, Tree) and target.data in ("field", "index"):
            if target.data == "field":
                assigned.add(id(target))
            target = first_child(target)
    found: set[tuple[str, str]] = set()
    for node in ctx.nodes("field"):
        if id(node) in assigned:
            continue
        base = types.type_of(first_child(node))
        if base is None:
            found.add(("", field_name(node)))
        elif base in types.structs:
            found.add((base, field_name(node)))
    for node in ctx.nodes("binary"):
        left, op, _ = binary_parts(node)
        if op in ("==", "!="):
            base = types.type_of(left)
            if base is not None and base in types.structs:
                found.add((base, ""))
    return frozenset(found)
