"""The OpenGL side of drawing a mesh scene: runs only inside the worker process.

The background program fills the frame first (a full-screen triangle, no depth test); then
each mesh is drawn from its vertex and index buffers with the depth test, into the same
RGBA32F framebuffer as a ShaderToy frame, read back as numpy.
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from glint.compiler.render import gl


def _version_line(source: str) -> str:
    return source.lstrip().split("\n", 1)[0]


def _program(ctx: Any, vertex: str, fragment: str, what: str) -> Any:
    import moderngl

    try:
        return ctx.program(vertex_shader=vertex, fragment_shader=fragment)
    except moderngl.Error as exc:
        raise gl.CompileFailure(f"{what}: {str(exc).strip()}") from exc


def _matrix(program: Any, name: str, matrix: Any) -> None:
    """Set a matrix uniform if the program has it (GL reads matrices column by column)."""
    if name in program:
        program[name].write(np.asarray(matrix, dtype=np.float32).T.tobytes())


def draw_meshes(ctx: Any, job: dict[str, Any], frame: gl.Frame) -> tuple[np.ndarray, list[float]]:
    """Draw the job's background and meshes; the image (row 0 at the top) and the seconds."""
    import moderngl

    size = (frame.width, frame.height)
    background_fragment = job["background"]
    background = _program(
        ctx,
        _version_line(background_fragment) + "\n" + gl.VERTEX_BODY,
        background_fragment,
        "background program",
    )
    gl.set_uniforms(background, frame)
    draws = []
    for item in job["draws"]:
        program = _program(ctx, item["vertex"], item["fragment"], f"program {item['name']!r}")
        arrays = np.load(item["arrays"])
        content = [
            (ctx.buffer(np.ascontiguousarray(arrays[name], np.float32)), "3f", name)
            for name in ("position", "normal")
            if name in program
        ]
        indices = ctx.buffer(np.ascontiguousarray(arrays["indices"], np.uint32))
        vertex_array = ctx.vertex_array(
            program, content, index_buffer=indices, index_element_size=4
        )
        _matrix(program, "modelMatrix", item["model"])
        _matrix(program, "normalMatrix", item["normal_matrix"])
        _matrix(program, "viewMatrix", job["view"])
        _matrix(program, "projectionMatrix", job["projection"])
        if "cameraPosition" in program:
            program["cameraPosition"].value = tuple(job["eye"])
        draws.append(vertex_array)
    pixels = np.empty((frame.height, frame.width, 4), dtype=np.float32)  # first: see gl.draw
    target = ctx.texture(size, 4, dtype="f4")
    depth = ctx.depth_renderbuffer(size)
    framebuffer = ctx.framebuffer(color_attachments=[target], depth_attachment=depth)
    framebuffer.use()
    framebuffer.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
    start = time.perf_counter()
    ctx.disable(moderngl.DEPTH_TEST)
    ctx.vertex_array(background, []).render(moderngl.TRIANGLES, vertices=3)
    ctx.enable(moderngl.DEPTH_TEST)
    for vertex_array in draws:
        vertex_array.render(moderngl.TRIANGLES)
    ctx.finish()
    seconds = [time.perf_counter() - start]
    return gl.read_frame(framebuffer, pixels), seconds


def glsl_version(job: dict[str, Any]) -> str:
    """The GLSL version the mesh programs are written in ("330", "300 es")."""
    first = job["draws"][0]["vertex"] if job["draws"] else job["background"]
    return _version_line(first).removeprefix("#version").strip()
