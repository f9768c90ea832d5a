"""Physics of the diffuse and specular lobes: the energy each variant's own GLSL reflects (run
at float64 by the evaluator), and, on the float64 references, reciprocity and the limits where
models coincide; and the half vector at L = −V."""

from __future__ import annotations

import numpy as np
import pytest

from glint.compiler.catalog.loader import load_catalog
from glint.compiler.compose.linking.snippet_evaluation import evaluate_snippet
from glint.compiler.verify.references import REFERENCES
from glint.compiler.verify.references.geometry import Lobe, directional_albedo, dots

CATALOG = load_catalog()
LOBES = sorted(s.id for s in CATALOG.snippets.values() if s.slot in ("diffuse", "specular"))
NOV = [1e-3, 0.2, 0.6, 1.0]
ROUGHNESS = [0.3, 0.6, 1.0]  # smoother lobes need finer quadrature than a test can afford

# Models that reflect more than arrives, by design, with the largest albedo measured over
# NOV × ROUGHNESS (white surface, F = 1; the quadrature is good to about 1e-3). Listed so that
# the excess is stated, not hidden: each must still exceed 1.01 and stay below its bound.
EXCEEDS_BY_DESIGN = {
    "diffuse.lambert_unnormalized": 3.143,  # π: the 1/π is left to the light's intensity
    "diffuse.half_lambert": 1.334,  # 4/3 whatever the view: light wraps to the back
    "diffuse.burley": 1.555,  # retro-reflection of rough surfaces at grazing view
    "diffuse.oren_nayar": 1.045,  # interreflection term at grazing view, σ = 0.3, albedo 1
    "diffuse.toon": 1.513,  # the rim adds light at grazing view
    "specular.phong": 6.274,  # unnormalised: 2π at roughness 1, where the lobe is flat
    "specular.blinn_phong": 6.274,
    "specular.blinn_phong_normalized": 1.071,  # (n + 8)/8π overshoots near normal incidence
}


def glsl_lobe(snippet_id: str) -> Lobe:
    """The variant's own GLSL (other slots at their balanced choices) as a lobe function of
    the geometry, evaluated at float64 for a white surface and F = 1."""

    def lobe(*, NoL: np.ndarray, NoV: float, phi: np.ndarray, roughness: float) -> np.ndarray:
        d = dots(NoL, NoV, phi)
        shape = d["NoL"].shape
        lanes = {k: np.ravel(v) for k, v in d.items()}
        surface = {
            "P": np.zeros(3),
            "N": np.array([0.0, 0.0, 1.0]),
            "V": np.array([0.0, 0.0, 1.0]),
            "diffuseColor": np.ones(3),
            "f0": np.full(3, 0.04),
            "roughness": np.float64(roughness),
            "a": np.float64(roughness**2),
            "NoV": np.float64(max(NoV, 1e-4)),
            "diffuseRoughness": np.float64(roughness),
        }
        args = [surface, lanes] + ([np.ones(3)] if snippet_id.startswith("specular") else [])
        out = evaluate_snippet(snippet_id, args=args, dtype=np.float64)
        return np.asarray(out)[..., 0].reshape(shape)

    return lobe


def albedo_range(lobe: Lobe) -> float:
    return max(
        directional_albedo(lobe, nov, r, n_theta=96, n_phi=96) for nov in NOV for r in ROUGHNESS
    )


@pytest.mark.parametrize("snippet_id", LOBES)
def test_directional_albedo_at_most_one_or_listed(snippet_id: str) -> None:
    worst = albedo_range(glsl_lobe(snippet_id))
    if snippet_id in EXCEEDS_BY_DESIGN:
        assert 1.01 < worst <= EXCEEDS_BY_DESIGN[snippet_id] * 1.001, worst
    else:
        assert worst <= 1.01, f"albedo {worst:.4f}: add it to EXCEEDS_BY_DESIGN or fix it"


def test_cook_torrance_with_ggx_loses_energy_only() -> None:
    # A single-scattering GGX lobe loses what bounces more than once between facets: at
    # roughness 1 seen head-on, about 70% (Monte Carlo with GGX-sampled half vectors: 0.307).
    rough = directional_albedo(REFERENCES["specular_cook_torrance_ggx"], 1.0, 1.0)
    assert rough == pytest.approx(0.307, abs=0.003)
    smooth = directional_albedo(REFERENCES["specular_cook_torrance_ggx"], 1.0, 0.3)
    assert 0.98 < smooth <= 1.0


def test_energy_conserving_wrap_reflects_uniform_light_as_lambert() -> None:
    for wrap in (0.0, 0.25, 0.5, 1.0):
        albedo = directional_albedo(REFERENCES["diffuse_wrapped"], 0.5, 0.5, wrap=wrap)
        assert albedo == pytest.approx(1.0, abs=2e-3), wrap


def geometry_grid() -> dict[str, np.ndarray]:
    rng = np.random.default_rng(7)
    return {
        "NoL": rng.uniform(0.05, 1.0, 400),
        "NoV": rng.uniform(0.05, 1.0, 400),
        "phi": rng.uniform(0.0, np.pi, 400),
        "roughness": rng.uniform(0.0, 1.0, 400),
    }


RECIPROCAL = [
    "diffuse_lambert",
    "diffuse_oren_nayar",
    "diffuse_burley",
    "specular_blinn_phong_normalized",
    "specular_cook_torrance_ggx",
]


@pytest.mark.parametrize("name", RECIPROCAL)
def test_reciprocity(name: str) -> None:
    # The lobes carry N·L: the BRDF is lobe / N·L, and swapping L and V must not change it.
    g = geometry_grid()
    forward = REFERENCES[name](**g) / g["NoL"]
    swapped = dict(g, NoL=g["NoV"], NoV=g["NoL"])
    backward = REFERENCES[name](**swapped) / g["NoV"]
    np.testing.assert_allclose(forward, backward, rtol=1e-9, atol=1e-12)


def test_the_lambert_family_meets_where_it_should() -> None:
    g = geometry_grid()
    g["NoL"] = np.linspace(-1.0, 1.0, 400)
    lambert = REFERENCES["diffuse_lambert"](**g)
    np.testing.assert_allclose(REFERENCES["diffuse_generalized"](**g), lambert)
    np.testing.assert_allclose(REFERENCES["diffuse_wrapped"](**g, wrap=0.0), lambert)
    half = REFERENCES["diffuse_generalized"](**g, multiply=0.5, add=0.5, power=2.0)
    np.testing.assert_allclose(REFERENCES["diffuse_half_lambert"](**g), half)
    smooth = dict(g, roughness=np.zeros(400))
    np.testing.assert_allclose(REFERENCES["diffuse_oren_nayar"](**smooth), lambert, atol=1e-15)


def test_full_oren_nayar_brightens_backscatter_on_rough_surfaces() -> None:
    # Seen from the light's side (φ = 0) a rough surface is brighter than Lambert; from the
    # opposite side (φ = π) darker: the flattening that made the model famous (the full moon).
    on = REFERENCES["diffuse_oren_nayar"]
    back = on(NoL=0.5, NoV=0.5, phi=0.0, roughness=0.8)
    forward = on(NoL=0.5, NoV=0.5, phi=np.pi, roughness=0.8)
    lambert = 0.5 / np.pi
    assert back > 1.2 * lambert and forward < lambert


def test_dots_put_the_half_vector_at_zero_when_light_is_behind_the_eye() -> None:
    d = dots(-0.5, 0.5, np.pi)
    assert d["LoV"] == pytest.approx(-1.0)
    assert d["NoH"] == 0.0 and d["VoH"] == 0.0


def test_light_dots_stays_finite_when_light_is_opposite_the_view() -> None:
    view = np.array([[0.6, 0.0, 0.8]])
    surface = {
        "P": np.zeros(3),
        "N": np.array([0.0, 0.0, 1.0]),
        "V": view,
        "diffuseColor": np.ones(3),
        "f0": np.full(3, 0.04),
        "roughness": np.array([0.5]),
        "a": np.array([0.25]),
        "NoV": np.array([0.8]),
        "diffuseRoughness": np.array([0.5]),
    }
    out = evaluate_snippet("core.surface", "lightDots", [surface, -view], dtype=np.float32)
    assert all(np.isfinite(value).all() for value in out.values())
    assert float(out["NoH"][0]) == 0.0 and float(out["NoLsigned"][0]) == pytest.approx(-0.8)
