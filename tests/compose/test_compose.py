"""Composition: a scene in, one deterministic, self-contained shader out, for every target."""

from __future__ import annotations

import re

import numpy as np
import pytest

from glint import compose
from glint.compiler.compose.pipeline import compose_scene, glint_version
from glint.compiler.errors import InputError
from glint.compiler.scene.model import parse_scene
from glint.compiler.target.glslang import validate

SCENES = "tests/scenes"


def test_shadertoy_target_pastes_into_the_image_tab() -> None:
    text = compose().text
    assert "#version" not in text
    assert not re.search(r"^\s*uniform\b", text, re.MULTILINE)
    assert re.search(r"^void mainImage\(out vec4 fragColor, in vec2 fragCoord\)", text, re.M)
    assert f"// glint {glint_version()}" in text.splitlines()[0]


def test_header_lists_every_snippet_used_exactly_once() -> None:
    shader = compose()
    header = [line for line in shader.text.splitlines() if line.startswith("//   ")]
    listed = [line.split()[1] for line in header]
    used = [u.id for u in shader.units if u.slot != "scene"]
    assert listed == used
    for unit_id in used:
        origin = f"// source: snippets/{unit_id.replace('.', '/')}.glsl:"
        assert shader.text.count(origin) == 1


def test_same_scene_same_bytes() -> None:
    assert compose().text == compose().text
    assert compose(target="desktop").text == compose(target="desktop").text


@pytest.mark.parametrize("target", ["shadertoy", "webgl2", "desktop"])
def test_every_target_validates(target: str) -> None:
    text = compose(target=target).text
    assert validate(text, "default.glsl", target) == []


def test_webgl2_and_desktop_are_complete_shaders() -> None:
    assert compose(target="webgl2").text.startswith("#version 300 es\n")
    assert compose(target="desktop").text.startswith("#version 330\n")


def test_variant_override_swaps_the_snippet() -> None:
    soft = compose(variants={"shadow": "soft"}).text
    hard = compose(variants={"shadow": "hard"}).text
    assert "snippets/shadow/soft.glsl" in soft and "snippets/shadow/hard.glsl" not in soft
    assert "snippets/shadow/hard.glsl" in hard and "snippets/shadow/soft.glsl" not in hard
    assert validate(hard, "hard.glsl") == []


def test_unknown_variant_and_slot_are_named() -> None:
    with pytest.raises(InputError, match="--variant.shadow: unknown variant 'blurry'; variants"):
        compose(variants={"shadow": "blurry"})
    with pytest.raises(InputError, match="--variant.glow: unknown slot"):
        compose(variants={"glow": "x"})


BARE = """
name = "bare"
[[objects]]
shape = "box"
size = [0.5, 0.5, 0.5]
material = "grey"
[materials.grey]
albedo = [0.5, 0.5, 0.5]
[camera]
type = "lookat"
position = [2.0, 2.0, 3.0]
[effects]
ao = false
[environment]
reflection = false
"""


def test_scene_code_emits_only_what_the_scene_uses() -> None:
    shader = compose_scene(parse_scene(BARE))
    ids = {u.id for u in shader.units}
    # No lights: no BRDF, no shadow; AO off and no reflection: no occlusion code.
    for absent in ("D.ggx", "F.schlick", "shadow.soft", "ao.sdf5", "ibl.simple_reflection"):
        assert absent not in ids
    assert {"sdf.box", "camera.lookat", "background.gradient"} <= ids
    assert "sdf.sphere" not in ids and "materialAt" not in shader.text
    assert "SUN_DIR" not in shader.text
    assert validate(shader.text, "bare.glsl") == []


def test_several_lights_get_distinct_names() -> None:
    text = BARE.replace(
        "[effects]",
        """
[[lights]]
type = "directional"
direction = [1.0, 1.0, 0.0]
[[lights]]
type = "directional"
direction = [-1.0, 1.0, 0.0]
shadow = false
[[lights]]
type = "back"
[[lights]]
type = "sky"
[[lights]]
type = "sky"
intensity = 0.5
[effects]""",
    )
    shader = compose_scene(parse_scene(text))
    for name in ("SUN_DIR", "LIGHT_DIR", "BACK_DIR", "SKY_COLOR", "SKY1_COLOR"):
        assert f"#define {name} " in shader.text
    assert "directionalLight(s, LIGHT_DIR, LIGHT_COLOR, vec3(1.0))" in shader.text
    assert validate(shader.text, "lights.glsl") == []


def test_back_light_without_a_sun_needs_a_direction() -> None:
    text = BARE.replace("[effects]", '[[lights]]\ntype = "back"\n[effects]')
    with pytest.raises(InputError, match=r"lights\[0\]\.direction: a back light needs"):
        compose_scene(parse_scene(text))


LIGHTS = """
[[lights]]
type = "directional"
direction = [0.6, 0.8, -0.5]
penumbra = [1.0, 1.2, 1.5]
[[lights]]
type = "point"
position = [1.5, 1.0, 1.0]
range = 6.0
[[lights]]
type = "bounce"
[[lights]]
type = "environment"
[effects]"""


def lit_scene() -> str:
    text = BARE.replace("[effects]", LIGHTS, 1)
    colors = "[environment]\ntop = [0.3, 0.5, 0.9]\nbottom = [0.7, 0.6, 0.5]"
    return text.replace("[environment]", colors)


def test_point_bounce_environment_lights_and_a_tinted_penumbra() -> None:
    shader = compose_scene(parse_scene(lit_scene()))
    text = shader.text
    assert "pow(vec3(shadow(s.P + s.N * hitLift, SUN_DIR, 0.02, 5.0)), SUN_PENUMBRA)" in text
    assert "#define SUN_PENUMBRA vec3(1.0, 1.2, 1.5)" in text
    assert "#define POINT_RANGE 6.0" in text
    assert "distance(POINT_POS, s.P)" in text  # the point light's shadow stops at the light
    assert "bounceLight(s, BOUNCE_DIR, BOUNCE_COLOR, 1.0)" in text  # AO is off
    ids = {u.id for u in shader.units}
    assert {"attenuation.inverse_square_range", "irradiance.sh9", "light.point"} <= ids
    assert validate(text, "lights.glsl") == []


def test_sh9_constants_come_from_the_scenes_environment() -> None:
    shader = compose_scene(parse_scene(lit_scene()))
    match = re.search(r"#define SH_C0 vec3\(([^)]*)\)", shader.text)
    assert match
    # L00 = ∫ L Y00 dω = 2√π · mean radiance, and a linear gradient in y averages to the
    # mean of its ends over the sphere.
    mean = (np.array([0.3, 0.5, 0.9]) + np.array([0.7, 0.6, 0.5])) / 2
    got = np.array([float(v) for v in match.group(1).split(",")])
    np.testing.assert_allclose(got, 2 * np.sqrt(np.pi) * mean, rtol=1e-5)


def test_fast_tier_uses_the_hemisphere_and_no_sh_constants() -> None:
    shader = compose_scene(parse_scene(lit_scene()), tier="fast")
    assert "irradiance.hemisphere" in {u.id for u in shader.units}
    assert "SH_C0" not in shader.text


def test_derivative_normals_are_taken_in_uniform_control_flow() -> None:
    flat = compose(variants={"normal": "derivative_flat"}).text
    main = flat[flat.index("void mainImage") :]
    assert main.index("calcNormal(P)") < main.index("if (t > 0.0)")
    assert validate(flat, "flat.glsl") == []
    default = compose().text
    main = default[default.index("void mainImage") :]
    assert main.index("if (t > 0.0)") < main.index("calcNormal(P)")  # no cost on misses
