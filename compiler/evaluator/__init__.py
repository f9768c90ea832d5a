"""A CPU evaluator of snippet GLSL over numpy arrays, at half, single or double precision.

It runs a snippet's own code (parsed by the project's front end) lane-wise, so float16
(mediump) behaviour can be tested without mobile hardware.
"""

from __future__ import annotations

from .api import FLOAT_DTYPES, evaluate
from .errors import EvaluationError, UnsupportedError
from .interpreter import MAX_ITERATIONS, Interpreter
from .precision import precision_report, survey
from .snippets import evaluate_snippet, snippet_source
from .values import StructValue, Value

__all__ = [
    "FLOAT_DTYPES",
    "MAX_ITERATIONS",
    "EvaluationError",
    "Interpreter",
    "StructValue",
    "UnsupportedError",
    "Value",
    "evaluate",
    "evaluate_snippet",
    "precision_report",
    "snippet_source",
    "survey",
]
