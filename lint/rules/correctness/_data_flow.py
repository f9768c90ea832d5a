"""Shared by the data-flow rules (C101-C105): mainImage's `out` colour, and the reads of one
variable gathered into one finding."""

from __future__ import annotations

from glint.compiler.glsl.ast import FunctionDefinition, assigned_target

from ...analysis.flow import FunctionFlow, Read, Var
from ...analysis.syntax import call_args, root_variable
from ...context import LintContext, walk_kind


def main_colour(flow: FunctionFlow) -> Var | None:
    """mainImage's `out` colour: its first parameter, when that is an `out`."""
    if flow.name != "mainImage" or not flow.outs:
        return None
    params = FunctionDefinition(flow.definition).prototype.parameters
    out = flow.outs[0]
    return out if params and params[0].name_token == out.token else None


def by_variable(reads: list[Read]) -> dict[int, list[Read]]:
    """The reads of each variable, in the order the analysis met them (one finding each)."""
    found: dict[int, list[Read]] = {}
    for read in reads:
        found.setdefault(id(read.var), []).append(read)
    return found


def write_lines(ctx: LintContext, flow: FunctionFlow, var: Var) -> list[int]:
    """The lines after its declaration where the function assigns `var` (or passes it to a
    call that may write it), for the message."""
    start = var.token.start_pos or 0
    lines: set[int] = set()
    for node in walk_kind(flow.definition, "assignment", "prefix", "postfix", "call"):
        if node.meta.empty or node.meta.start_pos < start:
            continue
        targets = call_args(node) if node.data == "call" else [assigned_target(node)]

        if any(root_variable(t) == var.name for t in targets):
            lines.add(ctx.span(node)[0])
    return sorted(lines)


def line_list(lines: list[int], most: int = 4) -> str:
    """`12`, `12 and 15`, `12, 15, 19 and 3 more`."""
    words = [str(n) for n in lines[:most]]
    if len(lines) > most:
        return ", ".join(words) + f" and {len(lines) - most} more"
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]
