"""Errors of the CPU evaluator; both name the construct and its file:line."""

from __future__ import annotations

from glint.compiler.errors import InputError


class EvaluationError(InputError):
    """The code cannot be evaluated as written (unknown name, bad types, a runaway loop)."""


class UnsupportedError(EvaluationError):
    """Valid GLSL that the evaluator does not run (texture lookups, derivatives, arrays...)."""
