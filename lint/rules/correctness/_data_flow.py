"""Shared by the data-flow rules (C101-C103): mainImage's `out` colour."""

from __future__ import annotations

from lark import Tree

from ...analysis.flow import FunctionFlow, Var


def main_colour(flow: FunctionFlow) -> Var | None:
    """mainImage's `out` colour: its first parameter, when that is an `out`."""
    if flow.name != "mainImage" or not flow.outs:
        return None
    params = flow.definition.children[0].children  # type: ignore[union-attr]
    first = params[2].children[0] if len(params) > 2 else None  # type: ignore[union-attr]
    out = flow.outs[0]
    return out if isinstance(first, Tree) and out.token in first.children else None
