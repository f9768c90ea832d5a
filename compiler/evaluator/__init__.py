"""A CPU evaluator of snippet GLSL over numpy arrays, at half, single or double precision.

It runs a snippet's own code (parsed by the project's front end) lane-wise, so float16
(mediump) behaviour can be tested without mobile hardware.
"""

from __future__ import annotations

from glint.compiler.evaluator.api import FLOAT_DTYPES, evaluate
from glint.compiler.evaluator.errors import EvaluationError, UnsupportedError
from glint.compiler.evaluator.interpreter import MAX_ITERATIONS, Interpreter
from glint.compiler.evaluator.values import StructValue, Value

__all__ = [
    "FLOAT_DTYPES",
    "MAX_ITERATIONS",
    "EvaluationError",
    "Interpreter",
    "StructValue",
    "UnsupportedError",
    "Value",
    "evaluate",
]
