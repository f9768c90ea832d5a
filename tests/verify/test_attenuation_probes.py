"""Point-light attenuation variants on the GPU at the inputs that break falloffs: the light's own
position, a range of zero, distances up to float32's largest and infinity. (Their error against
the float64 references over the domain is held by tests/verify/test_probe_references.py.)"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from glint.compiler.catalog.loader import load_catalog
from glint.compiler.verify.probes import run_probe

pytestmark = pytest.mark.render

CATALOG = load_catalog()
VARIANTS = sorted(s.id for s in CATALOG.in_slot("attenuation"))
F32_MAX = float(np.finfo(np.float32).max)
DISTANCES = [0.0, 1e-30, 1e-7, 0.005, 0.01, 0.5, 1.0, 7.0, 1e4, 1e19, 1e30, F32_MAX, np.inf]
RANGES = [0.0, 1e-7, 0.5, 1.0, 10.0, 1e30, np.inf]


def probe(snippet_id: str, dist: np.ndarray, rng: np.ndarray) -> np.ndarray:
    return run_probe(snippet_id, {"dist": dist, "range": rng}, CATALOG).astype(np.float64)


def extremes() -> tuple[np.ndarray, np.ndarray]:
    table = np.array(list(itertools.product(DISTANCES, RANGES)))
    return table[:, 0], table[:, 1]


@pytest.mark.parametrize("snippet_id", VARIANTS)
def test_finite_and_non_negative_at_the_extremes(snippet_id: str) -> None:
    dist, rng = extremes()
    values = probe(snippet_id, dist, rng)
    bad = ~np.isfinite(values) | (values < 0.0)
    where = [(d, r) for d, r in zip(dist[bad], rng[bad], strict=True)][:5]
    assert not bad.any(), f"{bad.sum()} bad values, e.g. at (dist, range) {where}"


@pytest.mark.parametrize("snippet_id", VARIANTS)
def test_falloff_never_rises_with_distance(snippet_id: str) -> None:
    dist = np.concatenate([np.linspace(0.0, 30.0, 3001), np.geomspace(30.0, 1e30, 200)])
    for light_range in (0.5, 5.0, 25.0):
        values = probe(snippet_id, dist, np.full_like(dist, light_range))
        rises = np.diff(values) > 1e-7 * values[:-1]
        assert not rises.any(), f"range {light_range}: rises after dist {dist[:-1][rises][:3]}"


def test_quadratic_ignores_the_range() -> None:
    dist = np.geomspace(1e-3, 1e3, 200)
    near = probe("attenuation.quadratic", dist, np.zeros_like(dist))
    far = probe("attenuation.quadratic", dist, np.full_like(dist, 1e6))
    np.testing.assert_array_equal(near, far)
    assert probe("attenuation.quadratic", np.zeros(1), np.zeros(1))[0] == 1.0


def test_inverse_square_range_ends_at_the_range_and_caps_at_the_light() -> None:
    snippet_id = "attenuation.inverse_square_range"
    dist, rng = extremes()
    values = probe(snippet_id, dist, rng)
    # Exactly zero wherever the light does not reach: at and past its range, and range 0.
    assert (values[dist >= rng] == 0.0).all()
    # Next to the light the floor ATTEN_MIN_DIST = 0.01 caps the factor at 1e4.
    assert values.max() == pytest.approx(1e4, rel=1e-5)
    at_light = probe(snippet_id, np.zeros(3), np.array([0.5, 10.0, np.inf]))
    np.testing.assert_allclose(at_light, 1e4, rtol=1e-5)
    # Far inside the range the window is 1 to float32 precision: plain inverse square.
    d = np.geomspace(0.02, 1.0, 50)
    inside = probe(snippet_id, d, np.full_like(d, 1e3))
    np.testing.assert_allclose(inside, 1.0 / d**2, rtol=1e-6)
