"""Analyses that rules share, computed once per file: the semantic model (types, value ranges
and unit length of expressions: model.py and its parts; rules build it only where they need a
range), the types of expressions alone (expression_types.py, far cheaper), definite assignment
(flow.py), a file's functions and locals (functions.py), constant folding (constants.py) and
liveness of values (liveness.py); and the shapes of the parse tree they all read (syntax.py)."""

from __future__ import annotations

from .model import Model, semantic_model
from .ranges import Interval
from .values import Value

__all__ = ["Interval", "Model", "Value", "semantic_model"]
