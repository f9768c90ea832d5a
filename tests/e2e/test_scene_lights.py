"""Spot and area lights, emission, the background shown as given, the linear output, the
camera's field of view, roll and start angle, anti-aliasing and [quality.params]: each judged on
what a user sees in a real render (moderngl on the machine's GL), or on the exact number the
feature must produce, not on the text glint writes."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import glint
from glint.compiler.bench.approximations import area_errors
from glint.compiler.errors import InputError
from glint.compiler.scene.model import scene_from_dict

SIZE = (96, 64)


def _scene(**extra: Any) -> dict[str, Any]:
    """A grey floor and a ball seen from above and in front, no lights, linear output and no
    tone map, so that a pixel is the radiance the shading computed."""
    scene: dict[str, Any] = {
        "camera": {"type": "lookat", "position": [0.0, 3.0, 5.0], "target": [0.0, 0.0, 0.0]},
        "objects": [
            {"shape": "plane", "material": "floor"},
            {"shape": "sphere", "position": [0.0, 0.6, 0.0], "radius": 0.6, "material": "ball"},
        ],
        "materials": {
            "floor": {"albedo": [0.5, 0.5, 0.5], "roughness": 0.6},
            "ball": {"albedo": [0.6, 0.6, 0.6], "roughness": 0.4},
        },
        "lights": [],
        "environment": None,
        "effects": {"ao": False},
        "post": {"tonemap": "none", "output": "none"},
    }
    scene.update(extra)
    return scene


def _pixels(scene: dict[str, Any], tier: str = "balanced", size: tuple[int, int] = SIZE,
            time: float = 0.0) -> np.ndarray:  # fmt: skip
    image = glint.render(glint.compose(scene, tier=tier), size=size, time=time)
    assert image.stats["nan"] == 0 and image.stats["inf"] == 0
    return np.asarray(image.pixels, np.float64)


def test_a_tiny_sphere_light_lights_as_the_point_light_of_its_intensity() -> None:
    """An area light's intensity is the point light's it looks like from afar: a sphere of
    radius 0.01 and a point light (range far beyond the scene) give the same picture."""
    where = [1.0, 2.5, 1.5]
    point = _scene(lights=[{"type": "point", "position": where, "intensity": 8.0,
                            "range": 1e4, "shadow": False}])  # fmt: skip
    sphere = _scene(lights=[{"type": "sphere", "position": where, "radius": 0.01,
                             "intensity": 8.0, "shadow": False}])  # fmt: skip
    for tier in ("balanced", "reference"):
        a, b = _pixels(point, tier), _pixels(sphere, tier)
        lit = a > 0.02
        assert lit.mean() > 0.3
        assert np.median(np.abs(a[lit] - b[lit]) / a[lit]) < 0.02, tier


@pytest.mark.parametrize("shape", ["sphere", "disc", "rect"])
def test_the_representative_tier_is_close_to_the_sampled_reference(shape: str) -> None:
    """Balanced (one representative direction) against reference (the light integrated over
    its surface) on the whole picture: close on average, not the same model."""
    light = {"type": shape, "position": [1.2, 2.2, 1.0], "intensity": 10.0, "shadow": False}
    light |= {"radius": 0.5} if shape != "rect" else {"size": [1.2, 0.8]}
    if shape != "sphere":
        light["direction"] = [-0.5, -1.0, -0.4]
    scene = _scene(lights=[light])
    balanced, reference = _pixels(scene, "balanced"), _pixels(scene, "reference")
    assert reference.mean() > 0.05
    assert abs(balanced.mean() - reference.mean()) < 0.05 * reference.mean()
    assert np.mean(np.abs(balanced - reference)) < 0.06 * reference.mean()


def test_area_variants_against_the_float64_integral() -> None:
    """On 360 lights of every shape, size and tilt: the sampled reference is within a few
    hundredths of the float64 integral everywhere, and several times closer than the
    representative point on average (which stays within its own bound)."""
    sampled, _ = area_errors("area.sampled")(None)
    representative, _ = area_errors("area.representative")(None)
    assert sampled.max() < 0.03
    assert representative.max() < 0.2
    assert sampled.mean() * 3 < representative.mean()


def test_a_spot_light_fills_its_cone_and_nothing_outside() -> None:
    """Straight down onto the floor: the point under the light is lit, a point beyond the
    outer cone is black, and the edge falls off between the two cones."""
    scene = _scene(
        camera={
            "type": "lookat",
            "position": [0.0, 6.0, 0.01],
            "target": [0.0, 0.0, 0.0],
            "fov": 90.0,
        },  # fmt: skip
        objects=[{"shape": "plane", "material": "floor"}],
        lights=[
            {
                "type": "spot",
                "position": [0.0, 2.0, 0.0],
                "direction": [0.0, -1.0, 0.0],
                "inner": 20.0,
                "outer": 30.0,
                "intensity": 10.0,
                "shadow": False,
            }
        ],  # fmt: skip
    )
    pixels = _pixels(scene, size=(121, 121))[..., 0]
    row = pixels[60]  # through the middle; 6 units up at fov 90 sees 12 units across
    x = (np.arange(121) + 0.5 - 60.5) / 60.5 * 6.0
    angle = np.degrees(np.arctan2(np.abs(x), 2.0))
    assert row[angle < 15].min() > 0.2
    assert row[angle > 31].max() == 0.0
    ramp = row[(angle > 21) & (angle < 29)]
    assert ramp.min() > 0.0 and ramp.max() < row[angle < 15].min()


def test_a_larger_area_light_casts_a_wider_penumbra() -> None:
    """The ball's shadow on the floor under a disc light: a larger disc of the same intensity
    leaves more pixels between umbra and full light."""

    def partly_lit(radius: float) -> int:
        disc = {"type": "disc", "position": [0.0, 3.0, 0.0], "radius": radius, "intensity": 6.0}
        shadowed = _pixels(_scene(lights=[disc]))[..., 0]
        unshadowed = _pixels(_scene(lights=[{**disc, "shadow": False}]))[..., 0]
        seen = unshadowed > 0.01
        visible = shadowed[seen] / unshadowed[seen]
        return int(np.sum((visible > 0.1) & (visible < 0.9)))

    assert partly_lit(1.2) > 1.5 * partly_lit(0.1)


def test_emission_and_a_background_shown_as_given() -> None:
    """No light at all: an emissive ball shows its emission, the rest its background colour,
    exactly, with output none and the background kept out of the tone map."""
    scene = _scene(
        objects=[{"shape": "sphere", "radius": 1.0, "material": "lamp"}],
        materials={"lamp": {"albedo": [0.5, 0.5, 0.5], "emission": [3.0, 1.5, 0.25]}},
        camera={"type": "lookat", "position": [0.0, 0.0, 6.0], "target": [0.0, 0.0, 0.0]},
        background={"color": [0.8, 0.9, 1.0], "tonemap": False},
        post={"tonemap": "reinhard", "output": "none"},
    )
    pixels = _pixels(scene)
    centre, corner = pixels[32, 48], pixels[0, 0]
    np.testing.assert_allclose(corner, [0.8, 0.9, 1.0], rtol=1e-6)
    np.testing.assert_allclose(centre, [3 / 4, 1.5 / 2.5, 0.25 / 1.25], rtol=1e-5)  # c/(1+c)
    scene["background"]["tonemap"] = True
    np.testing.assert_allclose(_pixels(scene)[0, 0], [0.8 / 1.8, 0.9 / 1.9, 0.5], rtol=1e-5)


def test_field_of_view_roll_and_start_angle() -> None:
    """fov is focal by another name; a roll of 90° turns the picture a quarter turn clockwise;
    an orbit started at 90° is where one started at 0° is a quarter period later."""
    scene = _scene(lights=[{"type": "directional", "direction": [0.3, 1.0, 0.5]}])
    lens = 1.5
    by_fov = dict(scene, camera={**scene["camera"], "fov": math.degrees(2 * math.atan(1 / lens))})
    by_focal = dict(scene, camera={**scene["camera"], "focal": lens})
    assert glint.compose(by_fov).text == glint.compose(by_focal).text

    square = (64, 64)
    rolled = dict(scene, camera={**scene["camera"], "roll": 90.0})
    upright, turned = _pixels(scene, size=square), _pixels(rolled, size=square)
    assert np.mean(np.abs(np.rot90(upright, k=-1) - turned)) < 0.01 * upright.mean()
    assert np.mean(np.abs(upright - turned)) > 0.1 * upright.mean()

    orbit = {"type": "orbit", "radius": 4.0, "height": 2.0, "speed": 0.5}
    later = _pixels(dict(scene, camera=orbit), time=math.pi)  # 0.5 rad/s for π s: 90°
    started = _pixels(dict(scene, camera={**orbit, "start": 90.0}), time=0.0)
    np.testing.assert_allclose(started, later, atol=1e-4)


def test_anti_aliasing_averages_the_rays_of_a_finer_grid() -> None:
    """aa = 2 at W×H is, pixel for pixel, the 2×2 mean of one ray per pixel at 2W×2H (the same
    rays), with output none so that the mean is of the same values; and its edges are soft."""
    lit = _scene(lights=[{"type": "directional", "direction": [0.3, 1.0, 0.5]}])
    fine = _pixels(lit, size=(2 * SIZE[0], 2 * SIZE[1]))
    mean = fine.reshape(SIZE[1], 2, SIZE[0], 2, 3).mean(axis=(1, 3))
    smooth = _pixels(dict(lit, quality={"aa": 2}))
    np.testing.assert_allclose(smooth, mean, atol=1e-4)
    assert np.mean(np.abs(smooth - _pixels(lit))) > 1e-3


def test_quality_params_set_snippet_parameters() -> None:
    scene = _scene(lights=[{"type": "directional", "direction": [0.3, 1.0, 0.5]}],
                   quality={"params": {"SHADOW_K": 16}})  # fmt: skip
    soft, sharp = _pixels(dict(scene, quality={})), _pixels(scene)
    assert "#define SHADOW_K 16.0" in glint.compose(scene).text
    assert np.sum(np.abs(soft - sharp) > 1e-3) > 0  # a harder penumbra
    for params, says in (
        ({"NO_SUCH": 1}, "not a parameter of the snippets this scene uses"),
        ({"SHADOW_K": 1000.0}, "outside its range"),
        ({"AREA_SHADOW_RAYS": 2.5}, "an int parameter"),
        ({"SHADOW_K": [1.0, 2.0, 3.0]}, "give one number"),
    ):
        with pytest.raises(InputError, match=says):
            glint.compose(dict(scene, quality={"params": params}))


@pytest.mark.parametrize(
    ("light", "says"),
    [
        ({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "inner": 40,
          "outer": 30}, "inner 40 is wider than outer 30"),
        ({"type": "spot", "position": [0, 1, 0]}, "give direction"),
        ({"type": "spot", "position": [0, 1, 0], "target": [0, 1, 0]}, "must not be its position"),
        ({"type": "rect", "position": [0, 1, 0], "direction": [0, -1, 0], "up": [0, 2, 0]},
         "up is along direction"),
        ({"type": "disc", "position": [0, 1, 0], "radius": 0}, "greater than 0"),
    ],
)  # fmt: skip
def test_a_light_that_cannot_be_drawn_is_refused(light: dict[str, Any], says: str) -> None:
    with pytest.raises(InputError, match=says):
        scene_from_dict(_scene(lights=[light]))


def test_fov_and_focal_must_agree() -> None:
    camera = {"type": "lookat", "position": [0, 1, 4], "fov": 60.0, "focal": 1.5}
    with pytest.raises(InputError, match="focal 1.5 and fov 60 disagree"):
        scene_from_dict(_scene(camera=camera))


def test_a_smooth_surface_reflects_the_scene_at_balanced_not_at_fast() -> None:
    """A mirror floor under a glowing ball, no lights: with effects.reflections the floor
    below the ball shows the ball's emission (balanced), without it only the environment;
    the fast tier keeps the environment, as documented."""
    scene = _scene(
        objects=[
            {"shape": "plane", "material": "mirror"},
            {"shape": "sphere", "position": [0.0, 1.2, 0.0], "radius": 0.5, "material": "lamp"},
        ],
        materials={
            "mirror": {"albedo": [0.9, 0.9, 0.9], "roughness": 0.0, "metallic": 1.0},
            "lamp": {"albedo": [0.0, 0.0, 0.0], "emission": [0.0, 4.0, 0.0]},
        },
        camera={"type": "lookat", "position": [0.0, 1.0, 5.0], "target": [0.0, 0.3, 0.0]},
        environment={"top": [0.1, 0.1, 0.1], "bottom": [0.1, 0.1, 0.1]},
    )
    reflecting = dict(scene, effects={"ao": False, "reflections": True})
    plain, mirrored = _pixels(scene), _pixels(reflecting)
    fast, fast_plain = _pixels(reflecting, "fast"), _pixels(scene, "fast")
    # the ball's image in the floor: green there only with reflections
    image = (mirrored[..., 1] > 1.0) & (plain[..., 1] < 0.2)
    assert image.sum() > 20
    rows = np.nonzero(image)[0]
    ball_rows = np.nonzero(plain[..., 1] > 1.0)[0]
    assert rows.min() > ball_rows.max()  # below the ball, in the floor
    np.testing.assert_allclose(fast, fast_plain, atol=1e-6)
