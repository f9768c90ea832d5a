"""Float64 references for the falloff of a point light with distance (slot attenuation) and of
a spot light with angle (light.spot_cone).

Each takes `dist` (from the light to the shaded point) and `range` (how far the light reaches),
like `float attenuation(float dist, float range)`, and returns the factor by which the light's
intensity is divided down at that distance, broadcasting as numpy does.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

# The seed template's constant-linear-quadratic coefficients (a fit by eye, not physics).
QUADRATIC_LINEAR = 0.1
QUADRATIC_QUADRATIC = 0.01


def inverse_square(*, dist: ArrayLike, range: ArrayLike | None = None) -> np.ndarray:
    """Radiometry of a point source: irradiance falls as 1/d² (∞ at the light itself).
    `range` is accepted and ignored: a physical point light reaches everywhere."""
    d = np.asarray(dist, np.float64)
    with np.errstate(divide="ignore"):
        return 1.0 / (d * d)


def range_window(*, dist: ArrayLike, range: ArrayLike) -> np.ndarray:
    """The smooth cut-off of Karis 2013 (UE4) and Filament: (saturate(1 − (d/r)⁴))².
    It is 1 at d = 0, 0 with zero slope at d = r, and 0 beyond; a range of 0 reaches nothing."""
    d = np.asarray(dist, np.float64)
    r = np.asarray(range, np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        q = d / r
        window = np.clip(1.0 - q**4, 0.0, 1.0) ** 2
    return np.where(d < r, window, 0.0)


def inverse_square_windowed(*, dist: ArrayLike, range: ArrayLike) -> np.ndarray:
    """1/d² brought smoothly to 0 at the range: range_window(d, r) / d². No floor at d = 0:
    that is the GLSL's precaution, not part of the model."""
    window = range_window(dist=dist, range=range)
    d = np.asarray(dist, np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(window > 0.0, window / (d * d), 0.0)


def quadratic(*, dist: ArrayLike, range: ArrayLike | None = None) -> np.ndarray:
    """1 / (1 + 0.1 d + 0.01 d²): the seed's falloff, 1 at the light, 1/d² ·100 far away.
    `range` is ignored, as the GLSL variant ignores it."""
    d = np.asarray(dist, np.float64)
    return 1.0 / (1.0 + QUADRATIC_LINEAR * d + QUADRATIC_QUADRATIC * d * d)


def spot_cone(*, cosAngle: ArrayLike, cosOuter: ArrayLike, cosInner: ArrayLike) -> np.ndarray:
    """Filament's spot falloff: the cosine's place between the outer and the inner cone,
    clamped to [0, 1] and squared; cones closer than 1e-4 in cosine count as 1e-4 apart."""
    c = np.asarray(cosAngle, np.float64)
    outer = np.asarray(cosOuter, np.float64)
    width = np.maximum(np.asarray(cosInner, np.float64) - outer, 1e-4)
    return np.clip((c - outer) / width, 0.0, 1.0) ** 2


# The references this module contributes to the registry, by the name snippets use.
REFERENCES = {
    "attenuation_inverse_square": inverse_square,
    "attenuation_inverse_square_windowed": inverse_square_windowed,
    "attenuation_quadratic": quadratic,
    "spot_cone": spot_cone,
}
