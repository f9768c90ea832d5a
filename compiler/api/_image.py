"""`glint.render`: one frame of a shader, drawn as `glint render` draws it, as an `Image`."""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from glint.compiler.errors import UsageError
from glint.compiler.files import read_text_file

from . import _args
from ._mesh import MeshShader, compose_mesh, draw_mesh_shader
from ._shader import Shader, compose, is_source, load_scene

if TYPE_CHECKING:
    import numpy as np

    from glint.compiler.scene.model import Scene
    from glint.compiler.target.shadertoy_project import Project


@dataclass(frozen=True, eq=False, repr=False)
class Image:
    """A rendered frame: `pixels` is float32 H x W x 3 (row 0 at the top) straight from the
    float framebuffer, so it may hold values outside [0, 1], NaN and Inf.

    `stats` is what `glint render --json` reports: `nan` and `inf` (pixels with such a channel),
    `finite_min`, `finite_max`, `mean` and `std` (per RGB channel), `black_fraction`,
    `white_fraction`, `width`, `height`. `np.asarray(image)` gives `pixels`.
    """

    pixels: np.ndarray
    stats: dict[str, Any]
    renderer: str  # GL_RENDERER and version, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) (...)"
    glsl_version: str  # "300 es", or "330" where the driver lacks ES 3.00 shaders
    draw_seconds: float  # the draw call alone; on llvmpipe this is CPU time
    time: float  # iTime
    frame: int  # iFrame

    @property
    def width(self) -> int:
        return int(self.pixels.shape[1])

    @property
    def height(self) -> int:
        return int(self.pixels.shape[0])

    @property
    def finite(self) -> bool:
        """No pixel is NaN or Inf (`glint render` exits 1 otherwise)."""
        return self.stats["nan"] == 0 and self.stats["inf"] == 0

    def to_png(self) -> bytes:
        """The image as an 8-bit RGB PNG, as `glint render` writes it (clamped to [0, 1], NaN
        shown magenta)."""
        from glint.compiler.render.images import png_bytes

        return png_bytes(self.pixels)

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write the PNG to `path` (atomically); returns the path."""
        from glint.compiler.render.images import save_png

        path = _args.path("path", path)
        save_png(self.pixels, path)
        return Path(path)

    def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
        if dtype is None or dtype == self.pixels.dtype:
            return self.pixels.copy() if copy else self.pixels
        return self.pixels.astype(dtype)

    def _repr_png_(self) -> bytes:
        return self.to_png()

    def __repr__(self) -> str:
        mean = ", ".join("n/a" if v is None else f"{v:.4g}" for v in self.stats["mean"])
        return (
            f"<glint.Image {self.width}x{self.height}, iTime {self.time:g}, "
            f"NaN pixels {self.stats['nan']}, Inf pixels {self.stats['inf']}, "
            f"mean RGB {mean}, {self.renderer}>"
        )


def render(
    shader: Shader | MeshShader | str | os.PathLike[str] | Mapping[str, Any] | Scene,
    *,
    size: tuple[int, int] = (640, 360),
    time: float = 0.0,
    frame: int = 0,
    mouse: Sequence[float] = (0.0, 0.0, 0.0, 0.0),
    timeout: float = 60.0,
    channels: Mapping[int, str | os.PathLike[str]] | None = None,
    frames: int = 1,
) -> Image:
    """Draw one frame, as `glint render` does: in a child process killed after `timeout`
    seconds, into a float framebuffer, with the statistics and NaN/Inf counts in `stats`.

    `shader` is a `Shader` composed for the shadertoy target, ShaderToy Image-tab code (a str
    holding a line break), the path of such a file, or a scene (the path of a `.toml` file, a
    dict, a Scene) to compose first at its own tier. `size` is (width, height); `time`,
    `frame` and `mouse` are iTime, iFrame and iMouse; `channels` binds pictures (files) to
    ShaderToy channels, e.g. {0: "stone.png"}, as ShaderToy binds them (mipmapped, repeating,
    bottom row at v = 0); the rest sample black. A `MeshShader` or a mesh scene is drawn
    by rasterizing its meshes (a mesh scene at its own tier, for mesh-desktop). A ShaderToy
    project (its JSON, or a folder of tabs: target/shadertoy_project.py) is drawn pass by pass,
    `frames` frames from iTime `time`, 1/60 s apart (buffers feed the next frame), and the last
    frame's Image returned.

    Raises InputError when the shader does not compile, does not finish in time or crashes the
    driver, EnvironmentProblem when no OpenGL context can be made. NaN and Inf pixels do not
    raise: see `Image.finite`.
    """
    from glint.compiler.render import image_stats, render_full
    from glint.compiler.render.limits import check_request
    from glint.compiler.render.runner import render_project

    width, height = _args.numbers_of("size", size, 2, whole=True)
    x, y, z, w = _args.numbers_of("mouse", mouse, 4)
    time = _args.number("time", time)
    frame = _args.integer("frame", frame)
    timeout = _args.number("timeout", timeout)
    # The values (size and the memory it takes, timeout, float32 uniforms) before any work.
    check_request(width, height, time, frame, (x, y, z, w), timeout)
    frames = _args.integer("frames", frames)
    project = _project(shader)
    if project is None and frames != 1:
        raise UsageError("frames: only a ShaderToy project (JSON or a folder of tabs) runs frames")
    meshes = None if project is not None else _mesh_shader(shader)
    if meshes is not None and channels:
        raise UsageError("channels: a mesh shader reads no ShaderToy channel; leave them out")
    if project is not None:
        if channels:
            raise UsageError(
                "channels: a project binds its own channels (its inputs); leave them out"
            )
        if not 1 <= frames <= MAX_FRAMES:
            raise UsageError(f"frames: {frames}; a project runs 1 to {MAX_FRAMES} frames")
        result = render_project(project, width, height, time, frames, (x, y, z, w), timeout)
    elif meshes is not None:
        result = draw_mesh_shader(meshes, (width, height), time, (x, y, z, w), timeout)
    else:
        from glint.compiler.render.images import channel_pictures

        source, scene = _source(shader)
        given = _given_pictures(channels)
        pictures = channel_pictures(scene.bound_pictures(given) if scene is not None else given)
        result = render_full(
            source, width, height, time, frame, (x, y, z, w), timeout=timeout,
            channels=pictures, pictures="mipmap" if pictures else None,
        )  # fmt: skip
    return Image(
        # A view of the RGBA frame, not a copy: a large frame is in memory once.
        pixels=result.image[:, :, :3],
        stats=image_stats(result.image),  # over RGBA, as `glint render` counts NaN and Inf
        renderer=result.renderer,
        glsl_version=result.glsl_version,
        draw_seconds=result.draw_seconds,
        time=time,
        frame=frame,
    )


# The most frames a project runs in one render (a minute at 60 frames a second).
MAX_FRAMES = 3600


def _project(shader: object) -> Project | None:
    """A ShaderToy project to draw: a Project, a `.json` file or a folder; None otherwise."""
    from glint.compiler.target.shadertoy_project import Project, is_project, read_project

    if isinstance(shader, Project):
        return shader
    if isinstance(shader, str | os.PathLike) and not is_source(shader):
        path = _args.path("shader", shader)
        if is_project(path):
            return read_project(path)
    return None


def _given_pictures(channels: object) -> dict[int, str]:
    """`channels` ({N: path}) checked: each a ShaderToy channel and a path."""
    if channels is None:
        return {}
    if not isinstance(channels, Mapping):
        raise UsageError(f"channels: a mapping of channel number to picture file, not {channels!r}")
    files = {}
    for unit, path in channels.items():
        if isinstance(unit, bool) or not isinstance(unit, int) or not 0 <= unit <= 3:
            raise UsageError(f"channels: {unit!r} is not a ShaderToy channel; they are 0 to 3")
        files[unit] = _args.path(f"channels[{unit}]", path)
    return files


def _mesh_shader(shader: object) -> MeshShader | None:
    """The mesh shader to draw: `shader` itself, or a mesh scene composed for mesh-desktop."""
    if isinstance(shader, MeshShader):
        return shader
    if is_source(shader) or isinstance(shader, Shader):
        return None
    if isinstance(shader, str | os.PathLike) and not _args.path("shader", shader).endswith(".toml"):
        return None
    from glint.compiler.scene.model import Scene

    if not isinstance(shader, str | os.PathLike | Mapping | Scene):
        return None
    scene = load_scene(shader)
    return compose_mesh(scene) if scene.is_mesh else None


def _source(shader: object) -> tuple[str, Scene | None]:
    """ShaderToy Image-tab code to draw, and its scene where it was composed from one (whose
    materials' pictures render binds: Scene.bound_pictures)."""
    if isinstance(shader, Shader):
        if shader.target != "shadertoy":
            raise UsageError(
                f"render draws ShaderToy Image-tab code; this shader's target is "
                f"{shader.target}: compose it with target='shadertoy'"
            )
        return shader.text, shader.scene
    if is_source(shader):
        return str(shader), None
    if isinstance(shader, str | os.PathLike):
        path = _args.path("shader", shader)
        if not path.endswith(".toml"):
            from glint.compiler.target.sourcemap import with_includes

            return with_includes(read_text_file(path), path), None
        shader = compose(path)
    from glint.compiler.scene.model import Scene

    if isinstance(shader, Mapping | Scene):
        shader = compose(shader)
    if isinstance(shader, Shader):
        return shader.text, shader.scene
    raise UsageError(
        "render takes a Shader, Image-tab code, the path of a shader or a scene, a dict or a "
        f"Scene, not {type(shader).__name__}"
    )
