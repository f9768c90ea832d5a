"""Float64 references for the normal distribution functions (slot D).

Each takes `NoH` (cosine of the half vector's polar angle) and `a` (roughness², never perceptual
roughness), like `float distribution(float NoH, float a)`, and returns D(h). Every NDF here is
normalised so that the projected microfacet area is one: ∫ D(h) (n·h) dω_h = 1 (Walter et al.
2007, eq. 4).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

_GAUSS_NODES, _GAUSS_WEIGHTS = np.polynomial.legendre.leggauss(400)


def _sin2(NoH: np.ndarray) -> np.ndarray:
    # 1 − cos² as (1 − c)(1 + c): no cancellation next to c = 1, where the narrow lobes live.
    return (1.0 - NoH) * (1.0 + NoH)


def D_ggx(*, NoH: ArrayLike, a: ArrayLike) -> np.ndarray:
    """GGX / Trowbridge-Reitz: a² / (π (cos²θ a² + sin²θ)²) (Walter et al. 2007, eq. 33)."""
    c = np.asarray(NoH, np.float64)
    a = np.asarray(a, np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        d = c * c * a * a + _sin2(c)
        return a * a / (np.pi * d * d)


def D_beckmann(*, NoH: ArrayLike, a: ArrayLike) -> np.ndarray:
    """Beckmann: exp(−tan²θ / a²) / (π a² cos⁴θ) (Walter et al. 2007, eq. 25); 0 at θ = π/2."""
    c = np.asarray(NoH, np.float64)
    a = np.asarray(a, np.float64)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        c2 = c * c
        value = np.exp(-_sin2(c) / (c2 * a * a)) / (np.pi * a * a * c2 * c2)
    return np.where(c > 0.0, value, 0.0)


def blinn_phong_exponent(a: ArrayLike) -> np.ndarray:
    """The Blinn-Phong exponent that matches Beckmann of roughness a: n = 2/a² − 2 (Walter 2007)."""
    a = np.asarray(a, np.float64)
    with np.errstate(divide="ignore"):
        return 2.0 / (a * a) - 2.0


def D_blinn_phong(*, NoH: ArrayLike, a: ArrayLike) -> np.ndarray:
    """Normalised Blinn-Phong: (n + 2) / (2π) cosⁿθ, since ∫ cosⁿθ cosθ dω = 2π / (n + 2)."""
    c = np.clip(np.asarray(NoH, np.float64), 0.0, 1.0)
    n = blinn_phong_exponent(a)
    with np.errstate(invalid="ignore", over="ignore"):
        return (n + 2.0) / (2.0 * np.pi) * c**n


def gaussian_norm(a: ArrayLike) -> np.ndarray:
    """1 / ∫ exp(−(θ/a)²) cosθ dω over the hemisphere, by 400-point Gauss-Legendre in θ.

    The integral is π ∫₀^{π/2} exp(−θ²/a²) sin 2θ dθ; it has no elementary closed form (it is
    a Dawson-function term minus a tail at θ = π/2), and tends to π a² as a → 0. The quadrature
    runs on [0, min(π/2, 8a)]: beyond 8a the integrand is below e⁻⁶⁴.
    """
    a = np.asarray(a, np.float64)
    upper = np.minimum(np.pi / 2, 8.0 * a)[..., None]
    theta = 0.5 * upper * (_GAUSS_NODES + 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        integrand = np.exp(-((theta / a[..., None]) ** 2)) * np.sin(2.0 * theta)
    integral = np.pi * 0.5 * upper[..., 0] * (integrand @ _GAUSS_WEIGHTS)
    with np.errstate(divide="ignore"):
        return 1.0 / integral


def D_gaussian(*, NoH: ArrayLike, a: ArrayLike) -> np.ndarray:
    """Gaussian in the half-vector angle, normalised: exp(−(θ/a)²) · gaussian_norm(a).

    The seed's version (004) has no normalisation, so its energy grows without bound as a → 0.
    """
    c = np.clip(np.asarray(NoH, np.float64), -1.0, 1.0)
    a = np.asarray(a, np.float64)
    theta = np.arctan2(np.sqrt(_sin2(c)), c)
    a_flat, inverse = np.unique(a, return_inverse=True)
    norm = gaussian_norm(a_flat)[inverse].reshape(a.shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.exp(-((theta / a) ** 2)) * norm


# The references this module contributes to the registry, by the name snippets use.
REFERENCES = {
    "D_ggx": D_ggx,
    "D_beckmann": D_beckmann,
    "D_blinn_phong": D_blinn_phong,
    "D_gaussian": D_gaussian,
}
