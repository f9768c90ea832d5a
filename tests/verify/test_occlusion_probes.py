"""AO and shadow variants, run on the GPU over reference SDF scenes, against many-ray float64
ground truth (compiler/verify/references/occlusion.py): within the error budget of their front
matter, more steps never worse, and finite and within [0, 1] where inputs are at their extremes."""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from glint.compiler.bench.errors import set_errors
from glint.compiler.bench.occlusion import (
    TMAX,
    TMIN,
    ao_inputs,
    ao_sets,
    shadow_inputs,
    shadow_sets,
)
from glint.compiler.catalog.loader import Snippet, load_catalog
from glint.compiler.render import render
from glint.compiler.target import shadertoy
from glint.compiler.verify.probes import PROBE_PRELUDE, run_probe
from glint.compiler.verify.references.occlusion_cases import shadow_cases
from glint.compiler.verify.references.scenes import SCENES
from glint.compiler.verify.references.scenes import scene as reference_scene

pytestmark = pytest.mark.render

CATALOG = load_catalog()
SHADOWS = sorted(s.id for s in CATALOG.in_slot("shadow"))
AOS = sorted(s.id for s in CATALOG.in_slot("ao"))


@cache
def shadow_errors(snippet_id: str) -> np.ndarray:
    """|GPU − truth| over every shadow case, pooled. The truth is the snippet's own reference:
    a disc light matched to its SHADOW_K, or a single ray for the hard shadow."""
    snippet = CATALOG.snippets[snippet_id]
    k = snippet.params.get("SHADOW_K")
    errors = []
    for case in shadow_sets(snippet.reference, None if k is None else float(k.default)):
        gpu = run_probe(snippet_id, case.inputs, CATALOG, case.scene_stub)
        errors.append(set_errors(case, gpu))
    return np.concatenate(errors)


def ao_errors(snippet_id: str) -> np.ndarray:
    errors = []
    for case in ao_sets():
        gpu = run_probe(snippet_id, case.inputs, CATALOG, case.scene_stub)
        errors.append(set_errors(case, gpu))
    return np.concatenate(errors)


def hold_to_budget(snippet: Snippet, error: np.ndarray) -> None:
    budget = snippet.error_budget
    assert np.isfinite(error).all(), f"{snippet.id}: non-finite output"
    report = f"{snippet.id}: max {error.max():.3f}, mean {error.mean():.4f} over {error.size}"
    if "max_abs" in budget:
        assert error.max() <= budget["max_abs"], report
    assert error.mean() <= budget["mean_abs"], report


def test_every_scene_variant_names_a_reference_and_a_mean_budget() -> None:
    for snippet in (CATALOG.snippets[i] for i in SHADOWS + AOS):
        assert snippet.reference, f"{snippet.file} names no reference"
        assert "mean_abs" in snippet.error_budget, f"{snippet.file}: {snippet.error_budget}"


@pytest.mark.parametrize("snippet_id", SHADOWS)
def test_shadow_within_its_error_budget(snippet_id: str) -> None:
    hold_to_budget(CATALOG.snippets[snippet_id], shadow_errors(snippet_id))


@pytest.mark.parametrize("snippet_id", AOS)
def test_ao_within_its_error_budget(snippet_id: str) -> None:
    hold_to_budget(CATALOG.snippets[snippet_id], ao_errors(snippet_id))


def test_more_steps_do_not_add_error() -> None:
    # The same march at 12 and 64 steps: 12 steps reach t ≤ 2.4 and miss the far occluders of
    # low suns. (Per case 64 steps can lose to 12 where the short march stops before an outer
    # penumbra that the estimator draws too dark; pooled, the longer march must win.)
    few, many = shadow_errors("shadow.soft_12"), shadow_errors("shadow.soft_64")
    assert many.mean() <= few.mean(), (many.mean(), few.mean())
    assert many.max() <= few.max(), (many.max(), few.max())
    assert np.sqrt(np.mean(many**2)) <= np.sqrt(np.mean(few**2))


def test_presets_run_their_base_with_their_own_defaults() -> None:
    # soft_64 and soft share one body; on a long, low shadow only the step count tells them
    # apart, so their outputs must differ there.
    c = shadow_cases()[1]
    stub = reference_scene(c.scene).glsl(queries=True)
    inputs = shadow_inputs(c.ro, c.light, TMIN, TMAX)
    preset = run_probe("shadow.soft_64", inputs, CATALOG, stub)
    base = run_probe("shadow.soft", inputs, CATALOG, stub)
    assert np.abs(preset - base).max() > 0.1


# Shadow rays at the extremes, on the sphere-on-plane scene: starting on the ground, inside the
# sphere, at the contact point, far away; toward the light, along the ground, into it, zero.
EXTREME_ORIGINS = np.array(
    [[0.0, 0.0, 2.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0], [0.0, 2.0, 0.0], [1e4, 0.0, 0.0]]
)
EXTREME_DIRECTIONS = np.array(
    [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.6, 0.8, 0.0], [0.0, 0.0, 0.0]]
)
EXTREME_T = [(0.0, 20.0), (1e-7, 20.0), (0.02, 0.0), (0.02, 1e6), (5.0, 1.0)]


@pytest.mark.parametrize("snippet_id", SHADOWS)
def test_shadow_finite_and_in_range_at_the_extremes(snippet_id: str) -> None:
    rows = [(ro, rd, t) for ro in EXTREME_ORIGINS for rd in EXTREME_DIRECTIONS for t in EXTREME_T]
    ro = np.array([r[0] for r in rows])
    rd = np.array([r[1] for r in rows])
    tmin, tmax = (np.array([r[2][i] for r in rows]) for i in (0, 1))
    inputs = shadow_inputs(ro, rd, 0.0, 0.0) | {"tmin": tmin, "tmax": tmax}
    stub = reference_scene("sphere_on_plane").glsl(queries=True)
    values = run_probe(snippet_id, inputs, CATALOG, stub)
    bad = ~np.isfinite(values) | (values < 0.0) | (values > 1.0)
    example = rows[int(np.argmax(bad))]
    assert not bad.any(), f"{bad.sum()} bad outputs, e.g. ro, rd, (tmin, tmax) = {example}"


@pytest.mark.parametrize("snippet_id", AOS)
def test_ao_finite_and_in_range_at_the_extremes(snippet_id: str) -> None:
    normals = np.array([[0.0, 1.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
    rows = [(p, n) for p in EXTREME_ORIGINS for n in normals]
    p = np.array([r[0] for r in rows])
    n = np.array([r[1] for r in rows])
    values = run_probe(snippet_id, ao_inputs(p, n), CATALOG, reference_scene("corner").glsl())
    bad = ~np.isfinite(values) | (values < 0.0) | (values > 1.0)
    assert not bad.any(), f"bad outputs at p, n = {rows[int(np.argmax(bad))]}"


@pytest.mark.parametrize("name", sorted(SCENES))
def test_glsl_map_is_the_numpy_sdf(name: str) -> None:
    # The probes march the GLSL `map`; the ground truth intersects the numpy scene: both must be
    # the same scene. Points around the objects, inside and out, evaluated on the GPU.
    scene = reference_scene(name)
    points = np.random.default_rng(3).uniform([-3.0, -0.5, -3.0], [3.0, 2.5, 3.0], (4096, 3))
    main = (
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    vec3 p = texelFetch(iChannel0, ivec2(fragCoord), 0).xyz;\n"
        "    fragColor = vec4(map(p), 0.0, 0.0, 1.0);\n"
        "}\n"
    )
    source = PROBE_PRELUDE + scene.glsl() + main + shadertoy.EPILOGUE
    texels = np.zeros((64, 64, 4), np.float32)
    texels[..., :3] = points.reshape(64, 64, 3)
    image = render(source, 64, 64, channels=[texels])
    gpu = image[::-1, :, 0].reshape(-1).astype(np.float64)
    exact = scene.sdf(points.astype(np.float32).astype(np.float64))
    assert np.abs(gpu - exact).max() < 1e-5
