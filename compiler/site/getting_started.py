"""The site's home page, Getting started: the README's two commands, the default scene's
picture and the Python API example, taken from the README so that they cannot drift from it
(tests/test_readme.py already holds the README to the truth)."""

from __future__ import annotations

import re
from pathlib import Path, PurePosixPath

from glint.compiler.errors import InputError
from glint.compiler.markdown import fenced

from .live_canvas import home_canvas

HOME_PAGE = PurePosixPath("index.md")
PICTURE = "examples/default.png"  # under site/docs, as the README shows it


def getting_started_pages(readme: Path) -> dict[PurePosixPath, str]:
    return {HOME_PAGE: getting_started_page(readme.read_text(encoding="utf-8"))}


def getting_started_page(readme: str) -> str:
    commands = _block(readme, "sh", after="")
    api = _block(readme, "python", after="## Python API")
    return (
        "# Getting started\n\n"
        "glint composes ShaderToy-ready lighting shaders from a catalog of small, "
        "interchangeable GLSL snippets, checks them with glslangValidator, renders them "
        "headlessly and lints shaders written by hand.\n\n"
        "On a fresh Debian machine with Python 3.11, two commands set everything up (as root "
        "they install the system packages with apt-get, then a virtual environment with glint):"
        "\n\n" + fenced(commands, "sh") + "\n"
        "`make demo` composes, validates and renders the default scene:\n\n"
        f"![The default scene rendered by glint]({PICTURE})\n\n"
        "The same scene live in your browser (WebGL2, composed with `glint compose --target "
        "webgl2 --params-as-uniforms`): press Play, scrub the time, or move a parameter's "
        "slider.\n\n" + home_canvas() + "\n"
        "## Python API\n\n"
        "`import glint` gives the commands as functions, for scripts and notebooks:\n\n"
        + fenced(api, "python")
        + "\n## Further\n\n"
        "- [Catalog](catalog/index.md): every snippet, its formula, code and tiers.\n"
        "- [Command line](cli.md): every command's options.\n"
        "- [Lint rules](rules.md), [Architecture](architecture.md), "
        "[Benchmark](bench/bench.md).\n"
    )


def _block(readme: str, language: str, after: str) -> str:
    """The first fenced block of `language` after the heading `after` ("" for the start)."""
    start = readme.find(after) if after else 0
    match = re.compile(rf"^```{language}\n(.*?)^```", re.S | re.M).search(readme, max(start, 0))
    if start < 0 or match is None:
        where = f"under '{after}'" if after else "at its start"
        raise InputError(f"README.md: no ```{language} block {where} for the docs site")
    return match.group(1)
