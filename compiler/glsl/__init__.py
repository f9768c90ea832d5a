"""The GLSL front end shared by the compiler and the linter.

preprocess (with a line map) -> parse (lark LALR, positions on every node) -> symbols.
"""

from __future__ import annotations

from glint.compiler.glsl.parser import GLSLSyntaxError, parse, parse_source
from glint.compiler.glsl.preprocessor import (
    Macro,
    Preprocessed,
    PreprocessorError,
    SourceLocation,
    preprocess,
)
from glint.compiler.glsl.symbols import (
    FunctionDef,
    ModuleSymbols,
    Param,
    analyze,
    reach,
    reachable,
    symbols_of,
)

__all__ = [
    "FunctionDef",
    "GLSLSyntaxError",
    "Macro",
    "ModuleSymbols",
    "Param",
    "Preprocessed",
    "PreprocessorError",
    "SourceLocation",
    "analyze",
    "parse",
    "parse_source",
    "preprocess",
    "reach",
    "reachable",
    "symbols_of",
]
