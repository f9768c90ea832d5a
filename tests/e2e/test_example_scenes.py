"""Every example scene in snippets/scenes composes, validates for every target and renders
without NaN or Inf: the raymarched ones for the ShaderToy targets, the mesh ones (their vertex
and fragment programs) for the mesh targets."""

from __future__ import annotations

from pathlib import Path

import pytest
from mesh_scenes import MESH_EXAMPLES, example_params

import glint
from glint import compose
from glint.compiler.render import image_stats, render
from glint.compiler.scene.model import default_scene_path
from glint.compiler.target.glslang import validate

SCENES = sorted(default_scene_path().parent.glob("*.toml"))
NOT_SHADERTOY = "no ShaderToy shader; test_mesh_example_* compose it for the mesh targets"


def test_there_are_examples_beyond_the_default() -> None:
    assert len(SCENES) >= 2


@pytest.mark.parametrize("scene", example_params(NOT_SHADERTOY))
@pytest.mark.parametrize("target", ["shadertoy", "webgl2", "desktop"])
def test_example_validates(scene: Path, target: str) -> None:
    shader = compose(scene, target=target)
    assert [str(d) for d in validate(shader.text, scene.name, target)] == []


@pytest.mark.render
@pytest.mark.parametrize("scene", example_params(NOT_SHADERTOY))
@pytest.mark.parametrize("tier", ["fast", "balanced", "reference"])
def test_example_renders_finite(scene: Path, tier: str) -> None:
    image = render(compose(scene, tier=tier).text, 160, 90, time=2.0)
    stats = image_stats(image)
    assert stats["nan"] == 0 and stats["inf"] == 0
    assert max(stats["std"]) > 0.02  # something is in the picture


def test_there_is_a_mesh_example() -> None:
    assert [path.stem for path in MESH_EXAMPLES] == ["eight_models"]


@pytest.mark.parametrize("scene", MESH_EXAMPLES, ids=lambda p: p.stem)
@pytest.mark.parametrize("target", ["mesh-webgl2", "mesh-desktop"])
def test_mesh_example_validates(scene: Path, target: str) -> None:
    shader = glint.compose_mesh(scene, target=target)
    assert [str(d) for d in shader.validate()] == []


@pytest.mark.render
@pytest.mark.parametrize("scene", MESH_EXAMPLES, ids=lambda p: p.stem)
@pytest.mark.parametrize("tier", ["fast", "balanced", "reference"])
def test_mesh_example_renders_finite(scene: Path, tier: str) -> None:
    image = glint.render(glint.compose_mesh(scene, tier=tier), size=(160, 90), time=2.0)
    assert image.finite
    assert max(image.stats["std"]) > 0.02  # something is in the picture


# The scene that exercises each slot; the camera, background and post slots follow the scene.
SCENE_OF_SLOT = {
    slot: None
    for slot in (
        "D",
        "F",
        "V",
        "diffuse",
        "specular",
        "ao",
        "specocc",
        "shadow",
        "env",
        "ibl",
        "normal",
        "raymarch",
        "tonemap",
        "output",
    )
} | {"attenuation": "lamp", "irradiance": "lamp", "sss": "pool", "phase": "pool", "media": "pool"}


def _swappable() -> list[str]:
    from glint.compiler.catalog.loader import load_catalog
    from glint.compiler.catalog.slots import SLOTS

    return sorted(
        s.id
        for s in load_catalog().snippets.values()
        if not SLOTS[s.slot].many and s.slot in SCENE_OF_SLOT
    )


@pytest.mark.render
@pytest.mark.parametrize("snippet_id", _swappable())
def test_every_variant_composes_into_a_scene_of_its_slot(snippet_id: str) -> None:
    slot, variant = snippet_id.split(".", 1)
    name = SCENE_OF_SLOT[slot]
    scene = None if name is None else default_scene_path().parent / f"{name}.toml"
    shader = compose(scene, variants={slot: variant})
    assert snippet_id in {u.id for u in shader.units}
    assert [str(d) for d in validate(shader.text, f"{snippet_id}.glsl")] == []
    stats = image_stats(render(shader.text, 96, 54, time=1.0))
    assert stats["nan"] == 0 and stats["inf"] == 0
