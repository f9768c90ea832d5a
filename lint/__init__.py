"""The linter: `glint lint` for ShaderToy and lighting code.

source (read, preprocess, parse) -> rules (one module per category in `rules/`, registered by
code) -> suppressions and configuration -> reporters; fixes are edits the runner applies.
The linter imports the compiler's GLSL front end; the compiler never imports the linter.
"""

from __future__ import annotations

from .finding import Edit, Finding, Fix
from .runner import LintResult, lint_source

__all__ = ["Edit", "Finding", "Fix", "LintResult", "lint_source"]
