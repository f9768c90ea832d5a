"""sceneSpan (compose/codegen/bounds.py): the part of a ray where a scene's surfaces can be. A march
that keeps to it must draw what a march of the whole ray draws, on every example scene; each
shape's box must hold the shape; and a user's field is bounded only by what it declares."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from mesh_scenes import example_params

from glint.compiler.compose.codegen.bounds import shape_bounds, span_unit
from glint.compiler.compose.codegen.field_code import rotation_matrix
from glint.compiler.compose.pipeline import compose_scene
from glint.compiler.errors import InputError
from glint.compiler.render import render_full
from glint.compiler.scene.model import load_scene, parse_scene

EXAMPLES = Path(__file__).resolve().parents[2] / "snippets" / "scenes"
WHOLE_RAY = "vec2 sceneSpan(vec3 ro, vec3 rd) {\n    return vec2(0.0, 1e30);\n}\n"
SPAN = re.compile(r"vec2 sceneSpan\(vec3 ro, vec3 rd\) \{\n.*?\n\}\n", re.S)


@pytest.mark.render
@pytest.mark.parametrize("path", example_params("rasterized, so no march to bound"))
def test_a_march_within_the_span_draws_what_the_whole_ray_draws(path: Path) -> None:
    # Every pixel that a march of the whole ray finds a surface for, the march within the span
    # finds too, at the same distance. (It may find more: the step budget it saves on empty
    # space reaches surfaces that the whole-ray march gives up before, far sea and ground.)
    name = path.stem
    shader = compose_scene(load_scene(path), tier="fast").text
    if "sceneSpan(ro, rd)" not in shader:
        pytest.skip(f"{name}: its fast tier does not march (every object is analytic)")
    shader = shader.replace("fragColor = vec4(color, 1.0);", "fragColor = vec4(color, t);")
    whole = SPAN.sub(WHOLE_RAY, shader, count=1)
    assert whole != shader
    for time in (0.0, 4.0):
        kept = render_full(shader, 240, 135, time=time).image[..., 3]
        free = render_full(whole, 240, 135, time=time).image[..., 3]
        # (the whole-ray march may also accept a hit a step past MARCH_FAR, 50; the span ends there)
        found = (free > 0.0) & (free <= 50.0)
        assert found.sum() > 1000
        same = (kept > 0.0) & (np.abs(kept - free) <= 0.01 * free)
        assert same[found].mean() > 0.999, f"{name} at iTime {time}: {(~same[found]).sum()} lost"


def test_a_shapes_box_holds_its_turned_and_scaled_surface() -> None:
    scene = parse_scene(
        """
name = "b"
[[objects]]
shape = "torus"
radius = 1.0
thickness = 0.25
rotation = [90.0, 30.0, 0.0]
scale = 1.5
position = [1.0, 2.0, -1.0]
material = "m"
[materials.m]
albedo = [0.5, 0.5, 0.5]
"""
    )
    lo, hi = shape_bounds(scene.objects[0])  # type: ignore[misc]
    # Points of the torus surface, placed as the scene places it.
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 60), np.linspace(0, 2 * np.pi, 30))
    ring = 1.0 + 0.25 * np.cos(v)
    local = np.stack([ring * np.cos(u), 0.25 * np.sin(v), ring * np.sin(u)], -1).reshape(-1, 3)
    world = 1.5 * local @ np.asarray(rotation_matrix([90.0, 30.0, 0.0])).T + [1.0, 2.0, -1.0]
    assert (world >= lo - 1e-9).all() and (world <= hi + 1e-9).all()
    # and not much more than it: each side within the torus' own size of the points
    assert (world.min(axis=0) - lo).max() < 0.6 and (hi - world.max(axis=0)).max() < 0.6


def test_a_user_field_is_bounded_only_when_it_says_where() -> None:
    island = load_scene(EXAMPLES / "island.toml")
    assert island.geometry is not None and island.geometry.bounds is not None
    bounded = span_unit(island.objects, True, island.geometry.bounds).body
    assert "boxSlabs" in bounded
    assert span_unit(island.objects, True, None).body.strip().endswith("return vec2(0.0, 1e30);\n}")
    text = (EXAMPLES / "island.toml").read_text()
    swapped = text.replace(
        "bounds = [[-2.7, -0.35, -2.7], [2.7, 0.7, 2.7]]",
        "bounds = [[2.7, -0.35, -2.7], [-2.7, 0.7, 2.7]]",
    )
    assert swapped != text
    with pytest.raises(InputError, match="bounds: the first corner must be below the second"):
        parse_scene(swapped, str(EXAMPLES / "island.toml"))
