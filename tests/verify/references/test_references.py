"""The float64 references are what they claim: normalised NDFs, Smith masking that passes the
weak white furnace, reciprocal visibility, Fresnel with its known values; and every snippet that
names a reference names a real one over inputs it takes."""

from __future__ import annotations

import inspect

import numpy as np
import pytest

from glint.compiler.catalog.loader import load_catalog
from glint.compiler.verify.references import REFERENCES, reference
from glint.compiler.verify.references.fresnel import (
    F_dielectric,
    f0_from_ior,
    fresnel_dielectric_ior,
)
from glint.compiler.verify.references.visibility import G1_smith_beckmann, G1_smith_ggx

# Quadrature in θ on geometric panels, so that lobes as narrow as a = 0.02 are resolved.
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(24)
_EDGES = np.concatenate([[0.0], np.geomspace(1e-6, np.pi / 2, 120)])
_LO, _HI = _EDGES[:-1, None], _EDGES[1:, None]
THETA = (0.5 * (_HI - _LO) * (_NODES + 1.0) + _LO).ravel()
D_THETA = (0.5 * (_HI - _LO) * _WEIGHTS).ravel()

D_NAMES = [name for name in REFERENCES if name.startswith("D_")]
ROUGHNESS_A = [0.02, 0.05, 0.1, 0.3, 0.6, 1.0]


@pytest.mark.parametrize("name", D_NAMES)
@pytest.mark.parametrize("a", ROUGHNESS_A)
def test_ndf_projected_area_is_one(name: str, a: float) -> None:
    # ∫ D(h) (n·h) dω = 2π ∫ D(cos θ) cos θ sin θ dθ
    d = reference(name)(NoH=np.cos(THETA), a=np.full_like(THETA, a))
    total = 2.0 * np.pi * np.sum(d * np.cos(THETA) * np.sin(THETA) * D_THETA)
    assert total == pytest.approx(1.0, abs=1e-3)


def _azimuthal_clamped_cosine(A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """∫₀^{2π} max(A cos φ + B, 0) dφ for A ≥ 0, in closed form."""
    with np.errstate(divide="ignore", invalid="ignore"):
        phi0 = np.arccos(np.clip(-B / A, -1.0, 1.0))
    partial = 2.0 * A * np.sin(phi0) + 2.0 * B * phi0
    return np.where(B >= A, 2.0 * np.pi * B, np.where(B <= -A, 0.0, partial))


@pytest.mark.parametrize(
    ("ndf", "g1"), [("D_ggx", G1_smith_ggx), ("D_beckmann", G1_smith_beckmann)]
)
@pytest.mark.parametrize("a", [0.05, 0.3, 0.7, 1.0])
@pytest.mark.parametrize("theta_v", [0.0, 0.5, 1.0, 1.4])
def test_weak_white_furnace(ndf: str, g1: object, a: float, theta_v: float) -> None:
    # ∫ G1(v, h) D(h) max(v·h, 0) dω_h / (v·n) = 1 (Heitz 2014, eq. 23); Smith G1 depends on v.
    A = np.sin(theta_v) * np.sin(THETA)
    B = np.cos(theta_v) * np.cos(THETA)
    d = reference(ndf)(NoH=np.cos(THETA), a=np.full_like(THETA, a))
    projected = np.sum(d * _azimuthal_clamped_cosine(A, B) * np.sin(THETA) * D_THETA)
    masking = g1(NoV=np.cos(theta_v), a=a)  # type: ignore[operator]
    assert masking * projected / np.cos(theta_v) == pytest.approx(1.0, rel=1e-2)


V_NAMES = [name for name in REFERENCES if name.startswith("V_")]


@pytest.mark.parametrize("name", V_NAMES)
def test_visibility_is_reciprocal(name: str) -> None:
    rng = np.random.default_rng(7)
    NoL, NoV = rng.uniform(0.0, 1.0, (2, 500))
    rest = {"NoH": rng.uniform(0.1, 1.0, 500), "VoH": rng.uniform(0.1, 1.0, 500)}
    a = rng.uniform(0.0, 1.0, 500)
    forward = reference(name)(NoL=NoL, NoV=NoV, a=a, **rest)
    backward = reference(name)(NoL=NoV, NoV=NoL, a=a, **rest)
    np.testing.assert_allclose(forward, backward, rtol=1e-12)
    assert np.all(np.isfinite(forward)) and np.all(forward >= 0.0)


def test_smith_correlated_matches_filament_closed_form() -> None:
    NoL, NoV, a = np.meshgrid(*(np.linspace(0.01, 1.0, 30),) * 3)
    filament = 0.5 / (
        NoL * np.sqrt(NoV * NoV * (1 - a * a) + a * a)
        + NoV * np.sqrt(NoL * NoL * (1 - a * a) + a * a)
    )
    v = reference("V_smith_ggx_correlated")(NoL=NoL, NoV=NoV, a=a)
    np.testing.assert_allclose(v, filament, rtol=1e-12)


def test_smith_beckmann_is_close_to_ggx_at_low_roughness() -> None:
    # Both tend to no masking away from grazing as a → 0.
    v = reference("V_smith_beckmann_correlated")(NoL=0.7, NoV=0.8, a=0.01)
    assert v == pytest.approx(0.25 / (0.7 * 0.8), rel=1e-3)


def test_fresnel_known_values() -> None:
    assert f0_from_ior(1.5) == pytest.approx(0.04)
    assert F_dielectric(f0=0.04, cosTheta=1.0) == pytest.approx(0.04)
    assert fresnel_dielectric_ior(eta=1.5, cosTheta=1.0) == pytest.approx(0.04)
    assert F_dielectric(f0=0.04, cosTheta=0.0) == pytest.approx(1.0)
    assert F_dielectric(f0=1.0, cosTheta=0.3) == pytest.approx(1.0)
    assert F_dielectric(f0=0.0, cosTheta=0.3) == pytest.approx(0.0)
    # Leaving glass beyond the critical angle (cos θc = √(1 − 1/1.5²) ≈ 0.745): total reflection.
    assert fresnel_dielectric_ior(eta=1 / 1.5, cosTheta=0.5) == pytest.approx(1.0)
    assert fresnel_dielectric_ior(eta=1 / 1.5, cosTheta=1.0) == pytest.approx(0.04)


def test_fresnel_is_per_channel() -> None:
    f0 = np.array([0.02, 0.04, 0.9])
    F = F_dielectric(f0=f0, cosTheta=np.array([[1.0], [0.0]]))
    np.testing.assert_allclose(F, [f0, [1.0, 1.0, 1.0]])


def test_schlick_error_against_exact_dielectric(capsys: pytest.CaptureFixture[str]) -> None:
    # Schlick 1994 approximates the exact Fresnel; report its largest error over f0 and angle.
    # f0 = 0 is left out: η = 1 is no interface (F = 0) while Schlick still gives 1 at grazing.
    f0 = np.linspace(0.01, 1.0, 199)[:, None]
    c = np.linspace(0.0, 1.0, 2001)[None, :]
    schlick = f0 + (1.0 - f0) * (1.0 - c) ** 5
    error = np.abs(schlick - F_dielectric(f0=f0, cosTheta=c))
    glass = 0.04 + 0.96 * (1.0 - c[0]) ** 5
    at_glass = np.abs(glass - F_dielectric(f0=0.04, cosTheta=c[0])).max()
    with capsys.disabled():
        print(f"\nSchlick vs exact: max |dF| {error.max():.4f}, f0 0.04: {at_glass:.4f}")
    # Over dielectrics (f0 ≤ 0.2, water to diamond) Schlick is within 0.11 (0.036 at glass, near
    # cos θ = 0.09); towards f0 = 1 the exact dielectric has a Brewster dip near grazing (F = ½
    # at cos θ ≈ 1/η) that Schlick does not have, so the error there reaches 0.5.
    assert error[f0[:, 0] <= 0.2].max() < 0.11
    assert 0.03 < at_glass < 0.04


def test_unknown_reference_names_the_known_ones() -> None:
    with pytest.raises(KeyError, match="D_ggx"):
        reference("D_nope")


CATALOG = load_catalog()
WITH_REFERENCE = sorted(s.id for s in CATALOG.snippets.values() if s.reference)


def test_the_brdf_terms_name_their_references() -> None:
    for snippet in CATALOG.snippets.values():
        if snippet.slot in {"D", "F", "V"}:
            assert snippet.reference, f"{snippet.relpath} names no reference"


@pytest.mark.parametrize("snippet_id", WITH_REFERENCE)
def test_snippet_reference_exists_and_takes_its_domain(snippet_id: str) -> None:
    snippet = CATALOG.snippets[snippet_id]
    assert snippet.reference in REFERENCES, f"{snippet.relpath}: unknown '{snippet.reference}'"
    parameters = inspect.signature(REFERENCES[snippet.reference]).parameters
    assert set(snippet.domain) <= set(parameters), f"{snippet.relpath}: domain {snippet.domain}"
    for name, bounds in snippet.domain.items():
        assert len(bounds) == 2 and bounds[0] <= bounds[1], f"{snippet.relpath}: {name}"
    budget = snippet.error_budget
    # max_deg / mean_deg: angular error of a normal against the exact normal, in degrees.
    # mean_abs: AO and shadows are also held on average over the points of reference scenes.
    # rms: an approximation by design (specular occlusion, a reflection) is held on its
    # typical error too, not only its worst.
    allowed = {"max_abs", "max_rel", "max_deg", "mean_deg", "mean_abs", "rms"}
    assert set(budget) <= allowed and budget, f"{snippet.relpath}: {budget}"
    assert all(value >= 0 for value in budget.values())
