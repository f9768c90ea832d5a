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

from glint.compiler.errors import EnvironmentProblem, GlintError, InputError, UsageError

from ._catalog import Catalog, Snippet, catalog
from ._image import Image, render
from ._lint import lint_shader
from ._mesh import MeshShader, compose_mesh
from ._shader import Shader, compose

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


def __getattr__(name: str) -> str:
    if name == "__version__":  # read on demand: importlib.metadata is slow to import
        from importlib.metadata import version

        return version("glint")
    raise AttributeError(f"module 'glint' has no attribute {name!r}")
