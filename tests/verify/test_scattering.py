"""Phase functions, media and subsurface: the references are what they claim, and the snippets'
own GLSL on the GPU integrates to one, stays finite and non-negative at the ends, and keeps the
transmittance budget of sss.sdf_probe on reference spheres."""

from __future__ import annotations

import numpy as np
import pytest

from glint.compiler.bench import subsurface
from glint.compiler.bench.errors import set_errors
from glint.compiler.catalog.loader import load_catalog
from glint.compiler.verify.probes import run_probe
from glint.compiler.verify.references import scattering
from glint.compiler.verify.references.scattering import phase_henyey_greenstein

CATALOG = load_catalog()
PHASES = sorted(s.id for s in CATALOG.in_slot("phase"))

# Gauss-Legendre on panels that crowd geometrically toward cosθ = ±1, where the lobes peak.
_X, _W = np.polynomial.legendre.leggauss(8)
_STEPS = np.geomspace(1e-7, 1.0, 40)
_EDGES = np.unique(np.concatenate([[-1.0, 1.0], -1.0 + _STEPS, 1.0 - _STEPS]))
_LO, _HI = _EDGES[:-1, None], _EDGES[1:, None]
COS = (0.5 * (_HI - _LO) * (_X + 1.0) + _LO).ravel()
D_COS = (0.5 * (_HI - _LO) * _W).ravel()
G_VALUES = [-0.9, -0.5, 0.0, 0.3, 0.7, 0.9]


def sphere_integral(values: np.ndarray) -> np.ndarray:
    """∫ p dω = 2π ∫ p(cosθ) dcosθ, per row of values (g, COS)."""
    return 2.0 * np.pi * values @ D_COS


def test_henyey_greenstein_reference_is_normalised_with_mean_cosine_g() -> None:
    g = np.array(G_VALUES)[:, None]
    p = phase_henyey_greenstein(cosTheta=COS[None, :], g=g)
    np.testing.assert_allclose(sphere_integral(p), 1.0, atol=1e-9)
    np.testing.assert_allclose(sphere_integral(p * COS), g[:, 0], atol=1e-9)


@pytest.mark.render
@pytest.mark.parametrize("snippet_id", PHASES)
def test_phase_is_normalised(snippet_id: str) -> None:
    g = np.repeat(G_VALUES, len(COS))
    values = run_probe(snippet_id, {"cosTheta": np.tile(COS, len(G_VALUES)), "g": g}, CATALOG)
    totals = sphere_integral(values.astype(np.float64).reshape(len(G_VALUES), -1))
    np.testing.assert_allclose(totals, 1.0, atol=1e-3)


@pytest.mark.render
@pytest.mark.parametrize("snippet_id", PHASES)
def test_phase_finite_and_non_negative_at_the_ends(snippet_id: str) -> None:
    cos = [-1.0, -1e-7, 0.0, 1e-7, 1.0, 1.0 + 1e-6, -1.0 - 1e-6]
    gs = [-1.5, -1.0, -0.999, -0.99, -0.95, 0.0, 0.95, 0.99, 0.999, 1.0, 1.5]
    c, g = (a.ravel() for a in np.meshgrid(cos, gs))
    values = run_probe(snippet_id, {"cosTheta": c, "g": g}, CATALOG)
    bad = ~np.isfinite(values) | (values < 0)
    assert not bad.any(), f"at cosTheta, g = {c[bad][:3]}, {g[bad][:3]}"


@pytest.mark.render
def test_henyey_greenstein_peak_at_the_clamp() -> None:
    # g beyond the clamp reads as ±0.99: the peak is (1 + g)/(4π(1 − g)²) ≈ 1583.6 there.
    values = run_probe("phase.henyey_greenstein", {"cosTheta": [1.0, -1.0], "g": [1.0, -5.0]})
    np.testing.assert_allclose(values, 1.99 / (4 * np.pi * 0.01**2), rtol=1e-5)


def test_reference_defaults_are_the_snippets() -> None:
    beer = CATALOG.get("media.beer").params
    np.testing.assert_allclose(beer["MEDIUM_EXTINCTION"].default, scattering.WATER_EXTINCTION)
    # the skill's water: exp2(−6 (0.5, 0.6, 0.9) d)
    d = 0.37
    np.testing.assert_allclose(
        np.exp(-d * np.array(scattering.WATER_EXTINCTION)),
        np.exp2(-6.0 * d * np.array([0.5, 0.6, 0.9])),
        rtol=1e-7,
    )
    assert beer["MEDIUM_INSCATTER"].default == list(scattering.WATER_INSCATTER)
    sss = CATALOG.get("sss.sdf_probe").params
    assert sss["SSS_EXTINCTION"].default == scattering.SSS_EXTINCTION


@pytest.mark.render
def test_medium_ends() -> None:
    # No distance: the surface as it is; a long way: the medium's own colour.
    color = np.array([[0.9, 0.5, 0.1]] * 2)
    inputs = {f"color{i}": color[:, i] for i in range(3)} | {"dist": np.array([0.0, 50.0])}
    values = run_probe("media.beer", inputs, CATALOG)
    np.testing.assert_allclose(values[0], color[0], atol=1e-7)
    np.testing.assert_allclose(values[1], scattering.WATER_INSCATTER, atol=1e-7)


# --- subsurface on reference spheres (bench/subsurface.py) -----------------------------------


@pytest.mark.render
def test_subsurface_within_its_budget_on_spheres(capsys: pytest.CaptureFixture[str]) -> None:
    rng = np.random.default_rng(subsurface.SEED)
    budget = CATALOG.get("sss.sdf_probe").error_budget["max_abs"]
    report = []
    for radius in subsurface.RADII:
        n, L = subsurface.sphere_directions(rng, subsurface.SAMPLES)  # noqa: N806
        case = subsurface.subsurface_set(radius, n, L)
        gpu = run_probe("sss.sdf_probe", case.inputs, CATALOG, scene_stub=case.scene_stub)
        error = set_errors(case, gpu)
        lit = np.sum(n * L, axis=1) > 0.3  # leaving the body at once: nothing in the way
        assert np.allclose(gpu[lit], 1.0)
        assert error.max() <= budget, f"radius {radius}: {error.max():.3f}"
        report.append(f"r {radius}: max {error.max():.3f} mean {error.mean():.3f}")
    with capsys.disabled():
        print("\nsss.sdf_probe vs exp(-sigma chord): " + "; ".join(report))
