"""What a render may ask for: image size, time limit, uniform values, and the memory it takes.

`glint render`'s options and `glint.render`'s arguments are checked against these before any
work starts, so that a request the renderer cannot serve is a usage error with a message, not
an internal error or a machine out of memory. The renderer's child process also runs under a
memory limit sized here (`worker_memory_limit`). Light on imports: the CLI's argument parser
uses it.
"""

from __future__ import annotations

import math
import os
import resource

from glint.compiler.errors import UsageError

# Width and height, each; llvmpipe's textures go to 16384, and 8192 is already 67 M pixels.
MAX_SIDE = 8192
# The longest wall-clock limit a render may be given: an hour.
MAX_TIMEOUT_S = 3600.0
# iTime, iMouse are float32 in the shader: what does not fit becomes Inf there.
FLOAT32_MAX = 3.4028234663852886e38
# iFrame is a GLSL int (32 bits) and counts frames from 0.
MAX_FRAME = 2**31 - 1

# Bytes per pixel while one frame is rendered, saved and reported: the worker holds the RGBA32F
# render target (16), the array it is read into (16) and, for a mesh scene, a depth buffer (4);
# the array goes through a file (16, in memory where /tmp is a tmpfs) to the parent, which
# loads it (16) and writes the statistics and the PNG in bounded blocks (the PNG's own 8-bit
# arrays: 7). The worker and the parent do not hold their arrays at the same time. Measured at
# 4096x4096 (VmHWM less that at 8x8): the parent 23 bytes a pixel through glint.render and
# Image.save (134 before the statistics and the PNG went by blocks and the copies went), the
# worker 31 (see worker_memory_limit).
PIPELINE_BYTES_PER_PIXEL = 64
# What the worker needs before any pixel: Python, numpy, moderngl, Mesa, LLVM and one
# compiled shader (measured with two llvmpipe threads: 159 MB of VmData for the default scene
# and every example scene at the reference tier, up to 240 MB for the 40 largest ShaderToy
# shaders of the corpus), with room for larger shaders...
WORKER_BASE_BYTES = 512 << 20
# ...and each llvmpipe thread: measured 16 MB of VmData each (stack and arena) with
# LP_NUM_THREADS=32; llvmpipe starts one per CPU unless LP_NUM_THREADS says otherwise.
WORKER_BYTES_PER_THREAD = 32 << 20
# The worker's own share of PIPELINE_BYTES_PER_PIXEL: the render target and the array it is
# read into (32), and a mesh scene's depth buffer (4), rounded up.
WORKER_BYTES_PER_PIXEL = 40


def timeout_problem(seconds: float) -> str | None:
    """What is wrong with a time limit in seconds, or None."""
    if not 0.0 < seconds <= MAX_TIMEOUT_S:  # also false for NaN
        return f"must be more than 0 and at most {MAX_TIMEOUT_S:g} seconds"
    return None


def float32_problem(value: float) -> str | None:
    """What is wrong with a value for a float uniform (iTime, iMouse), or None."""
    if not abs(value) <= FLOAT32_MAX:  # also false for NaN
        largest = f"{FLOAT32_MAX:.3g}"
        return f"must be a finite number from -{largest} to {largest} (a GLSL float)"
    return None


def frame_problem(frame: int) -> str | None:
    """What is wrong with a value for iFrame, or None."""
    if not 0 <= frame <= MAX_FRAME:
        return f"must be from 0 to {MAX_FRAME} (iFrame is a 32-bit int counting from 0)"
    return None


def size_problem(width: int, height: int) -> str | None:
    """What is wrong with an image size, or None: each side 1..MAX_SIDE, and the pixels must
    fit in the memory this process may use (render_memory_needed against available_memory)."""
    if not (1 <= width <= MAX_SIDE and 1 <= height <= MAX_SIDE):
        return f"width and height must be 1..{MAX_SIDE}, got {width}x{height}"
    needed = render_memory_needed(width * height)
    available = available_memory()
    if available is not None and needed > available:
        return (
            f"{width}x{height} needs about {_size(needed)} of memory to render, and only "
            f"{_size(available)} is available here; choose a smaller size"
        )
    return None


def check_request(
    width: int,
    height: int,
    time: float,
    frame: int,
    mouse: tuple[float, float, float, float],
    timeout: float,
) -> None:
    """Raise UsageError, naming the argument, for values a render cannot take."""
    check_size(width, height)
    check_timeout(timeout)
    for name, value in (("time", time), *((f"mouse[{i}]", v) for i, v in enumerate(mouse))):
        problem = float32_problem(value)
        if problem is not None:
            raise UsageError(f"{name}: {problem}, got {value!r}")
    problem = frame_problem(frame)
    if problem is not None:
        raise UsageError(f"frame: {problem}, got {frame!r}")


def check_size(width: int, height: int) -> None:
    """Raise UsageError when size_problem finds one."""
    problem = size_problem(width, height)
    if problem is not None:
        raise UsageError(f"image size: {problem}")


def check_timeout(seconds: float) -> None:
    """Raise UsageError when timeout_problem finds one."""
    problem = timeout_problem(seconds)
    if problem is not None:
        raise UsageError(f"timeout: {problem}, got {seconds!r}")


def render_memory_needed(pixels: int) -> int:
    """Bytes a render of `pixels` pixels needs at its peak, the worker's base included."""
    return _worker_base() + PIPELINE_BYTES_PER_PIXEL * pixels


def worker_memory_limit(pixels: int, extra_bytes: int = 0) -> int:
    """RLIMIT_DATA for the worker that renders `pixels` pixels with `extra_bytes` of input
    (channel textures, mesh buffers): the base and the threads plus twice the pixels' and the
    input's bytes, within this process's own hard limit.

    RLIMIT_DATA, not RLIMIT_AS: llvmpipe maps far more address space than it uses (the
    default scene at 640x360 with two CPUs needs 613 MB of address space against 175 MB of
    data; with LP_NUM_THREADS=32, 1848 MB against 653 MB), and the address space grows with
    each thread's reserved malloc arena, so a limit on it would follow the CPU count more than
    the render. Since Linux 4.7 RLIMIT_DATA counts every private writable mapping, so numpy's
    and Mesa's large allocations are within it.

    Measured (the least limit, in 8 MB steps, under which the default scene renders; two
    CPUs): 159 MB at 640x360, 278 MB at 2048x2048, 669 MB at 4096x4096 (31 bytes a pixel);
    645 MB at 640x360 with LP_NUM_THREADS=32 (16 MB a thread). The limit here gives 594 MB at
    640x360 on two CPUs (3.7 times the default scene's need, 2.5 times the largest corpus
    shader's), 1.8 GB at 4096x4096 (2.8 times), 1.5 GB with 32 threads (2.4 times): no render
    that fits comes near it, while a shader or driver that runs away stops with a message
    ("the renderer ran out of memory") instead of taking the machine.
    """
    wanted = _worker_base() + 2 * (WORKER_BYTES_PER_PIXEL * pixels + extra_bytes)
    _, hard = resource.getrlimit(resource.RLIMIT_DATA)
    return wanted if hard == resource.RLIM_INFINITY else min(wanted, hard)


def _worker_base() -> int:
    return WORKER_BASE_BYTES + WORKER_BYTES_PER_THREAD * _llvmpipe_threads()


def _llvmpipe_threads() -> int:
    try:
        return max(1, int(os.environ["LP_NUM_THREADS"]))
    except (KeyError, ValueError):
        return os.cpu_count() or 1


def available_memory() -> int | None:
    """Bytes this process and its children may still take: the least of the system's
    MemAvailable (free memory and what the page cache can give back), the cgroup's remaining
    memory.max (a container's limit) and this process's RLIMIT_DATA; None when none is known."""
    found = [m for m in (_mem_available(), _cgroup_available(), _data_limit()) if m is not None]
    return min(found) if found else None


def _mem_available() -> int | None:
    try:
        with open("/proc/meminfo", encoding="ascii") as meminfo:
            for line in meminfo:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:  # not Linux, or an old kernel: free pages only (cache not counted)
        return os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (ValueError, OSError, AttributeError):
        return None


def _cgroup_available() -> int | None:
    """A container's memory limit less what its processes use (page cache that can be given
    back not counted as used), or None without a limit: cgroup v2's memory.max, or v1's
    memory.limit_in_bytes where the container sees its own cgroup at the root."""
    try:
        with open("/proc/self/cgroup", encoding="ascii") as cgroups:
            v2 = next((line.split(":", 2)[2].strip() for line in cgroups if line[:3] == "0::"), "")
        folder = os.path.join("/sys/fs/cgroup", v2.lstrip("/"))
        files = ("memory.max", "memory.current", "inactive_file")
        if not os.path.exists(os.path.join(folder, files[0])):
            folder = "/sys/fs/cgroup/memory"
            files = ("memory.limit_in_bytes", "memory.usage_in_bytes", "total_inactive_file")
        limit = _read_number(os.path.join(folder, files[0]))
        if limit is None or limit >= 2**60:  # "max", or v1's "no limit" (2**63 less a page)
            return None
        used = _read_number(os.path.join(folder, files[1])) or 0
        with open(os.path.join(folder, "memory.stat"), encoding="ascii") as stat:
            cache = next((int(line.split()[1]) for line in stat if line.split()[0] == files[2]), 0)
        return max(0, limit - used + cache)
    except (OSError, ValueError, IndexError):
        return None


def _read_number(path: str) -> int | None:
    with open(path, encoding="ascii") as handle:
        text = handle.read().strip()
    return None if text == "max" else int(text)


def _data_limit() -> int | None:
    soft, _ = resource.getrlimit(resource.RLIMIT_DATA)
    return None if soft == resource.RLIM_INFINITY else soft


def _size(count: int) -> str:
    gib = count / 2**30
    return f"{gib:.1f} GB" if gib >= 1 else f"{math.ceil(count / 2**20)} MB"
