"""Float64 references for scattering and participating media (slots phase, sss and media).

- `phase_henyey_greenstein(cosTheta, g)`: the Henyey-Greenstein phase function (1941), exact,
  normalised over the sphere, cosTheta the cosine of the scattering angle (g > 0 forward).
- `subsurface_sphere(p0..p2, L0..L2, radius, SSS_EXTINCTION)`: exp(−σ·c), c the exact length of
  the ray p + tL, t ≥ 0, inside a sphere of `radius` at the origin.
- `medium_beer(color0..2, dist, MEDIUM_EXTINCTION, MEDIUM_INSCATTER)`: Beer-Lambert
  extinction with constant in-scatter, color·T + inscatter·(1 − T), T = exp(−σ·dist).

Parameters named in capitals are the snippets' own `#define` knobs; their defaults here are
the snippets' defaults (tests/verify/test_scattering.py holds them equal).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

# media.beer's defaults: the skill's water exp2(−6·(0.5, 0.6, 0.9)·d) as natural-log σ.
WATER_EXTINCTION = tuple(6.0 * np.log(2.0) * np.array([0.5, 0.6, 0.9]))
WATER_INSCATTER = (0.02, 0.12, 0.16)
SSS_EXTINCTION = 6.0


def _vec3(x: ArrayLike, y: ArrayLike, z: ArrayLike) -> np.ndarray:
    """Three broadcast components stacked into (..., 3), as the probes pass a vec3."""
    return np.stack(np.broadcast_arrays(*(np.asarray(c, np.float64) for c in (x, y, z))), -1)


def phase_henyey_greenstein(*, cosTheta: ArrayLike, g: ArrayLike) -> np.ndarray:  # noqa: N803
    """(1 − g²) / (4π (1 + g² − 2g cosθ)^{3/2}); the denominator as (1 − g)² + 2g(1 − cosθ),
    which is the same number without cancellation next to g = cosθ = 1."""
    c = np.asarray(cosTheta, np.float64)
    g = np.asarray(g, np.float64)
    d = (1.0 - g) ** 2 + 2.0 * g * (1.0 - c)
    with np.errstate(divide="ignore", invalid="ignore"):
        return (1.0 - g * g) / (4.0 * np.pi * d**1.5)


def phase_schlick(*, cosTheta: ArrayLike, k: ArrayLike) -> np.ndarray:  # noqa: N803
    """Schlick's phase function (1 − k²) / (4π (1 − k cosθ)²), normalised for |k| < 1."""
    c = np.asarray(cosTheta, np.float64)
    k = np.asarray(k, np.float64)
    return (1.0 - k * k) / (4.0 * np.pi * (1.0 - k * c) ** 2)


def chord_through_sphere(p: ArrayLike, L: ArrayLike, radius: ArrayLike) -> np.ndarray:  # noqa: N803
    """Length of {p + tL : t ≥ 0} inside |x| < radius, for unit L; p and L are (..., 3)."""
    p = np.asarray(p, np.float64)
    L = np.asarray(L, np.float64)
    b = np.sum(p * L, -1)
    c = np.sum(p * p, -1) - np.asarray(radius, np.float64) ** 2
    disc = b * b - c
    root = np.sqrt(np.maximum(disc, 0.0))
    enter, leave = -b - root, -b + root
    return np.where(disc > 0.0, np.maximum(leave, 0.0) - np.maximum(enter, 0.0), 0.0)


def subsurface_sphere(
    *,
    p0: ArrayLike,
    p1: ArrayLike,
    p2: ArrayLike,
    L0: ArrayLike,  # noqa: N803
    L1: ArrayLike,  # noqa: N803
    L2: ArrayLike,  # noqa: N803
    radius: ArrayLike = 1.0,
    SSS_EXTINCTION: ArrayLike = SSS_EXTINCTION,  # noqa: N803
) -> np.ndarray:
    """Transmittance exp(−σ c) along L from p through the sphere (L normalised here)."""
    p = _vec3(p0, p1, p2)
    L = _vec3(L0, L1, L2)
    L = L / np.linalg.norm(L, axis=-1, keepdims=True)
    return np.exp(-np.asarray(SSS_EXTINCTION, np.float64) * chord_through_sphere(p, L, radius))


def medium_beer(
    *,
    color0: ArrayLike,
    color1: ArrayLike,
    color2: ArrayLike,
    dist: ArrayLike,
    MEDIUM_EXTINCTION: ArrayLike = WATER_EXTINCTION,  # noqa: N803
    MEDIUM_INSCATTER: ArrayLike = WATER_INSCATTER,  # noqa: N803
) -> np.ndarray:
    """color·T + inscatter·(1 − T), T = exp(−σ max(dist, 0)) per channel: (..., 3)."""
    color = _vec3(color0, color1, color2)
    d = np.maximum(np.asarray(dist, np.float64), 0.0)[..., None]
    transmittance = np.exp(-d * np.asarray(MEDIUM_EXTINCTION, np.float64))
    return color * transmittance + np.asarray(MEDIUM_INSCATTER, np.float64) * (1.0 - transmittance)


REFERENCES = {
    "phase_henyey_greenstein": phase_henyey_greenstein,
    "subsurface_sphere": subsurface_sphere,
    "medium_beer": medium_beer,
}
