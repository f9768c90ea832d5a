"""Mesh rendering with moderngl on llvmpipe, verified by agreement and convergence: a finely
tessellated sphere under phong draws what the raymarched sphere of the same scene draws;
gouraud approaches phong as the tessellation grows; flat shading is exact on flat faces."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from mesh_scenes import mesh_scene, raymarched_scene

import glint
from glint.compiler.render.images import flip_error

SIZE = (240, 135)


def _render(scene: dict, target: str = "mesh-desktop") -> np.ndarray:
    image = glint.render(glint.compose_mesh(scene, target=target), size=SIZE)
    assert image.finite
    return image.pixels


@pytest.mark.parametrize("target", ["mesh-desktop", "mesh-webgl2"])
def test_sphere_is_drawn_where_the_camera_looks(target: str) -> None:
    pixels = _render(mesh_scene(subdivisions=4), target)
    height, width = pixels.shape[:2]
    centre = pixels[height // 2, width // 2]
    corner = pixels[2, 2]
    assert centre[0] > centre[2] + 0.1, centre  # the red sphere, not the blue-grey sky
    assert corner[2] > corner[0], corner  # the sky
    assert pixels.mean() > 0.2  # not black
    # the sphere's silhouette: about a circle of radius focal / sqrt(d^2 - 1) (in uv) around
    # the centre, d the camera's distance: red inside, sky outside
    distance = float(np.hypot(0.8, 2.6))
    radius = 1.5 / np.sqrt(distance**2 - 1.0) * height / 2.0
    assert pixels[height // 2, int(width / 2 + 0.9 * radius), 0] > 0.3
    assert pixels[height // 2, int(width / 2 + 1.1 * radius), 2] > 0.5


def test_fine_phong_sphere_matches_the_raymarched_sphere() -> None:
    raymarched = glint.render(raymarched_scene(), size=SIZE).pixels
    mesh = _render(mesh_scene(subdivisions=6, shading="phong"))
    error = flip_error(raymarched, mesh)
    assert error < 0.02, error


def test_gouraud_converges_to_phong() -> None:
    phong = _render(mesh_scene(subdivisions=6, shading="phong"))
    errors = [
        flip_error(phong, _render(mesh_scene(subdivisions=level, shading="gouraud")))
        for level in (1, 2, 3)
    ]
    assert errors[0] > errors[1] > errors[2], errors
    assert errors[0] > 2.0 * errors[2], errors


def test_flat_shading_is_exact_on_flat_faces() -> None:
    """A cube's built-in normals are its faces' normals: flat shading (derivatives of the
    world position) must draw what phong shading (interpolated exact normals) draws."""
    rotated = {"rotation": [20.0, 35.0, 0.0], "scale": 0.7}
    scenes = [mesh_scene("cube", 1, shading) for shading in ("flat", "phong")]
    for scene in scenes:
        scene["objects"][0] |= rotated
    flat, phong = (_render(scene) for scene in scenes)
    assert np.abs(flat - phong).max() < 2e-3
    # and on a curved mesh flat is not phong: the facets show
    coarse = [_render(mesh_scene("icosphere", 1, shading)) for shading in ("flat", "phong")]
    assert np.abs(coarse[0] - coarse[1]).max() > 0.05


def test_cli_renders_a_mesh_scene(tmp_path: Path) -> None:
    (tmp_path / "cube.toml").write_text(
        '[[objects]]\nshape = "mesh"\nbuiltin = "cube"\nmaterial = "m"\n'
        "[materials.m]\nalbedo = [0.8, 0.8, 0.8]\n"
        '[[lights]]\ntype = "directional"\ndirection = [0.3, 1.0, 0.5]\n'
    )
    result = subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", "render", "cube.toml", "-o", "cube.png"]
        + ["--size", "64x36", "--json"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)
    assert report["nan"] == 0 and report["glsl_version"] == "330"
    assert (tmp_path / "cube.png").stat().st_size > 0
