"""The README tells the truth: its commands, its shader excerpt and its picture are current."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from glint import compose
from glint.compiler.render import render
from glint.compiler.render.images import flip_error, load_png
from glint.compiler.scene.model import default_scene_path

ROOT = Path(__file__).parent.parent
README = (ROOT / "README.md").read_text()
EXAMPLE = ROOT / "site" / "docs" / "examples" / "default.glsl"


def test_the_two_commands_come_first() -> None:
    first_block = re.search(r"```sh\n(.*?)```", README, re.S)
    assert first_block is not None
    assert README.index("```sh") < 20
    commands = [line.split("#")[0].strip() for line in first_block.group(1).splitlines()]
    assert commands == ["make demo", "make test"]
    assert "make test" in (ROOT / ".ci" / "run").read_text()


def test_shader_excerpt_is_what_compose_emits() -> None:
    excerpt = re.search(r"```glsl\n(.*?)```", README, re.S)
    assert excerpt is not None
    assert excerpt.group(1) in compose().text


def test_example_shader_is_current() -> None:
    hint = f"regenerate with: glint compose -o {EXAMPLE}"
    assert EXAMPLE.read_text() == compose().text, hint


@pytest.mark.render
def test_example_picture_is_the_default_scene() -> None:
    picture = load_png(str(EXAMPLE.with_suffix(".png")))
    fresh = render(compose().text, 640, 360, time=1.0)
    assert flip_error(picture, fresh) <= 0.001


# The pictures of the scene section: each is its example scene as glint renders it now.
SCENE_PICTURES = ["machined_part", "sculpture_garden", "island"]


@pytest.mark.render
@pytest.mark.parametrize("name", SCENE_PICTURES)
def test_scene_pictures_are_their_scenes(name: str) -> None:
    picture_path = EXAMPLE.parent / f"{name}.png"
    assert f"site/docs/examples/{name}.png" in README
    scene = default_scene_path().parent / f"{name}.toml"
    fresh = render(compose(scene).text, 640, 360, time=1.0)
    hint = f"regenerate with: glint render {scene} -o {picture_path} --time 1.0"
    assert flip_error(load_png(str(picture_path)), fresh) <= 0.001, hint


@pytest.mark.render
def test_mesh_scene_picture_is_its_scene() -> None:
    """The Mesh scenes section's picture: the eight-model example as glint draws it now."""
    import glint

    picture_path = EXAMPLE.parent / "eight_models.png"
    assert "site/docs/examples/eight_models.png" in README
    scene = default_scene_path().parent / "eight_models.toml"
    fresh = glint.render(glint.compose_mesh(scene), size=(640, 360), time=1.0).pixels
    hint = f"regenerate with: glint render {scene} -o {picture_path} --size 640x360 --time 1.0"
    assert flip_error(load_png(str(picture_path)), fresh) <= 0.001, hint
