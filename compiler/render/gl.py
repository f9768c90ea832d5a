"""The OpenGL side of rendering: runs only inside the worker process.

One ShaderToy frame is drawn with a full-screen triangle into an RGBA32F framebuffer, so values
outside [0, 1], NaN and Inf survive for the checks that follow, and is read back as numpy.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from glint.compiler.target import shadertoy
from glint.compiler.target.glslang import wrap_for_target

# Debian packages that provide headless EGL with Mesa's software rasteriser.
EGL_PACKAGES = "libegl1 libegl-mesa0 libgl1-mesa-dri"
# A triangle that covers the viewport; no vertex buffer needed.
VERTEX_BODY = (
    "void main() {\n"
    "    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);\n"
    "    gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n"
)
# Unbound ShaderToy channels read as black; this is the size of the stand-in texture.
CHANNEL_SIZE = 1
_ARRAYS = frozenset({"iChannelTime", "iChannelResolution"})


class ContextFailure(Exception):
    """No OpenGL context could be made: the environment, not the shader, is at fault."""


class CompileFailure(Exception):
    """The driver rejected the shader; the message is its log."""


@dataclass
class Frame:
    """The ShaderToy inputs of one frame."""

    width: int
    height: int
    time: float
    frame: int
    mouse: tuple[float, float, float, float]
    date: tuple[float, float, float, float]
    # Float data for iChannel0..3, each H x W x 4; texel (x, y) is array[y, x], no flip, so
    # a probe shader can read its inputs with texelFetch. Unset channels are black.
    channels: tuple[np.ndarray | None, ...] = ()
    # Sample the channels as a picture, repeating: "mipmap" (ShaderToy's default) or "linear"
    # (no mipmaps); None: texel by texel, as a probe reads its inputs.
    pictures: str | None = None


def create_context() -> Any:
    """A headless OpenGL context through EGL."""
    try:
        import moderngl
    except ImportError as exc:
        raise ContextFailure(f"moderngl cannot be imported: {exc}") from exc
    try:
        return moderngl.create_context(standalone=True, backend="egl")
    except Exception as exc:  # moderngl/glcontext raise plain Exceptions for missing libraries
        raise ContextFailure(f"cannot create an OpenGL context through EGL: {exc}") from exc


def accepts_es3(ctx: Any) -> bool:
    """Whether a core context compiles `#version 300 es` (GL 4.3 or ARB_ES3_compatibility)."""
    return ctx.version_code >= 430 or "GL_ARB_ES3_compatibility" in ctx.extensions


def glsl_version(ctx: Any) -> str:
    """The GLSL version the shader is compiled as: ShaderToy's ES 3.00 where the driver can."""
    return "300 es" if accepts_es3(ctx) else "330"


def wrap(source: str, version: str) -> tuple[str, int]:
    """The complete fragment shader for `version` and the number of lines before the user's."""
    if shadertoy.is_complete(source):
        return source, 0
    if version == "300 es":
        return shadertoy.wrap(source), shadertoy.PRELUDE_LINES
    return wrap_for_target(source, "desktop")


def build_program(ctx: Any, source: str) -> tuple[Any, str]:
    """Compile the ShaderToy source; return the program and the GLSL version it was built as."""
    import moderngl

    version = glsl_version(ctx)
    fragment, _ = wrap(source, version)
    vertex = f"#version {version}\n" + VERTEX_BODY
    try:
        return ctx.program(vertex_shader=vertex, fragment_shader=fragment), version
    except moderngl.Error as exc:
        raise CompileFailure(str(exc).strip()) from exc


def _set(program: Any, name: str, values: Any) -> None:
    """Set a uniform if the program still has it (unused ones are optimised away)."""
    if name not in program:
        return
    uniform = program[name]
    data = np.asarray(values, dtype=np.int32 if name == "iFrame" else np.float32)
    if name in _ARRAYS:
        # The driver keeps the array only up to the last element that is used.
        data = data[: uniform.array_length]
    uniform.write(data.tobytes())


def set_uniforms(program: Any, frame: Frame) -> None:
    """Give the program every ShaderToy uniform it uses, with ShaderToy's meaning."""
    _set(program, "iResolution", (frame.width, frame.height, 1.0))
    _set(program, "iTime", frame.time)
    _set(program, "iTimeDelta", 1.0 / 60.0)
    _set(program, "iFrame", frame.frame)
    _set(program, "iFrameRate", 60.0)
    _set(program, "iMouse", frame.mouse)
    _set(program, "iDate", frame.date)
    _set(program, "iChannelTime", [frame.time] * 4)
    sizes = [
        (c.shape[1], c.shape[0], 1.0) if c is not None else (CHANNEL_SIZE, CHANNEL_SIZE, 1.0)
        for c in frame.channels
    ]
    sizes += [(CHANNEL_SIZE, CHANNEL_SIZE, 1.0)] * (4 - len(sizes))
    _set(program, "iChannelResolution", sizes)
    _set(program, "iSampleRate", 44100.0)
    for unit in range(4):
        name = f"iChannel{unit}"
        if name in program:
            program[name].value = unit


def draw(ctx: Any, program: Any, frame: Frame, repeats: int = 1) -> tuple[np.ndarray, list[float]]:
    """Draw the frame `repeats` times; return it in image convention (row 0 at the top) and the
    time of each draw (for benchmarks: the first may include the driver's lazy compilation)."""
    import moderngl

    black = ctx.texture((CHANNEL_SIZE, CHANNEL_SIZE), 4, dtype="f4")
    for unit in range(4):
        black.use(location=unit)
    for unit, data in enumerate(frame.channels):
        if data is None:
            continue
        rows, cols = data.shape[:2]
        texture = ctx.texture((cols, rows), 4, np.ascontiguousarray(data, np.float32), dtype="f4")
        texture.filter = (moderngl.NEAREST, moderngl.NEAREST)
        if frame.pictures == "mipmap":
            texture.build_mipmaps()
            texture.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
        elif frame.pictures == "linear":
            texture.filter = (moderngl.LINEAR, moderngl.LINEAR)
        if frame.pictures is not None:
            texture.repeat_x = texture.repeat_y = True
        texture.use(location=unit)
    # The array the frame is read into comes first: where memory is short, numpy says so with
    # a MemoryError, where the driver would fail in ways that are harder to tell apart.
    pixels = np.empty((frame.height, frame.width, 4), dtype=np.float32)
    target = ctx.texture((frame.width, frame.height), 4, dtype="f4")
    framebuffer = ctx.framebuffer(color_attachments=[target])
    framebuffer.use()
    framebuffer.clear(0.0, 0.0, 0.0, 0.0)
    set_uniforms(program, frame)
    vertex_array = ctx.vertex_array(program, [])
    seconds = []
    for _ in range(repeats):
        start = time.perf_counter()
        vertex_array.render(moderngl.TRIANGLES, vertices=3)
        ctx.finish()
        seconds.append(time.perf_counter() - start)
    return read_frame(framebuffer, pixels), seconds


def read_frame(framebuffer: Any, pixels: np.ndarray) -> np.ndarray:
    """Read the framebuffer into `pixels` (H x W x 4 float32) and put row 0 at the top.

    Read in place, with no bytes object and no flipped copy in between, so that a frame costs
    its own size once more, not three times."""
    framebuffer.read_into(pixels, components=4, dtype="f4")
    # GL's origin is the bottom-left corner; images start at the top. Swap rows in place.
    height = pixels.shape[0]
    for top in range(height // 2):
        bottom = height - 1 - top
        row = pixels[top].copy()
        pixels[top] = pixels[bottom]
        pixels[bottom] = row
    return pixels
