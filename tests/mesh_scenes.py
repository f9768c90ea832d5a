"""Scenes for the mesh tests, as dicts: one sphere under a sun and the sky, the raymarched
version of the same scene, and what varies between the tests. And the example scenes split
into raymarched and mesh ones, for the tests that loop over the examples."""

from __future__ import annotations

import copy
from typing import Any

import pytest

from glint.compiler.scene.model import default_scene_path, load_scene

EXAMPLES = sorted(default_scene_path().parent.glob("*.toml"))
MESH_EXAMPLES = [path for path in EXAMPLES if load_scene(path).is_mesh]
RAYMARCHED_EXAMPLES = [path for path in EXAMPLES if path not in MESH_EXAMPLES]


def example_params(mesh_reason: str) -> list[Any]:
    """Every example scene file as a pytest parameter named by its stem; the mesh scenes
    marked skipped with `mesh_reason` (why a test of ShaderToy shaders leaves them out)."""
    mesh_skip = pytest.mark.skip(reason=f"mesh scene: {mesh_reason}")
    return [
        pytest.param(path, id=path.stem, marks=[mesh_skip] if path in MESH_EXAMPLES else [])
        for path in EXAMPLES
    ]


# Shadows and AO need a distance field: off here so that the raymarched sphere is lit as the
# mesh is (the mesh programs ignore both).
BASE: dict[str, Any] = {
    "name": "mesh test",
    "camera": {"type": "lookat", "position": [0.0, 0.8, 2.6], "target": [0.0, 0.0, 0.0]},
    "materials": {"red": {"albedo": [0.8, 0.1, 0.1], "roughness": 0.4}},
    "lights": [
        {"type": "directional", "direction": [0.5, 0.8, 0.3], "shadow": False},
        {"type": "sky"},
    ],
    "effects": {"ao": False},
}


def mesh_scene(
    builtin: str = "uv_sphere", subdivisions: int = 3, shading: str = "phong", **more: Any
) -> dict[str, Any]:
    sphere = {"shape": "mesh", "builtin": builtin, "subdivisions": subdivisions}
    scene = {**BASE, "objects": [{**sphere, "material": "red"}], "mesh": {"shading": shading}}
    return copy.deepcopy({**scene, **more})  # tests change it


def raymarched_scene() -> dict[str, Any]:
    return copy.deepcopy({**BASE, "objects": [{"shape": "sphere", "material": "red"}]})
