"""glint's Python API: compose a scene into a shader, render it, lint GLSL, browse the catalog.

    import glint

    shader = glint.compose("scene.toml", tier="fast")  # or a dict, a Scene, None (the default)
    shader.text, shader.plan, shader.explain()
    image = glint.render(shader, size=(640, 360), time=1.0)  # image.pixels: float32 H x W x 3
    findings = glint.lint_shader("my_shader.glsl")  # or GLSL text, or a Shader
    glint.catalog()["D.ggx"].source

The functions run what the `glint` command runs and fail as it does: they raise `InputError`
(a bad scene or shader), `EnvironmentProblem` (a missing tool or library, an unwritable path) or
`UsageError` (an argument out of range), all `GlintError`s, with the messages the command prints.
In Jupyter a `Shader` shows its header and code, an `Image` shows itself.

The linter's own package is `glint.lint` (hence `lint_shader` here), the compiler's
`glint.compiler`. The heavy parts (the scene model, numpy, the renderer, the linter) are imported
on first use, so that `import glint` stays fast.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

from glint.compiler.errors import EnvironmentProblem, GlintError, InputError, UsageError

if TYPE_CHECKING:
    from ._catalog import Catalog, Snippet, catalog
    from ._image import Image, render
    from ._lint import lint_shader
    from ._mesh import MeshShader, compose_mesh
    from ._shader import Shader, compose

# Where each public name lives: imported on first use (PEP 562), so that `glint lint`, which
# imports `glint.compiler` and with it this package, does not pay for the renderer's modules.
_LAZY = {
    "Catalog": "_catalog",
    "Snippet": "_catalog",
    "catalog": "_catalog",
    "Image": "_image",
    "render": "_image",
    "lint_shader": "_lint",
    "MeshShader": "_mesh",
    "compose_mesh": "_mesh",
    "Shader": "_shader",
    "compose": "_shader",
}

__all__ = [
    "Catalog",
    "EnvironmentProblem",
    "GlintError",
    "Image",
    "InputError",
    "MeshShader",
    "Shader",
    "Snippet",
    "UsageError",
    "catalog",
    "compose",
    "compose_mesh",
    "lint_shader",
    "render",
]


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(import_module(f".{_LAZY[name]}", __name__), name)
        globals()[name] = value  # the next access finds it without this hook
        return value
    if name == "__version__":  # read on demand: importlib.metadata is slow to import
        from importlib.metadata import version

        return version("glint")
    raise AttributeError(f"module 'glint' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
