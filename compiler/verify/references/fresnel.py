"""Float64 references for the Fresnel term (slot F).

Each takes `f0` (reflectance at normal incidence: a scalar or an array whose last axis is RGB)
and `cosTheta`, like `vec3 fresnel(vec3 f0, float cosTheta)`. `f0` and `cosTheta` broadcast
against each other; for a last axis of 3, give `cosTheta` a trailing axis of 1.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike


def f0_from_ior(ior: ArrayLike) -> np.ndarray:
    """Reflectance at normal incidence of an interface to a medium of relative IOR η:
    ((η − 1) / (η + 1))²."""
    eta = np.asarray(ior, np.float64)
    return ((eta - 1.0) / (eta + 1.0)) ** 2


def ior_from_f0(f0: ArrayLike) -> np.ndarray:
    """The relative IOR η ≥ 1 whose f0 this is: η = (1 + √f0) / (1 − √f0); ∞ at f0 = 1."""
    s = np.sqrt(np.clip(np.asarray(f0, np.float64), 0.0, 1.0))
    with np.errstate(divide="ignore"):
        return (1.0 + s) / (1.0 - s)


def fresnel_dielectric_ior(*, eta: ArrayLike, cosTheta: ArrayLike) -> np.ndarray:
    """Exact unpolarised Fresnel reflectance for relative IOR η (Walter et al. 2007, eq. 22):

    g = √(η² − 1 + c²), F = ½ ((g − c)/(g + c))² (1 + ((c(g + c) − 1)/(c(g − c) + 1))²).

    η < 1 (leaving a denser medium) beyond the critical angle has g² < 0: total internal
    reflection, F = 1. η = ∞ (f0 = 1) reflects everything. η = 1 reflects nothing.
    """
    eta = np.asarray(eta, np.float64)
    c = np.abs(np.asarray(cosTheta, np.float64))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        g2 = eta * eta - 1.0 + c * c
        g = np.sqrt(np.maximum(g2, 0.0))
        A = (g - c) / (g + c)
        B = (c * (g + c) - 1.0) / (c * (g - c) + 1.0)
        F = 0.5 * A * A * (1.0 + B * B)
    F = np.where(g2 <= 0.0, 1.0, F)  # total internal reflection
    F = np.where(np.isinf(eta), 1.0, F)
    return np.where(eta == 1.0, 0.0, F)  # matched media: no interface, even at grazing


def F_dielectric(*, f0: ArrayLike, cosTheta: ArrayLike) -> np.ndarray:
    """Exact Fresnel of the dielectric whose IOR is recovered from f0, channel by channel.

    This is what Schlick's approximation (Schlick 1994) approximates; for conductors it is a
    stand-in (their f0 has no real IOR), which is how the F slot treats every f0.
    """
    return fresnel_dielectric_ior(eta=ior_from_f0(f0), cosTheta=np.clip(cosTheta, 0.0, 1.0))


# The references this module contributes to the registry, by the name snippets use.
REFERENCES = {
    "F_dielectric": F_dielectric,
}
