"""[geometry] setup (a function run once per ray before the march, whose globals the field
reads) and detail (a height that tilts the shading normal and is never marched), on renders."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

import glint
from glint.compiler.errors import InputError
from glint.compiler.scene.model import scene_from_dict

SIZE = (80, 48)
FLOOR = "float floorDistance(vec3 p) { return p.y; }\n"


def _scene(tmp_path: Path, source: str, **geometry: Any) -> Any:
    (tmp_path / "field.glsl").write_text(source)
    data = {
        "camera": {"type": "lookat", "position": [0.0, 1.0, 3.0], "target": [0.0, 0.3, 0.0]},
        "geometry": {"file": "field.glsl", "material": "stone", **geometry},
        "materials": {"stone": {"albedo": [0.6, 0.6, 0.6], "roughness": 0.5}},
        "lights": [{"type": "directional", "direction": [0.5, 0.6, 0.2], "intensity": 3.0}],
        "effects": {"ao": False},
        "background": {"color": [0.0, 0.0, 0.0], "tonemap": False},  # rays that miss: 0
    }
    return scene_from_dict(data, str(tmp_path / "scene.toml"))


def _pixels(scene: Any, time: float = 0.0) -> np.ndarray:
    image = glint.render(glint.compose(scene), size=SIZE, time=time)
    assert image.stats["nan"] == 0
    return np.asarray(image.pixels, np.float64)


def test_setup_runs_before_the_march_and_its_globals_shape_the_field(tmp_path: Path) -> None:
    """A radius set by setup from iTime draws what the same radius written into the field
    draws; without the setup call the global stays 0 and the picture differs."""
    setup = (
        "float radius;\nvoid prepare() { radius = 0.5 + 0.25 * iTime; }\n"
        "float sceneDistance(vec3 p) { return min(length(p) - radius, p.y + 1.0); }\n"
    )
    fixed = "float sceneDistance(vec3 p) { return min(length(p) - 1.0, p.y + 1.0); }\n"
    by_setup = _pixels(_scene(tmp_path, setup, setup="prepare"), time=2.0)
    written = _pixels(_scene(tmp_path, fixed), time=2.0)
    np.testing.assert_allclose(by_setup, written, atol=1e-5)
    by_setup_at_0 = _pixels(_scene(tmp_path, setup, setup="prepare"), time=0.0)
    assert np.mean(np.abs(by_setup_at_0 - written)) > 0.01


def test_detail_tilts_the_shading_but_not_the_silhouette(tmp_path: Path) -> None:
    """Ripples on a floor seen up to its horizon: the floor's shading ripples from pixel to
    pixel where it was smooth, the horizon (where rays miss) stays where it was, and a detail
    of zero height changes nothing."""
    field = "float sceneDistance(vec3 p) { return p.y; }\n"
    ripples = "float ripples(vec3 p) { return 0.02 * sin(20.0 * p.x); }\n"
    flat_height = "float nothing(vec3 p) { return 0.0; }\n"
    flat = _pixels(_scene(tmp_path, field))
    rippled = _pixels(_scene(tmp_path, field + ripples, detail="ripples"))
    unchanged = _pixels(_scene(tmp_path, field + flat_height, detail="nothing"))
    np.testing.assert_allclose(unchanged, flat, atol=1e-6)
    ground = flat[..., 0] > 0.0
    assert 0.2 < ground.mean() < 0.9
    np.testing.assert_array_equal(ground, rippled[..., 0] > 0.0)

    def ripple(image: np.ndarray) -> float:
        return float(np.abs(np.diff(image[..., 0], axis=1))[ground[:, 1:]].mean())

    assert ripple(rippled) > 5 * ripple(flat)


@pytest.mark.parametrize(
    ("source", "geometry", "says"),
    [
        ("float sceneDistance(vec3 p) { return p.y; }\n", {"setup": "prepare"},
         "geometry.setup: .* defines no `void prepare\\(\\)`"),
        ("float sceneDistance(vec3 p) { return p.y; }\nfloat prepare() { return 1.0; }\n",
         {"setup": "prepare"}, "geometry.setup calls it as void prepare\\(\\)"),
        ("float sceneDistance(vec3 p) { return p.y; }\nfloat bump(vec2 p) { return 0.0; }\n",
         {"detail": "bump"}, "geometry.detail calls it as float bump\\(vec3\\)"),
    ],
)  # fmt: skip
def test_a_hook_that_is_not_there_is_named(
    tmp_path: Path, source: str, geometry: dict[str, str], says: str
) -> None:
    with pytest.raises(InputError, match=says):
        glint.compose(_scene(tmp_path, source, **geometry))
