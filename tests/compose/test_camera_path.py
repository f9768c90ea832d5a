"""A keyframed camera path (camera.type = "path"): at each key's time the picture is the
look-at camera's at that key; an open path holds at its last key; a loop comes back."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glint
from glint.compiler.errors import InputError
from glint.compiler.scene.model import scene_from_dict

SIZE = (64, 40)
KEYS = [
    {"time": 0.0, "position": [0.0, 1.0, 4.0], "target": [0.0, 0.0, 0.0]},
    {"time": 1.5, "position": [3.5, 2.0, 1.0], "target": [0.0, 0.5, 0.0]},
    {"time": 4.0, "position": [-1.0, 1.5, -3.5], "target": [0.2, 0.0, 0.0]},
]


def _scene(camera: dict[str, Any]) -> dict[str, Any]:
    return {
        "camera": camera,
        "objects": [
            {"shape": "box", "size": [1.0, 0.6, 0.4], "material": "m"},
            {"shape": "plane", "offset": 0.3, "material": "m"},
        ],
        "materials": {"m": {"albedo": [0.6, 0.5, 0.4]}},
        "lights": [{"type": "directional", "direction": [0.3, 1.0, 0.2]}],
    }


def _pixels(scene: dict[str, Any], time: float) -> np.ndarray:
    return np.asarray(glint.render(glint.compose(scene), size=SIZE, time=time).pixels)


@pytest.mark.parametrize("loop", [False, True])
def test_the_path_passes_through_every_key_at_its_time(loop: bool) -> None:
    path = _scene({"type": "path", "keys": KEYS, "loop": loop})
    for key in KEYS:
        fixed = _scene({"type": "lookat", "position": key["position"], "target": key["target"]})
        np.testing.assert_allclose(_pixels(path, key["time"]), _pixels(fixed, 0.0), atol=2e-3)
    between = _pixels(path, 0.75)
    assert np.mean(np.abs(between - _pixels(path, 0.0))) > 0.01


def test_an_open_path_holds_at_its_last_key_and_a_loop_comes_round() -> None:
    open_path = _scene({"type": "path", "keys": KEYS})
    np.testing.assert_allclose(_pixels(open_path, 9.0), _pixels(open_path, 4.0), atol=1e-6)
    loop = _scene({"type": "path", "keys": KEYS, "loop": True})
    period = 4.0 + 1.5  # the last key's time and a closing segment as long as the first
    np.testing.assert_allclose(_pixels(loop, period + 0.75), _pixels(loop, 0.75), atol=2e-3)


def test_keys_out_of_order_are_refused() -> None:
    keys = [KEYS[0], {**KEYS[1], "time": 0.0}]
    with pytest.raises(InputError, match=r"camera: keys\[1\].time: 0 is not after"):
        scene_from_dict(_scene({"type": "path", "keys": keys}))


def test_a_far_camera_still_reaches_its_scene() -> None:
    """A look-at camera 80 units from a large sphere: the march's far limit grows with the
    eye's distance (its default, 50, would stop short and draw only the background)."""
    scene = {
        "camera": {
            "type": "lookat",
            "position": [0.0, 10.0, 80.0],
            "target": [0.0, 0.0, 0.0],
            "focal": 6.0,
        },  # fmt: skip
        "objects": [{"shape": "sphere", "radius": 5.0, "material": "m"}],
        "materials": {"m": {"albedo": [0.9, 0.2, 0.1]}},
        "lights": [{"type": "directional", "direction": [0.3, 1.0, 0.5]}],
        "background": {"color": [0.0, 0.0, 0.0], "tonemap": False},
    }

    def red(scene: dict[str, Any], tier: str) -> float:
        pixels = np.asarray(glint.render(glint.compose(scene, tier=tier), size=SIZE).pixels)
        return float((pixels[..., 0] > 0.3).mean())

    for tier in ("fast", "balanced", "reference"):
        assert red(scene, tier) > 0.03, tier  # the red sphere in the middle
    # the old limit, given back by hand, draws nothing: what a far camera used to get
    assert red({**scene, "quality": {"params": {"MARCH_FAR": 50.0}}}, "balanced") == 0.0
