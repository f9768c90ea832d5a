"""Every example scene in snippets/scenes composes, validates for every target and renders
without NaN or Inf."""

from __future__ import annotations

from pathlib import Path

import pytest

from glint.compiler.compose import compose
from glint.compiler.glslang import validate
from glint.compiler.render import image_stats, render
from glint.compiler.scene import default_scene_path

SCENES = sorted(default_scene_path().parent.glob("*.toml"))


def test_there_are_examples_beyond_the_default() -> None:
    assert len(SCENES) >= 2


@pytest.mark.parametrize("scene", SCENES, ids=lambda p: p.stem)
@pytest.mark.parametrize("target", ["shadertoy", "webgl2", "desktop"])
def test_example_validates(scene: Path, target: str) -> None:
    shader = compose(scene, target)
    assert [str(d) for d in validate(shader.text, scene.name, target)] == []


@pytest.mark.render
@pytest.mark.parametrize("scene", SCENES, ids=lambda p: p.stem)
@pytest.mark.parametrize("tier", ["fast", "balanced", "reference"])
def test_example_renders_finite(scene: Path, tier: str) -> None:
    image = render(compose(scene, tier=tier).text, 160, 90, time=2.0)
    stats = image_stats(image)
    assert stats["nan"] == 0 and stats["inf"] == 0
    assert max(stats["std"]) > 0.02  # something is in the picture
