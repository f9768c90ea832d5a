"""`glint.lint_shader`: the findings `glint lint` reports for a file, a folder or GLSL text."""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import TYPE_CHECKING

from glint.compiler.errors import UsageError
from glint.compiler.target.shadertoy import TARGETS

from ._shader import Shader, is_source

if TYPE_CHECKING:
    from glint.lint.finding import Finding


def lint_shader(
    shader: str | os.PathLike[str] | Shader,
    *,
    select: str | Sequence[str] | None = None,
    ignore: str | Sequence[str] | None = None,
    target: str | None = None,
    glslang: bool = True,
) -> list[Finding]:
    """Lint GLSL as `glint lint` does; returns the findings sorted by file and position.

    `shader` is GLSL text (a str holding a line break; its findings name the file `<input>`),
    the path of a shader file or of a folder to search for shaders, or a composed `Shader`
    (linted for its own target). `select` and `ignore` are rule codes or prefixes ("N001",
    "L", "ALL"; a list, or one comma-separated str) and replace the configured lists; `target`
    is shadertoy, webgl2 or desktop; `glslang=False` is `--no-glslang`. As for the command,
    `[tool.glint.lint]` of the nearest pyproject.toml above the current directory applies.

    Raises UsageError for an unknown rule code, target or a path that does not exist.
    Problems in the code itself (even binary junk) are findings, never exceptions.
    """
    import argparse

    from glint.lint.cli import collect, options_for, read_source
    from glint.lint.runner import lint_bytes

    if isinstance(shader, Shader):
        target = target or shader.target
    if target is not None and target not in TARGETS:
        raise UsageError(f"target: unknown value {target!r}; expected one of {', '.join(TARGETS)}")
    flags = argparse.Namespace(
        select=_codes(select), ignore=_codes(ignore), target=target, no_glslang=not glslang
    )
    options = options_for(flags)  # the configuration file, then the flags, checked as the CLI
    if isinstance(shader, Shader) or is_source(shader):
        # A lone surrogate (text read with errors="surrogateescape") cannot be UTF-8: kept as
        # its bytes, it is reported as text that is not UTF-8 (C005) rather than raising.
        data = str(shader).encode("utf-8", errors="surrogatepass")
        return lint_bytes(data, "<input>", options).findings
    findings: list[Finding] = []
    for file in collect([os.fspath(shader)]):  # type: ignore[arg-type]
        findings += lint_bytes(read_source(file), file, options).findings
    return findings


def _codes(codes: str | Sequence[str] | None) -> list[str] | None:
    if codes is None:
        return None
    items = codes.split(",") if isinstance(codes, str) else codes
    return [c.strip().upper() for c in items if c.strip()]
