"""`glint.lint_shader`: the findings `glint lint` reports for a file, a folder or GLSL text."""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

from glint.compiler.errors import UsageError
from glint.compiler.target.shadertoy import TARGETS

from . import _args
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
    common: str | os.PathLike[str] | None = None,
    channels: Mapping[int, str] | None = None,
) -> list[Finding]:
    """Lint GLSL as `glint lint` does; returns the findings sorted by file and position.

    `shader` is GLSL text (a str holding a line break; its findings name the file `<input>`),
    the path of a shader file or of a folder to search for shaders, or a composed `Shader`
    (linted for its own target). `select` and `ignore` are rule codes or prefixes ("N001",
    "L", "ALL"; a list, or one comma-separated str) and replace the configured lists; `target`
    is shadertoy, webgl2 or desktop; `glslang=False` is `--no-glslang`. As for the command,
    `[tool.glint.lint]` of the nearest pyproject.toml above the current directory applies.

    `common` is ShaderToy's Common tab, GLSL text or the path of its file (`--common`): the
    shader is analysed with it in front, and the Common tab is linted too (its findings name
    its file, or `<common>` for text). Without it, a shader file's `NAME.common.glsl` beside
    it is its Common tab. `channels` binds iChannelN to "2d", "cube" or "3d", e.g.
    {0: "cube"} (`--channel 0=cube`).

    Raises UsageError for an unknown rule code, target, channel or a path that does not exist.
    Problems in the code itself (even binary junk) are findings, never exceptions.
    """
    import argparse

    from glint.lint.cli import collect, options_for, read_source
    from glint.lint.runner import lint_bytes
    from glint.lint.tabs import plan, read_common

    if isinstance(shader, Shader):
        target = target or shader.target
    if target is not None:
        _args.choice("target", target, TARGETS)
    selected = _codes("select", select)
    if selected == []:
        raise UsageError(
            "select: no rule codes given; pass codes or prefixes such as 'N001', 'L' or 'ALL' "
            "(None: the configured selection)"
        )
    flags = argparse.Namespace(
        select=selected,
        ignore=_codes("ignore", ignore),
        target=target,
        no_glslang=not _args.flag("glslang", glslang),
        channel=_args.channel_bindings("channels", channels),
    )
    options = options_for(flags)  # the configuration file, then the flags, checked as the CLI
    explicit = None
    texts: dict[str, bytes] = {}  # the sources given as text, by the name findings carry
    if common is not None:
        if isinstance(common, str) and is_source(common):
            explicit = ("<common>", common)
            texts["<common>"] = _encoded(common)
        elif isinstance(common, str | os.PathLike):
            explicit = read_common(_args.path("common", common), "common:")
        else:
            raise UsageError(
                "common: expected GLSL text (a str with a line break) or the path of the Common "
                f"tab's file, not {type(common).__name__}"
            )
    if isinstance(shader, Shader) or is_source(shader):
        texts["<input>"] = _encoded(str(shader))
        files = ["<input>"]
    elif not isinstance(shader, str | os.PathLike):
        raise UsageError(
            "shader: expected GLSL text (a str with a line break), the path of a file or a "
            f"folder, or a Shader, not {type(shader).__name__}"
        )
    else:
        path = _args.path("shader", shader)
        if path == "-":
            raise UsageError(
                "shader: '-' (standard input) is for `glint lint`; pass the text itself"
            )
        files = collect([path])
    findings: list[Finding] = []
    for file, tab in plan(files, explicit, options):
        data = texts[file] if file in texts else read_source(file)
        findings += lint_bytes(data, file, options, tab=tab).findings
    return findings


def _encoded(text: str) -> bytes:
    # A lone surrogate (text read with errors="surrogateescape") cannot be UTF-8: kept as its
    # bytes, it is reported as text that is not UTF-8 (C005) rather than raising.
    return text.encode("utf-8", errors="surrogatepass")


def _codes(name: str, codes: object) -> list[str] | None:
    items = _args.str_list(name, codes)
    if items is None:
        return None
    return [c.strip().upper() for c in items if c.strip()]
