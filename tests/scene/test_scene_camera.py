"""A camera straight above or below its target (its line of sight parallel to the world's
up) sees the scene: the look-at basis of the camera snippets and of the mesh camera takes the
world's x for the screen's then, instead of normalising a zero vector."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from scene_inputs import base_scene

import glint
from glint.compiler.scene.model import scene_from_dict


def test_the_mesh_camera_has_a_basis_straight_down_and_up() -> None:
    from glint.compiler.compose.mesh.camera import camera_matrices

    for y in (4.0, -4.0):
        scene = scene_from_dict(base_scene(camera={"type": "lookat", "position": [0.0, y, 0.0]}))
        view = camera_matrices(scene, (64, 64), (0.1, 10.0)).view
        assert np.isfinite(view).all()
        assert np.allclose(view[:3, :3] @ view[:3, :3].T, np.eye(3))
        # looking down, the screen's up is -z; looking up, +z
        assert np.allclose(view[1, :3], [0.0, 0.0, -1.0 if y > 0 else 1.0])


@pytest.mark.render
@pytest.mark.parametrize(
    "camera",
    [
        {"type": "lookat", "position": [0.0, 4.0, 0.0], "target": [0.0, 0.0, 0.0]},
        {"type": "lookat", "position": [0.0, -4.0, 0.0], "target": [0.0, 0.0, 0.0]},
        {"type": "orbit", "radius": 1e-20, "height": 4.0, "speed": 0.0},
    ],
    ids=["above", "below", "orbit-overhead"],
)
def test_a_camera_straight_above_or_below_sees_the_sphere(camera: dict[str, Any]) -> None:
    grey = [0.1, 0.1, 0.1]
    data = base_scene(camera=camera, environment={"top": grey, "bottom": grey},
                      background={"sun": False})  # fmt: skip
    data["lights"] = [
        {
            "type": "directional",
            "direction": [0.3, 1.0, -0.2]
            if camera.get("position", [0, 1, 0])[1] > 0
            else [0.3, -1.0, -0.2],
            "shadow": False,
        }
    ]
    image = glint.render(data, size=(64, 64))
    pixels = image.pixels
    assert np.isfinite(pixels).all()
    centre, corner = pixels[32, 32], pixels[2, 2]
    assert centre[0] > corner[0] + 0.1, (centre, corner)  # the red sphere, in the middle
    sphere = np.abs(pixels - corner).max(axis=-1) > 0.05
    assert 0.05 < sphere.mean() < 0.6  # a disc in the middle, not one flat colour
