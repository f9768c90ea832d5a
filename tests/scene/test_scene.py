"""The scene model: the default scene loads, and bad scenes get one message naming the key."""

from __future__ import annotations

import pytest

from glint.compiler.errors import InputError
from glint.compiler.scene.model import load_scene, parse_scene

BASE = """
[[objects]]
shape = "sphere"
material = "m"

[materials.m]
albedo = [0.5, 0.5, 0.5]
"""


def test_default_scene_is_the_template_scene() -> None:
    scene = load_scene()
    assert [o.shape for o in scene.objects] == ["sphere", "plane"]
    assert [light.type for light in scene.lights] == ["directional", "sky", "back"]
    assert scene.materials["red"].albedo == [0.8, 0.2, 0.2]
    assert scene.post.tonemap == "reinhard" and scene.post.output == "gamma22"


def test_minimal_scene_gets_defaults() -> None:
    scene = parse_scene(BASE)
    assert scene.camera.type == "orbit"
    assert scene.quality.tier == "balanced"
    assert scene.lights == []


@pytest.mark.parametrize(
    ("extra", "expected"),
    [
        ("colour = 1", "colour: unknown key; allowed keys here: name, description"),
        ("[camera]\ntype = 'orbit'\nradius = -2.0", "camera.radius: input should be greater"),
        ("[camera]\ntype = 'dolly'", "camera.type: unknown value 'dolly'; expected one of"),
        ("[post]\ntonemap = 'filmic'", "post.tonemap: unknown value 'filmic'"),
        ("[effects]\nao = 'yes'", "effects.ao: input should be a valid boolean (got 'yes')"),
        ("[[lights]]\ntype = 'directional'\ndirection = [0, 0, 0]", "lights[0]: direction must"),
        ("[[lights]]\ntype = 'directional'\ndirection = [1, 2]", "lights[0].direction: list"),
        ("[[lights]]\ntype = 'sky'\ncolor = [1, 'x', 1]", "lights[0].color[1]: input should be"),
        ("[[lights]]\ncolor = [1, 1, 1]", "lights[0]: needs a 'type' key"),
        ("[materials.n]\nalbedo = [1, 1, 1]\nroughness = 1.5", "materials.n.roughness: input"),
        ("[materials.n]\nalbedo = [1, 1, 1]\npattern = 'checker'", "needs pattern_albedo"),
        ("[quality]\ntier = 'ultra'", "quality.tier: unknown value 'ultra'"),
    ],
)
def test_bad_scene_names_key_value_and_expectation(extra: str, expected: str) -> None:
    # Top-level keys must come before the tables of BASE.
    text = extra + "\n" + BASE if "=" in extra.split("\n")[0] and "[" not in extra else BASE + extra
    with pytest.raises(InputError) as info:
        parse_scene(text, "bad.toml")
    assert info.value.message.startswith("bad.toml: ")
    assert expected in info.value.message


def test_unknown_material_reference() -> None:
    text = BASE.replace('material = "m"', 'material = "gold"')
    with pytest.raises(InputError, match=r"objects\[0\]\.material: 'gold' is not a material"):
        parse_scene(text, "s.toml")


def test_not_toml() -> None:
    with pytest.raises(InputError, match="s.toml: not valid TOML"):
        parse_scene("a = = 1", "s.toml")


def test_missing_file(tmp_path) -> None:
    with pytest.raises(InputError, match="no such scene file"):
        load_scene(tmp_path / "nope.toml")
