"""The render worker: `python -m glint.compiler.render.worker BYTES`, one frame per process, its
memory (RLIMIT_DATA) limited to BYTES.

It reads a job as JSON on stdin, renders, saves the image as `image.npy` and its outcome as
`result.json` in the job's directory. Files rather than stdout, because drivers may print there.
Running in its own process lets the parent kill a shader that never finishes or a crashing driver.
"""

from __future__ import annotations

import json
import os
import resource
import sys
from typing import Any

import numpy as np

from glint.compiler.render import gl, mesh_gl, passes


def run_job(job: dict[str, Any]) -> dict[str, Any]:
    """Render the job; return the outcome to report (status ok, environment, compile, memory or
    error)."""
    frame = gl.Frame(
        width=int(job["width"]),
        height=int(job["height"]),
        time=float(job["time"]),
        frame=int(job["frame"]),
        mouse=tuple(job["mouse"]),
        date=tuple(job["date"]),
        channels=tuple(None if path is None else np.load(path) for path in job.get("channels", [])),
        pictures=job.get("pictures"),
    )
    try:
        ctx = gl.create_context()
    except gl.ContextFailure as exc:
        return {"status": "environment", "message": str(exc)}
    renderer = f"{ctx.info.get('GL_RENDERER', '?')} (OpenGL {ctx.info.get('GL_VERSION', '?')})"
    try:
        return _draw(ctx, job, frame, renderer)
    except Exception as exc:
        # A driver that cannot allocate records GL_OUT_OF_MEMORY and moderngl then fails on
        # what it could not make (e.g. "the framebuffer is not complete"): say what it was.
        if ctx.error == "GL_OUT_OF_MEMORY":
            return {"status": "memory", "message": f"GL_OUT_OF_MEMORY ({exc})"}
        raise


def _draw(ctx: Any, job: dict[str, Any], frame: gl.Frame, renderer: str) -> dict[str, Any]:
    if job.get("kind") == "project":  # a ShaderToy project's passes, frame after frame
        try:
            image, seconds = passes.draw_project(ctx, job, frame)
        except gl.CompileFailure as exc:
            return {"status": "compile", "message": str(exc), "version": gl.glsl_version(ctx)}
        np.save(os.path.join(job["output_dir"], "image.npy"), image)
        return {"status": "ok", "renderer": renderer, "glsl_version": "300 es", "seconds": seconds}
    if job.get("kind") == "mesh":  # a mesh scene: background, then meshes (mesh_gl.py)
        try:
            image, seconds = mesh_gl.draw_meshes(ctx, job, frame)
        except gl.CompileFailure as exc:
            return {"status": "compile", "message": str(exc)}
        version = mesh_gl.glsl_version(job)
    else:
        try:
            program, version = gl.build_program(ctx, job["source"])
        except gl.CompileFailure as exc:
            return {"status": "compile", "message": str(exc), "version": gl.glsl_version(ctx)}
        image, seconds = gl.draw(ctx, program, frame, int(job.get("repeats", 1)))
    np.save(os.path.join(job["output_dir"], "image.npy"), image)
    return {"status": "ok", "renderer": renderer, "glsl_version": version, "seconds": seconds}


def limit_memory(argv: list[str]) -> None:
    """Take RLIMIT_DATA from the command line (`worker BYTES`; runner.py sizes it with
    limits.worker_memory_limit), before the driver is loaded: past it an allocation fails,
    which the worker reports as status "memory", instead of the machine running out."""
    if len(argv) > 1:
        limit = int(argv[1])
        resource.setrlimit(resource.RLIMIT_DATA, (limit, limit))


def main() -> int:
    limit_memory(sys.argv)
    job = json.load(sys.stdin)
    try:
        outcome = run_job(job)
    except MemoryError as exc:  # under the memory limit the parent set (runner.py)
        outcome = {"status": "memory", "message": f"MemoryError: {exc}"}
    except Exception as exc:  # report anything unexpected to the parent rather than a traceback
        outcome = {"status": "error", "message": f"{type(exc).__name__}: {exc}"}
    with open(os.path.join(job["output_dir"], "result.json"), "w", encoding="utf-8") as handle:
        json.dump(outcome, handle)
    return 0


if __name__ == "__main__":
    sys.exit(main())
