"""Render a ShaderToy shader in a child process, under a wall-clock limit and a memory limit.

A shader can loop forever, a driver can crash or allocate without end; each must cost the tool
one error message, never a hang, the machine's memory or the tool's own life. So each frame is
drawn by `worker.py` in a fresh process, which is killed, with everything it started, when the
time is up, and which may use no more memory than limits.worker_memory_limit allows.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from glint.compiler.errors import EnvironmentProblem, InputError, UsageError
from glint.compiler.render import gl, limits
from glint.compiler.target.shadertoy_project import ChannelInput, Project
from glint.compiler.target.sourcemap import MARKER as SOURCE_MARKER
from glint.compiler.target.sourcemap import build_line_map, split_lines

DEFAULT_TIMEOUT_S = 60.0
DEFAULT_DATE = (2026.0, 0.0, 1.0, 0.0)  # ShaderToy's iDate: year, month from 0, day, seconds
_STDERR_TAIL = 2000
_DRIVER_LINE = re.compile(r"^\d+:(\d+)\((\d+)\):")
# The headings moderngl puts around the driver's log.
_BOILERPLATE = re.compile(r"^(GLSL (Compiler|Linker) failed|\w+_shader|=+)\s*$")


@dataclass
class RenderResult:
    """One rendered frame: float32 H x W x 4, row 0 at the top, and how it was made."""

    image: np.ndarray
    renderer: str  # GL_RENDERER and version, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) (OpenGL 4.5 …)"
    glsl_version: str  # "300 es", or "330" where the driver lacks ES 3.00 shaders
    draw_seconds: float  # time of the (first) draw call alone; on llvmpipe this is CPU time
    draw_times: list[float]  # seconds of each of the `repeats` draws, the first included


def _tail(text: str) -> str:
    text = text.strip()
    return text if len(text) <= _STDERR_TAIL else "…" + text[-_STDERR_TAIL:]


def _kill(process: subprocess.Popen[bytes]) -> None:
    """Kill the worker and any thread or child it started (it leads its own process group)."""
    with contextlib.suppress(ProcessLookupError):
        os.killpg(process.pid, signal.SIGKILL)
    process.wait()


def _run_worker(job: dict[str, object], timeout: float, memory_limit: int) -> str:
    """Run the worker on `job`; return its stderr. Raises InputError on timeout, a crash or
    running out of memory.

    The worker sets its own RLIMIT_DATA to `memory_limit` as the first thing it does (see
    worker.main), rather than a preexec_fn here: preexec_fn is not safe in a process that has
    threads (the site's preview server has one), and the limit applies all the same to every
    allocation that matters, the driver's and the image's."""
    process = subprocess.Popen(
        [sys.executable, "-m", "glint.compiler.render.worker", str(memory_limit)],
        stdin=subprocess.PIPE,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    try:
        _, stderr = process.communicate(json.dumps(job).encode(), timeout=timeout)
    except subprocess.TimeoutExpired:
        _kill(process)
        raise InputError(
            f"rendering did not finish within {timeout:g} s: the shader may loop forever or be "
            "too slow for the software renderer; bound its loops or raise the time limit"
        ) from None
    except BaseException:
        _kill(process)  # e.g. Ctrl-C: leave no worker behind
        raise
    message = stderr.decode(errors="replace")
    if process.returncode == -signal.SIGKILL or _OUT_OF_MEMORY.search(message):
        # Nothing here kills the worker but the watchdog above: a SIGKILL is the system's
        # out-of-memory killer; a driver that failed to allocate says so on stderr.
        raise InputError(_out_of_memory(job, memory_limit, message))
    if process.returncode < 0:
        name = signal.Signals(-process.returncode).name
        raise InputError(
            f"the renderer crashed ({name}) while drawing this shader; the driver said: "
            f"{_tail(message) or 'nothing'}"
        )
    if process.returncode != 0:
        raise InputError(
            f"the renderer failed (exit status {process.returncode}): {_tail(message) or '?'}"
        )
    return message


# What a driver, LLVM or the C library writes when an allocation fails.
_OUT_OF_MEMORY = re.compile(
    r"out of memory|cannot allocate memory|bad_alloc|MemoryError|GL_OUT_OF_MEMORY", re.IGNORECASE
)


def _out_of_memory(job: dict[str, object], memory_limit: int, detail: str) -> str:
    size = f"{job['width']}x{job['height']}"
    return (
        f"the renderer ran out of memory drawing a {size} image (its limit was "
        f"{memory_limit / 2**20:.0f} MB, the machine has "
        f"{_megabytes(limits.available_memory())} available): render a smaller size, or "
        f"simplify the shader; the renderer said: {_tail(detail) or 'nothing'}"
    )


def _megabytes(count: int | None) -> str:
    return "an unknown amount" if count is None else f"{count / 2**20:.0f} MB"


def _outcome(output_dir: str, stderr: str) -> dict[str, object]:
    path = os.path.join(output_dir, "result.json")
    try:
        with open(path, encoding="utf-8") as handle:
            outcome: dict[str, object] = json.load(handle)
    except (OSError, ValueError):
        raise InputError(f"the renderer stopped without a result: {_tail(stderr) or '?'}") from None
    return outcome


def driver_log(log: str, source: str, version: str) -> str:
    """Mesa's compile log with its line numbers moved from the wrapped shader to the user's code.

    Mesa writes `0:LINE(COLUMN): error: ...`; this becomes `LINE:COLUMN: error: ...`, or
    `FILE:LINE:COLUMN: error: ...` where a source marker names the line's own file.
    """
    _, prelude_lines = gl.wrap(source, version)
    user_lines = len(split_lines(source))
    # source markers (a composed shader's snippets, an included file) name the line's own file
    marked = any(SOURCE_MARKER.match(text) for text in source.split("\n"))
    origins = build_line_map(source, "") if marked else []

    def relocate(match: re.Match[str]) -> str:
        line = int(match.group(1)) - prelude_lines
        if 1 <= line <= user_lines:
            origin = origins[line - 1] if origins else None
            if origin is not None and origin.file:
                return f"{origin.file}:{origin.line}:{match.group(2)}:"
            return f"{line}:{match.group(2)}:"
        return "(in the main that ShaderToy appends, which calls mainImage):"

    kept = [line for line in log.splitlines() if line.strip() and not _BOILERPLATE.match(line)]
    return "\n".join(_DRIVER_LINE.sub(relocate, line) for line in kept) or log


def _save_channels(channels: Sequence[np.ndarray | None], output_dir: str) -> list[str | None]:
    """Write channel data where the worker can load it; at most four, each H x W x 4 (None
    for a channel left black)."""
    if len(channels) > 4:
        raise UsageError(f"ShaderToy has four channels, got {len(channels)}")
    paths: list[str | None] = []
    for unit, data in enumerate(channels):
        if data is None:
            paths.append(None)
            continue
        if data.ndim != 3 or data.shape[2] != 4:
            raise UsageError(f"iChannel{unit} data must be H x W x 4, got shape {data.shape}")
        path = os.path.join(output_dir, f"channel{unit}.npy")
        np.save(path, data.astype(np.float32))
        paths.append(path)
    return paths


def _input_bytes(job: dict[str, object]) -> int:
    """What the worker loads besides the image: channel data and mesh arrays, counted twice
    (the loaded array and the driver's copy)."""
    paths = list(job.get("channels", []))  # type: ignore[call-overload]
    paths += [
        entry.get("path")
        for item in job.get("passes", [])
        for entry in item["inputs"]  # type: ignore[attr-defined]
    ]
    paths += [draw["arrays"] for draw in job.get("draws", [])]  # type: ignore[attr-defined]
    return 2 * sum(os.path.getsize(path) for path in paths if path is not None)


def render_full(
    source: str,
    width: int = 640,
    height: int = 360,
    time: float = 0.0,
    frame: int = 0,
    mouse: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0),
    timeout: float = DEFAULT_TIMEOUT_S,
    date: tuple[float, float, float, float] = DEFAULT_DATE,
    channels: Sequence[np.ndarray | None] = (),
    repeats: int = 1,
    pictures: str | None = None,
) -> RenderResult:
    """Render one frame of a ShaderToy Image-tab shader; see `render`. With `repeats` > 1 the
    frame is drawn that many times in one context and every draw is timed (for benchmarks).
    `channels`: data for iChannel0.. (None: black); `pictures`: sample them as a picture,
    repeating, "mipmap" (ShaderToy's default) or "linear" (no mipmaps, as wgpu-shadertoy
    does), rather than texel by texel (None: probes' data)."""
    limits.check_request(width, height, time, frame, mouse, timeout)
    with tempfile.TemporaryDirectory(prefix="glint-render-") as output_dir:
        job = {
            "source": source,
            "width": width,
            "height": height,
            "time": time,
            "frame": frame,
            "mouse": list(mouse),
            "date": list(date),
            "output_dir": output_dir,
            "channels": _save_channels(channels, output_dir),
            "repeats": max(1, repeats),
            "pictures": pictures,
        }

        def rejected(message: str, outcome: dict[str, object]) -> str:
            log = driver_log(message, source, str(outcome.get("version", "300 es")))
            return f"the OpenGL driver rejected the shader:\n{log}"

        return run_job(job, timeout, rejected)


def render_project(
    project: Project,
    width: int = 640,
    height: int = 360,
    time: float = 0.0,
    frames: int = 1,
    mouse: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0),
    timeout: float = DEFAULT_TIMEOUT_S,
) -> RenderResult:
    """Draw a ShaderToy project (render/passes.py): `frames` frames from iTime `time`, 1/60 s
    apart, and return the Image of the last one."""
    limits.check_request(width, height, time, frames - 1, mouse, timeout)
    unbound = project.unbound_reads()
    if unbound:
        name, channel = unbound[0]
        raise InputError(
            f"{project.origin}: {name} reads iChannel{channel}, which nothing is bound to (it "
            "would sample black); bind it (an input of the pass in the JSON, or a key of its "
            "table in channels.toml)"
        )
    with tempfile.TemporaryDirectory(prefix="glint-project-") as output_dir:
        passes = []
        for index, item in enumerate(project.passes):
            inputs = [
                _project_input(entry, f"{item.name}: iChannel{entry.channel}",
                               os.path.join(output_dir, f"channel-{index}-{entry.channel}.npy"))
                for entry in item.inputs
                if entry.kind != "silent"  # black, as every unbound channel
            ]  # fmt: skip
            passes.append({"name": item.name, "source": project.source(item),
                           "buffer": item.buffer, "inputs": inputs})  # fmt: skip
        job = {
            "kind": "project",
            "passes": passes,
            "width": width,
            "height": height,
            "time": time,
            "frame": 0,
            "frames": frames,
            "mouse": list(mouse),
            "date": list(DEFAULT_DATE),
            "output_dir": output_dir,
        }

        def rejected(message: str, outcome: dict[str, object]) -> str:
            return f"the OpenGL driver rejected a pass of {project.origin}:\n{message}"

        return run_job(job, timeout, rejected)


def _project_input(entry: ChannelInput, where: str, path: str) -> dict[str, object]:
    """One channel input of a project's pass as the worker takes it; a picture's data saved at
    `path` (a texture: bottom row first where vflip; a cubemap: its six faces, each's row 0 at
    t = 0, as WebGL uploads a face)."""
    from glint.compiler.render.images import channel_picture

    read: dict[str, object] = {
        "channel": entry.channel, "kind": entry.kind, "buffer": entry.buffer,
        "filter": entry.filter, "wrap": entry.wrap,
    }  # fmt: skip
    if entry.kind == "texture":
        assert entry.file is not None
        data = channel_picture(str(entry.file), where)  # bottom row first
        np.save(path, data if entry.vflip else np.ascontiguousarray(data[::-1]))
        read["path"] = path
    elif entry.kind == "cubemap":
        faces = [channel_picture(str(face), where) for face in entry.faces]
        faces = [face if entry.vflip else face[::-1] for face in faces]
        if len({face.shape for face in faces}) != 1 or faces[0].shape[0] != faces[0].shape[1]:
            raise InputError(f"{where}: a cubemap's six faces must be squares of one size")
        np.save(path, np.ascontiguousarray(np.stack(faces)))
        read["path"] = path
    return read


def run_job(
    job: dict[str, object], timeout: float, rejected: Callable[[str, dict[str, object]], str]
) -> RenderResult:
    """Run a render job in the worker and read back its image, or raise the error its outcome
    says; `rejected(message, outcome)` words a compile error. The job's output_dir must exist
    until this returns."""
    memory_limit = limits.worker_memory_limit(
        int(job["width"]) * int(job["height"]),  # type: ignore[call-overload]
        _input_bytes(job),
    )
    stderr = _run_worker(job, timeout, memory_limit)
    outcome = _outcome(str(job["output_dir"]), stderr)
    status, message = outcome.get("status"), str(outcome.get("message", ""))
    if status == "memory":
        raise InputError(_out_of_memory(job, memory_limit, message))
    if status == "environment":
        raise EnvironmentProblem(
            f"{message}; install {gl.EGL_PACKAGES} (Debian) or run `make setup`"
        )
    if status == "compile":
        raise InputError(rejected(message, outcome))
    if status != "ok":
        raise InputError(f"rendering failed: {message}")
    return RenderResult(
        image=np.load(os.path.join(str(job["output_dir"]), "image.npy")),
        renderer=str(outcome["renderer"]),
        glsl_version=str(outcome["glsl_version"]),
        draw_seconds=float(outcome["seconds"][0]),  # type: ignore[index]
        draw_times=[float(t) for t in outcome["seconds"]],  # type: ignore[union-attr]
    )


def render(
    source: str,
    width: int = 640,
    height: int = 360,
    time: float = 0.0,
    frame: int = 0,
    mouse: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0),
    timeout: float = DEFAULT_TIMEOUT_S,
    date: tuple[float, float, float, float] = DEFAULT_DATE,
    channels: Sequence[np.ndarray] = (),
) -> np.ndarray:
    """Render one frame of a ShaderToy Image-tab shader (no #version, no uniforms).

    Returns float32 H x W x 4 with row 0 at the top of the picture. Raises InputError when the
    shader does not compile, does not finish within `timeout` seconds or crashes the driver, and
    EnvironmentProblem when no OpenGL context can be created.
    """
    return render_full(source, width, height, time, frame, mouse, timeout, date, channels).image
