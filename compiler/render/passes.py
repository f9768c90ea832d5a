"""Drawing a ShaderToy project in the render worker: its buffers and its Image, frame after frame,
as ShaderToy draws them (target/shadertoy_project.py says what a project is).

Each buffer is two float32 textures, one drawn into while the other is read (ping-pong): a pass
that reads a buffer sees what that buffer drew last, this frame's for a buffer drawn before it
and the previous frame's for itself and the buffers after it. Buffers start black. Pictures are
the job's arrays (bottom row first where the input flips them, as ShaderToy does). Each frame
advances iTime by iTimeDelta and iFrame by one; the Image of the last frame is the result.
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from glint.compiler.render import gl


def draw_project(ctx: Any, job: dict[str, Any], frame: gl.Frame) -> tuple[np.ndarray, list[float]]:
    """The Image of the job's last frame (row 0 at the top) and the time each frame took."""
    import moderngl

    width, height = frame.width, frame.height
    programs = []
    for item in job["passes"]:
        try:
            programs.append(gl.build_program(ctx, item["source"])[0])
        except gl.CompileFailure as exc:  # say which pass
            raise gl.CompileFailure(f"{item['name']}: {exc}") from None
    pictures = {
        (index, entry["channel"]): (
            _cube(ctx, np.load(entry["path"]), entry)
            if entry["kind"] == "cubemap"
            else _picture(ctx, np.load(entry["path"]), entry)
        )
        for index, item in enumerate(job["passes"])
        for entry in item["inputs"]
        if entry["kind"] in ("texture", "cubemap")
    }
    buffers = {
        item["buffer"]: [_target(ctx, width, height) for _ in range(2)]
        for item in job["passes"]
        if item["buffer"]
    }
    latest = dict.fromkeys(buffers, 0)  # which of the two each buffer drew last
    image = _target(ctx, width, height)
    black = ctx.texture((1, 1), 4, np.zeros(4, np.float32).tobytes(), dtype="f4")
    vertex_arrays = [ctx.vertex_array(program, []) for program in programs]
    step = float(job.get("time_delta", 1.0 / 60.0))
    seconds = []
    for number in range(int(job.get("frames", 1))):
        start = time.perf_counter()
        now = gl.Frame(width, height, frame.time + number * step, number, frame.mouse, frame.date)
        for index, item in enumerate(job["passes"]):
            program = programs[index]
            sizes = np.ones((4, 3), np.float32)
            for unit in range(4):
                black.use(location=unit)
            for entry in item["inputs"]:
                unit = entry["channel"]
                if entry["kind"] == "buffer":
                    texture = buffers[entry["buffer"]][latest[entry["buffer"]]][0]
                    _sample(texture, entry)
                    sizes[unit] = (width, height, 1.0)
                else:
                    texture = pictures[(index, unit)]
                    sizes[unit] = (texture.size[0], texture.size[1], 1.0)
                texture.use(location=unit)
            if item["buffer"]:
                into = 1 - latest[item["buffer"]]
                framebuffer = buffers[item["buffer"]][into][1]
            else:
                framebuffer = image[1]
            framebuffer.use()
            gl.set_uniforms(program, now)
            if "iChannelResolution" in program:
                program["iChannelResolution"].value = [tuple(row) for row in sizes][
                    : program["iChannelResolution"].array_length
                ]
            if "iTimeDelta" in program:
                program["iTimeDelta"].value = step
            vertex_arrays[index].render(moderngl.TRIANGLES, vertices=3)
            if item["buffer"]:
                latest[item["buffer"]] = into
        ctx.finish()
        seconds.append(time.perf_counter() - start)
    pixels = np.empty((height, width, 4), dtype=np.float32)
    return gl.read_frame(image[1], pixels), seconds


def _target(ctx: Any, width: int, height: int) -> tuple[Any, Any]:
    """A black float texture and the framebuffer that draws into it."""
    texture = ctx.texture((width, height), 4, dtype="f4")
    framebuffer = ctx.framebuffer(color_attachments=[texture])
    framebuffer.clear(0.0, 0.0, 0.0, 0.0)
    return texture, framebuffer


def _picture(ctx: Any, data: np.ndarray, entry: dict[str, Any]) -> Any:
    rows, cols = data.shape[:2]
    texture = ctx.texture((cols, rows), 4, np.ascontiguousarray(data, np.float32), dtype="f4")
    if entry["filter"] == "mipmap":
        texture.build_mipmaps()
    _sample(texture, entry)
    return texture


def _cube(ctx: Any, faces: np.ndarray, entry: dict[str, Any]) -> Any:
    """A cube map from six faces (+x, -x, +y, -y, +z, -z), each's row 0 at t = 0."""
    size = faces.shape[1]
    texture = ctx.texture_cube((size, size), 4, np.ascontiguousarray(faces, np.float32), dtype="f4")
    if entry["filter"] == "mipmap":
        texture.build_mipmaps()
    _sample(texture, entry, wraps=False)  # a direction never leaves a cube
    return texture


def _sample(texture: Any, entry: dict[str, Any], wraps: bool = True) -> None:
    """The input's sampler: its filter and wrap (a buffer is never mipmapped here: linear)."""
    import moderngl

    mipmapped = entry["filter"] == "mipmap" and entry["kind"] in ("texture", "cubemap")
    if entry["filter"] == "nearest":
        texture.filter = (moderngl.NEAREST, moderngl.NEAREST)
    elif mipmapped:
        texture.filter = (moderngl.LINEAR_MIPMAP_LINEAR, moderngl.LINEAR)
    else:
        texture.filter = (moderngl.LINEAR, moderngl.LINEAR)
    if wraps:
        texture.repeat_x = texture.repeat_y = entry["wrap"] == "repeat"
