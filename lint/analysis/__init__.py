"""Analyses that rules share, computed once per file: the semantic model (scopes, types and
value ranges of expressions) and data flow."""

from __future__ import annotations

from ..context import LintContext
from .model import Model, Value
from .ranges import Interval

__all__ = ["Interval", "Model", "Value", "semantic_model"]


def semantic_model(ctx: LintContext) -> Model:
    """The file's semantic model, built on first use and cached in `ctx.cache["model"]`.
    Only for a parsed file (rules with `needs_tree`)."""
    model = ctx.cache.get("model")
    if model is None:
        if ctx.tree is None:
            raise ValueError("semantic_model needs a parsed file")
        model = ctx.cache["model"] = Model(ctx.tree)
    return model
