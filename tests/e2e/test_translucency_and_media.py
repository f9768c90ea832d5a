"""Scene integration of the sss, phase and media slots and of the diffuse roughness: the scene
keys, what the composer emits for them (and only when the scene asks), and rendered values at
the centre pixel checked against the formulas the generated glue is meant to compute."""

from __future__ import annotations

import math

import numpy as np
import pytest

from glint.compiler.compose.pipeline import compose_scene
from glint.compiler.errors import InputError
from glint.compiler.render import render
from glint.compiler.scene.model import parse_scene

# A sphere seen head-on against the light: the camera on +z looks at the origin, the key light
# shines from straight behind the sphere (toward the light is −z). Linear output (no tone
# map), so that gamma 2.2 can be undone exactly.
BACKLIT = """
camera = {{ type = "lookat", position = [0.0, 0.0, 3.0], target = [0.0, 0.0, 0.0] }}
objects = [{{ shape = "sphere", radius = {radius}, material = "body" }}]
lights = [{{ type = "directional", direction = [0.0, 0.0, -1.0], color = [0.5, 0.4, 0.3] }}]
environment = {{ reflection = false }}
background = {{ sun = false }}
post = {{ tonemap = "none", output = "gamma22" }}
[materials.body]
albedo = [0.2, 0.2, 0.2]
{extra}
"""

# The camera looks down at 45° at the origin on the floor y = 0, so the centre ray travels
# 2√2 to the floor, of which 2√2·(level − 0)/2 below a water level between 0 and 2.
FLOOR = """
camera = {{ type = "lookat", position = [0.0, 2.0, 2.0], target = [0.0, 0.0, 0.0] }}
objects = [{{ shape = "plane", material = "floor" }}]
lights = [{{ type = "sky", color = [0.3, 0.3, 0.3] }}]
environment = {{ reflection = false }}
effects = {{ ao = false }}
background = {{ sun = false }}
post = {{ tonemap = "none", output = "gamma22" }}
[materials.floor]
albedo = [0.6, 0.5, 0.4]
{extra}
"""
SIZE = 33  # odd, so that the centre pixel's ray is the camera's axis


def centre_linear(text: str, **overrides: str) -> np.ndarray:
    """Linear RGB of the centre pixel of the scene rendered with `overrides` variants."""
    shader = compose_scene(parse_scene(text), variants=overrides or None)
    image = render(shader.text, SIZE, SIZE, time=0.0)
    return image[SIZE // 2, SIZE // 2, :3].astype(np.float64) ** 2.2


def units_of(text: str) -> set[str]:
    return {u.id for u in compose_scene(parse_scene(text)).units}


# --- scene keys --------------------------------------------------------------------------------


def test_subsurface_g_out_of_range_names_the_key() -> None:
    with pytest.raises(InputError, match=r"materials\.body\.subsurface_g"):
        parse_scene(
            BACKLIT.format(radius=0.2, extra="subsurface = [1.0, 1.0, 1.0]\nsubsurface_g = 1.5")
        )


def test_unknown_medium_key_lists_the_allowed_ones() -> None:
    text = FLOOR.format(extra="[medium]\ndepth = 1.0")
    with pytest.raises(
        InputError,
        match=r"medium\.depth: unknown key; allowed keys here: "
        r"extinction, inscatter, level",
    ):
        parse_scene(text)


def test_errors_inside_every_light_type_name_the_light() -> None:
    for light in ("point", "bounce", "environment"):
        text = FLOOR.format(extra="").replace(
            'lights = [{ type = "sky", color = [0.3, 0.3, 0.3] }]',
            f'lights = [{{ type = "{light}", position = [0.0, 1.0, 0.0], bogus = 1 }}]'
            if light == "point"
            else f'lights = [{{ type = "{light}", bogus = 1 }}]',
        )
        with pytest.raises(InputError, match=r"lights\[0\]\.bogus: unknown key; allowed keys"):
            parse_scene(text)


# --- only what the scene asks for --------------------------------------------------------------


def test_opaque_scene_emits_no_subsurface_or_medium() -> None:
    ids = units_of(BACKLIT.format(radius=0.2, extra=""))
    assert not {"sss.sdf_probe", "phase.henyey_greenstein", "media.beer"} & ids
    assert not {"scene.subsurface", "scene.submerged"} & ids


def test_translucent_material_brings_sss_and_phase() -> None:
    ids = units_of(BACKLIT.format(radius=0.2, extra="subsurface = [1.0, 1.0, 1.0]"))
    assert {"sss.sdf_probe", "phase.henyey_greenstein", "scene.subsurface"} <= ids


def test_fog_has_no_water_level_function() -> None:
    ids = units_of(FLOOR.format(extra="[medium]"))
    assert "media.beer" in ids and "scene.submerged" not in ids


def test_diffuse_roughness_is_set_only_where_a_material_has_it() -> None:
    plain = compose_scene(parse_scene(FLOOR.format(extra=""))).text
    rough = compose_scene(parse_scene(FLOOR.format(extra="diffuse_roughness = 0.7"))).text
    assert "s.diffuseRoughness = " not in plain.split("Surface surfaceAt")[1]
    assert "s.diffuseRoughness = 0.7;" in rough


# --- rendered values -----------------------------------------------------------------------------


def hg(cos_theta: float, g: float) -> float:
    return (1 - g * g) / (4 * math.pi * (1 + g * g - 2 * g * cos_theta) ** 1.5)


@pytest.mark.render
@pytest.mark.parametrize("phase", ["henyey_greenstein", "schlick", "isotropic"])
def test_backlit_body_glows_by_transmittance_times_forward_phase(phase: str) -> None:
    # At the centre the eye sees the front of the sphere and the light is straight behind it:
    # L = −V, so the light leaves the body straight toward the eye (cos θ = 1), after crossing
    # a chord of 2r = 0.4. sss.sdf_probe's five midpoint taps (0.05 … 0.45) count 4 inside:
    # T = exp(−6 · 0.1 · 4). N·L < 0 there, so nothing else lights that point.
    color = [0.8, 0.6, 0.4]
    g = 0.5
    extra = f"subsurface = {color}\nsubsurface_g = {g}"
    lit = centre_linear(BACKLIT.format(radius=0.2, extra=extra), phase=phase)
    dark = centre_linear(BACKLIT.format(radius=0.2, extra=""), phase=phase)
    forward = {"henyey_greenstein": hg(1.0, g), "isotropic": 1 / (4 * math.pi)}
    # Schlick's k = 1.55g − 0.55g³ stands in for g: (1 − k²)/(4π(1 − k)²) straight ahead.
    k = 1.55 * g - 0.55 * g**3
    forward["schlick"] = (1 - k * k) / (4 * math.pi * (1 - k) ** 2)
    expected = np.array(color) * np.array([0.5, 0.4, 0.3]) * math.exp(-2.4) * forward[phase]
    np.testing.assert_allclose(lit - dark, expected, rtol=2e-3)


@pytest.mark.render
def test_front_lit_translucent_body_gains_only_the_back_scatter() -> None:
    # Light from the eye's side: L = V, the path toward the light leaves the body at once (T = 1)
    # and the light turns straight back (cos θ = −1).
    g = 0.5
    text = BACKLIT.format(radius=0.2, extra=f"subsurface = [1.0, 1.0, 1.0]\nsubsurface_g = {g}")
    text = text.replace("direction = [0.0, 0.0, -1.0]", "direction = [0.0, 0.0, 1.0]")
    lit = centre_linear(text)
    dark = centre_linear(text.replace("subsurface = [1.0, 1.0, 1.0]", ""))
    np.testing.assert_allclose(lit - dark, np.array([0.5, 0.4, 0.3]) * hg(-1.0, g), rtol=2e-3)


EXTINCTION = np.array([0.3, 0.6, 1.2])
INSCATTER = np.array([0.02, 0.05, 0.08])


def medium_table(level: float | None) -> str:
    lines = ["[medium]", f"extinction = {EXTINCTION.tolist()}", f"inscatter = {INSCATTER.tolist()}"]
    return "\n".join(lines + ([f"level = {level}"] if level is not None else []))


@pytest.mark.render
@pytest.mark.parametrize(
    ("level", "path"),
    [
        (None, 2 * math.sqrt(2)),
        (1.0, math.sqrt(2)),
        (0.5, math.sqrt(2) / 2),
        (3.0, 2 * math.sqrt(2)),
        (-1.0, 0.0),
    ],
    ids=["fog", "water-half", "water-quarter", "camera-under-water", "water-below-floor"],
)
def test_medium_weighs_the_surface_by_beer_lambert_over_the_submerged_path(
    level: float | None, path: float
) -> None:
    clear = centre_linear(FLOOR.format(extra=""))
    seen = centre_linear(FLOOR.format(extra=medium_table(level)))
    transmittance = np.exp(-EXTINCTION * path)
    # The march stops within its surface epsilon of the floor: a relative 1e-3 on the path.
    np.testing.assert_allclose(seen, INSCATTER + (clear - INSCATTER) * transmittance, rtol=3e-3)


@pytest.mark.render
def test_background_is_outside_the_medium() -> None:
    # Looking up at the sky: the ray misses and the fog does not touch the background.
    sky = FLOOR.replace("target = [0.0, 0.0, 0.0]", "target = [0.0, 3.0, 0.0]")
    np.testing.assert_array_equal(
        centre_linear(sky.format(extra="")), centre_linear(sky.format(extra=medium_table(None)))
    )


@pytest.mark.render
@pytest.mark.parametrize("variant", ["oren_nayar", "oren_nayar_qualitative", "oren_nayar_improved"])
def test_oren_nayar_reads_the_diffuse_roughness_not_the_specular(variant: str) -> None:
    # σ = 0 makes every Oren-Nayar form Lambert, whatever the specular roughness.
    def scene(sigma: str) -> str:
        text = BACKLIT.format(radius=0.5, extra=f"roughness = 0.9\n{sigma}")
        return text.replace("direction = [0.0, 0.0, -1.0]", "direction = [0.6, 0.5, 1.0]")

    lambert = centre_linear(scene(""), diffuse="lambert")
    smooth = centre_linear(scene("diffuse_roughness = 0.0"), diffuse=variant)
    rough = centre_linear(scene("diffuse_roughness = 1.0"), diffuse=variant)
    np.testing.assert_allclose(smooth, lambert, rtol=1e-5)
    assert np.abs(rough - lambert).max() > 1e-3
