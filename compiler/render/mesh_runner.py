"""Render a mesh scene's programs in the worker process, under the same time limit, with the
same float framebuffer and outcome as a ShaderToy frame (runner.py)."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from glint.compiler.render import limits
from glint.compiler.render.runner import DEFAULT_DATE, DEFAULT_TIMEOUT_S, RenderResult, run_job


@dataclass(frozen=True)
class MeshDraw:
    """One mesh drawn with one program: its shaders, triangles and placement."""

    name: str  # says which program failed, if one does
    vertex: str  # complete vertex shader
    fragment: str  # complete fragment shader
    positions: np.ndarray  # float32 V x 3, object space
    normals: np.ndarray  # float32 V x 3
    indices: np.ndarray  # uint32 F x 3
    model: np.ndarray  # 4x4 row-major
    normal_matrix: np.ndarray  # 3x3 row-major


@dataclass(frozen=True)
class MeshView:
    """The camera, as the mesh programs' uniforms take it."""

    eye: np.ndarray  # (3,)
    view: np.ndarray  # 4x4 row-major
    projection: np.ndarray  # 4x4 row-major


def render_meshes(
    background: str,
    draws: Sequence[MeshDraw],
    camera: MeshView,
    width: int = 640,
    height: int = 360,
    time: float = 0.0,
    mouse: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0),
    timeout: float = DEFAULT_TIMEOUT_S,
) -> RenderResult:
    """Draw `background` (a complete full-screen fragment shader with ShaderToy's uniforms),
    then every mesh with the depth test. Raises as `runner.render_full` does."""
    limits.check_request(width, height, time, 0, mouse, timeout)
    with tempfile.TemporaryDirectory(prefix="glint-render-") as output_dir:
        items = []
        for index, draw in enumerate(draws):
            arrays = os.path.join(output_dir, f"mesh{index}.npz")
            np.savez(arrays, position=draw.positions, normal=draw.normals, indices=draw.indices)
            items.append(
                {
                    "name": draw.name,
                    "vertex": draw.vertex,
                    "fragment": draw.fragment,
                    "arrays": arrays,
                    "model": np.asarray(draw.model).tolist(),
                    "normal_matrix": np.asarray(draw.normal_matrix).tolist(),
                }
            )
        job = {
            "kind": "mesh",
            "background": background,
            "draws": items,
            "eye": np.asarray(camera.eye).tolist(),
            "view": np.asarray(camera.view).tolist(),
            "projection": np.asarray(camera.projection).tolist(),
            "width": width,
            "height": height,
            "time": time,
            "frame": 0,
            "mouse": list(mouse),
            "date": list(DEFAULT_DATE),
            "output_dir": output_dir,
        }
        return run_job(job, timeout, lambda message, _: f"the OpenGL driver rejected the {message}")
