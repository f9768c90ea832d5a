"""Composition: a scene in, one deterministic, self-contained shader out, for every target."""

from __future__ import annotations

import re

import pytest

from glint.compiler.compose import compose, compose_scene, glint_version
from glint.compiler.errors import InputError
from glint.compiler.glslang import validate
from glint.compiler.scene import parse_scene

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
    soft = compose().text
    hard = compose(overrides={"shadow": "hard"}).text
    assert "snippets/shadow/soft.glsl" in soft and "snippets/shadow/hard.glsl" not in soft
    assert "snippets/shadow/hard.glsl" in hard and "snippets/shadow/soft.glsl" not in hard
    assert validate(hard, "hard.glsl") == []


def test_unknown_variant_and_slot_are_named() -> None:
    with pytest.raises(InputError, match="--variant.shadow: unknown variant 'blurry'; variants"):
        compose(overrides={"shadow": "blurry"})
    with pytest.raises(InputError, match="--variant.glow: unknown slot"):
        compose(overrides={"glow": "x"})


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
    text = BARE.replace("[effects]", """
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
[effects]""")
    shader = compose_scene(parse_scene(text))
    for name in ("SUN_DIR", "LIGHT_DIR", "BACK_DIR", "SKY_COLOR", "SKY1_COLOR"):
        assert f"#define {name} " in shader.text
    assert "directionalLight(s, LIGHT_DIR, LIGHT_COLOR, 1.0)" in shader.text
    assert validate(shader.text, "lights.glsl") == []


def test_back_light_without_a_sun_needs_a_direction() -> None:
    text = BARE.replace("[effects]", "[[lights]]\ntype = \"back\"\n[effects]")
    with pytest.raises(InputError, match=r"lights\[0\]\.direction: a back light needs"):
        compose_scene(parse_scene(text))
