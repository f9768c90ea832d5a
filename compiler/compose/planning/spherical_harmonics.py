"""Order-2 (nine-term) spherical-harmonic projection of an environment, for `irradiance.sh9`.

Ramamoorthi and Hanrahan (2001, "An Efficient Representation for Irradiance Environment Maps")
showed that irradiance is so smooth that the first nine real SH terms of the radiance carry it:
convolving with the clamped cosine multiplies band l by Â_l = π, 2π/3, π/4, and bands above 2
are small (Â_3 = 0, Â_4 = −π/24). This module projects radiance L(ω) onto those nine terms by
quadrature; the snippet applies the basis and the Â_l/π factors on the GPU, so its parameters
SH_C0..SH_C8 are the radiance coefficients L_lm themselves, in the order of `SH9_TERMS`.

The environment is a numpy function of unit directions (..., 3) -> radiance (..., 3), or a
catalog `env` snippet run by the GLSL evaluator at float64 with chosen parameters.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import cache

import numpy as np

from glint.compiler.compose.linking.snippet_evaluation import evaluate_snippet

Environment = Callable[[np.ndarray], np.ndarray]

# Real SH basis constants (Sloan 2008, "Stupid Spherical Harmonics Tricks", appendix A2),
# z the polar axis: Y00, Y1-1 (y), Y10 (z), Y11 (x), Y2-2 (xy), Y2-1 (yz), Y20 (3z² − 1),
# Y21 (xz), Y22 (x² − y²).
SH9_TERMS = ("1", "y", "z", "x", "xy", "yz", "3z2-1", "xz", "x2-y2")
Y0 = 0.5 / np.sqrt(np.pi)  # 0.282095
Y1 = np.sqrt(3.0 / (4.0 * np.pi))  # 0.488603
Y2 = 0.5 * np.sqrt(15.0 / np.pi)  # 1.092548
Y20 = 0.25 * np.sqrt(5.0 / np.pi)  # 0.315392
Y22 = 0.25 * np.sqrt(15.0 / np.pi)  # 0.546274
# Â_l / π per term: the clamped-cosine convolution over π (irradiance/π, what Lambert needs).
BAND_FACTOR = np.array([1.0, 2 / 3, 2 / 3, 2 / 3, 0.25, 0.25, 0.25, 0.25, 0.25])
PARAM_NAMES = tuple(f"SH_C{i}" for i in range(9))


def sh9_basis(dirs: np.ndarray) -> np.ndarray:
    """The nine real SH functions at unit directions (..., 3): (..., 9)."""
    x, y, z = dirs[..., 0], dirs[..., 1], dirs[..., 2]
    return np.stack(
        [
            np.full_like(x, Y0),
            Y1 * y,
            Y1 * z,
            Y1 * x,
            Y2 * x * y,
            Y2 * y * z,
            Y20 * (3.0 * z * z - 1.0),
            Y2 * x * z,
            Y22 * (x * x - y * y),
        ],
        -1,
    )


@cache
def sphere_rule(
    n_mu: int = 64, n_phi: int = 128, breaks: tuple[float, ...] = ()
) -> tuple[np.ndarray, np.ndarray]:
    """Directions (K, 3) and weights (K,) of ∫ g dω over the sphere: Gauss-Legendre in μ = y on
    panels split at `breaks` (y values where the environment jumps, e.g. the rim of a sun disc
    at the zenith, so that no panel straddles a discontinuity), trapezoid in the azimuth."""
    edges = np.unique(np.concatenate([[-1.0], np.asarray(breaks, float), [1.0]]))
    x, w = np.polynomial.legendre.leggauss(n_mu)
    mus, mu_w = [], []
    for lo, hi in zip(edges[:-1], edges[1:], strict=True):
        mus.append(lo + 0.5 * (hi - lo) * (x + 1.0))
        mu_w.append(0.5 * (hi - lo) * w)
    mu, wmu = np.concatenate(mus), np.concatenate(mu_w)
    phi = (np.arange(n_phi) + 0.5) * (2.0 * np.pi / n_phi)
    s = np.sqrt(1.0 - mu * mu)[:, None]
    dirs = np.stack(np.broadcast_arrays(s * np.cos(phi), mu[:, None], s * np.sin(phi)), -1).reshape(
        -1, 3
    )
    weights = (wmu[:, None] * np.full(n_phi, 2.0 * np.pi / n_phi)).ravel()
    return dirs, weights


def project_sh9(
    env: Environment, n_mu: int = 64, n_phi: int = 128, breaks: Sequence[float] = ()
) -> np.ndarray:
    """L_lm = ∫ L(ω) Y_lm(ω) dω for the nine terms: (9, 3), float64."""
    dirs, weights = sphere_rule(n_mu, n_phi, tuple(breaks))
    radiance = np.asarray(env(dirs), np.float64).reshape(-1, 3)
    return np.einsum("kc,ki,k->ic", radiance, sh9_basis(dirs), weights)


def sh9_irradiance(coefficients: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """E(n)/π from the nine radiance coefficients (9, 3) at unit normals (..., 3): what the
    snippet computes, in float64."""
    return np.einsum("...i,i,ic->...c", sh9_basis(normals), BAND_FACTOR, coefficients)


def snippet_environment(
    snippet_id: str = "env.gradient", params: dict[str, str] | None = None
) -> Environment:
    """A catalog `env` snippet as a numpy environment, evaluated by compiler/evaluator at float64;
    `params` overrides its parameters as GLSL text, e.g. {"ENV_TOP": "vec3(1.0)"}."""

    def radiance(dirs: np.ndarray) -> np.ndarray:
        out = evaluate_snippet(snippet_id, args=[dirs], dtype=np.float64, params=params)
        return np.asarray(out, np.float64)

    return radiance


def sh9_params(coefficients: np.ndarray, digits: int = 7) -> dict[str, list[float]]:
    """The snippet's parameters SH_C0..SH_C8 for these coefficients, rounded for front matter."""
    return {
        name: [round(float(v), digits) + 0.0 for v in row]
        for name, row in zip(PARAM_NAMES, coefficients, strict=True)
    }


def sh9_front_matter(coefficients: np.ndarray) -> str:
    """TOML tables of SH_C0..SH_C8 as irradiance.sh9's front matter holds them."""
    lines = []
    for name, value in sh9_params(coefficients).items():
        lines.append(f'[params.{name}]\ntype = "vec3"\ndefault = {value}')
    return "\n".join(lines) + "\n"
