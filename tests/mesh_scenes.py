"""Scenes for the mesh tests, as dicts: one sphere under a sun and the sky, the raymarched
version of the same scene, and what varies between the tests."""

from __future__ import annotations

import copy
from typing import Any

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
