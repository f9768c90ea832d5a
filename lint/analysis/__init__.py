"""Analyses that rules share, computed once per file: the semantic model (scopes, types and
value ranges of expressions) and data flow."""

from __future__ import annotations

from .model import Model, semantic_model
from .ranges import Interval
from .values import Value

__all__ = ["Interval", "Model", "Value", "semantic_model"]
