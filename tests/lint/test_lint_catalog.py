"""The catalog lints clean: every snippet file with every rule that applies to a library file
(glslang needs a complete shader, so it runs on the composed example scenes instead), and the
shader composed from every example scene at every tier with every rule, glslang included."""

from __future__ import annotations

from pathlib import Path

import pytest
from mesh_scenes import example_params

from glint import compose
from glint.compiler.scene.model import default_scene_path
from glint.lint.options import Options
from glint.lint.runner import lint_source

SNIPPETS = sorted(default_scene_path().parent.parent.rglob("*.glsl"))
# A mesh scene has no ShaderToy shader to lint; its stages are validated per stage by glslang
# (test_example_scenes).
SCENES = example_params("no ShaderToy shader to lint")


def shown(findings: list) -> list[str]:
    return [f"{f.file}:{f.line}:{f.column}: {f.code} {f.message}" for f in findings]


def test_every_catalog_file_is_linted() -> None:
    assert len(SNIPPETS) >= 60


@pytest.mark.parametrize("path", SNIPPETS, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_snippet_lints_clean(path: Path) -> None:
    found = lint_source(path.read_text(encoding="utf-8"), str(path), Options(glslang=False))
    assert shown(found) == []


@pytest.mark.parametrize("scene", SCENES)
@pytest.mark.parametrize("tier", ["fast", "balanced", "reference"])
def test_composed_scene_lints_clean(scene: Path, tier: str) -> None:
    shader = compose(scene, tier=tier)
    assert shown(lint_source(shader.text, f"{scene.stem}.glsl", Options())) == []
