"""Float64 references for the visibility term (slot V): V = G2 / (4 NoL NoV).

Each takes the fields of the `Dots` struct and `a` by keyword (NoL, NoV, NoH, VoH, LoV, a), like
`float visibility(Dots d, float a)`; a field a model does not use is optional and ignored.

Smith's masking is written with Λ (Heitz 2014, "Understanding the Masking-Shadowing Function",
section 5): G1 = 1 / (1 + Λ), height-correlated G2 = 1 / (1 + Λ(v) + Λ(l)), separable
G2 = G1(v) G1(l). Λ(c) blows up at c → 0 while V stays finite, so everything is written with
c·Λ(c), which is finite there:

    correlated  V = 1 / (4 (NoL NoV + NoV·cΛ(NoL) + NoL·cΛ(NoV)))
    separable   V = 1 / (4 (NoL + cΛ(NoL)) (NoV + cΛ(NoV)))
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike

_erf = np.vectorize(math.erf, otypes=[np.float64])
_SQRT_PI = math.sqrt(math.pi)

CLambda = Callable[[np.ndarray, np.ndarray], np.ndarray]


def _cos(x: ArrayLike) -> np.ndarray:
    return np.clip(np.asarray(x, np.float64), 0.0, 1.0)


def c_lambda_ggx(c: np.ndarray, a: np.ndarray) -> np.ndarray:
    """c·Λ(c) for GGX, Λ = (√(1 + a² tan²θ) − 1) / 2 (Heitz 2014, eq. 72)."""
    return 0.5 * (np.sqrt(c * c + a * a * (1.0 - c) * (1.0 + c)) - c)


def c_lambda_beckmann(c: np.ndarray, a: np.ndarray) -> np.ndarray:
    """c·Λ(c) for Beckmann, Λ = (erf(μ) − 1)/2 + exp(−μ²)/(2μ√π), μ = 1/(a tanθ)
    (Heitz 2014, eq. 69); c/μ = a sinθ makes the second term finite at c = 0."""
    s = np.sqrt((1.0 - c) * (1.0 + c))
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = c / (a * s)
    mu = np.where(np.isnan(mu), np.inf, mu)  # a sinθ = 0 and c = 0 only at a = 0: no masking
    return 0.5 * c * (_erf(mu) - 1.0) + a * s * np.exp(-mu * mu) / (2.0 * _SQRT_PI)


def _correlated(c_lambda: CLambda, NoL: ArrayLike, NoV: ArrayLike, a: ArrayLike) -> np.ndarray:
    nl, v, a = _cos(NoL), _cos(NoV), np.asarray(a, np.float64)
    with np.errstate(divide="ignore"):
        return 0.25 / (nl * v + v * c_lambda(nl, a) + nl * c_lambda(v, a))


def _separable(c_lambda: CLambda, NoL: ArrayLike, NoV: ArrayLike, a: ArrayLike) -> np.ndarray:
    nl, v, a = _cos(NoL), _cos(NoV), np.asarray(a, np.float64)
    with np.errstate(divide="ignore"):
        return 0.25 / ((nl + c_lambda(nl, a)) * (v + c_lambda(v, a)))


def V_smith_ggx_correlated(
    *, NoL: ArrayLike, NoV: ArrayLike, a: ArrayLike, **_other_dots: ArrayLike
) -> np.ndarray:
    """Height-correlated Smith for GGX (Heitz 2014, eq. 99)."""
    return _correlated(c_lambda_ggx, NoL, NoV, a)


def V_smith_ggx_separable(
    *, NoL: ArrayLike, NoV: ArrayLike, a: ArrayLike, **_other_dots: ArrayLike
) -> np.ndarray:
    """Separable Smith for GGX, G1(l)·G1(v): what Schlick-GGX with k = a/2 fits (Karis 2013)."""
    return _separable(c_lambda_ggx, NoL, NoV, a)


def V_smith_ggx_separable_remapped(
    *, NoL: ArrayLike, NoV: ArrayLike, a: ArrayLike, **_other_dots: ArrayLike
) -> np.ndarray:
    """Separable Smith GGX at the roughness UE4 uses for analytic lights, r' = (r + 1)/2 with
    r = √a, so a' = ((√a + 1)/2)² (Karis 2013, "Real Shading in Unreal Engine 4", p. 3).
    Schlick-GGX with k = (r + 1)²/8 = a'/2 approximates this, not the unremapped model."""
    a_remapped = ((np.sqrt(np.asarray(a, np.float64)) + 1.0) / 2.0) ** 2
    return _separable(c_lambda_ggx, NoL, NoV, a_remapped)


def V_smith_beckmann_correlated(
    *, NoL: ArrayLike, NoV: ArrayLike, a: ArrayLike, **_other_dots: ArrayLike
) -> np.ndarray:
    """Height-correlated Smith for Beckmann with the exact (erf) Λ (Heitz 2014, eq. 99, 69)."""
    return _correlated(c_lambda_beckmann, NoL, NoV, a)


def V_smith_beckmann_separable(
    *, NoL: ArrayLike, NoV: ArrayLike, a: ArrayLike, **_other_dots: ArrayLike
) -> np.ndarray:
    """Separable Smith for Beckmann, G1(l)·G1(v) with the exact Λ."""
    return _separable(c_lambda_beckmann, NoL, NoV, a)


def V_cook_torrance(
    *,
    NoL: ArrayLike,
    NoV: ArrayLike,
    NoH: ArrayLike,
    VoH: ArrayLike,
    **_other_dots: ArrayLike,
) -> np.ndarray:
    """Cook-Torrance's V-groove term over 4 NoL NoV (Cook & Torrance 1982, eq. 7):
    G = min(1, 2 NoH NoV / VoH, 2 NoH NoL / VoH), divided through so that it stays finite at
    NoL → 0 or NoV → 0: V = min(1/(4 NoL NoV), NoH/(2 VoH NoL), NoH/(2 VoH NoV))."""
    nl, v, h, vh = _cos(NoL), _cos(NoV), _cos(NoH), _cos(VoH)
    with np.errstate(divide="ignore", invalid="ignore"):
        terms = np.stack(
            np.broadcast_arrays(0.25 / (nl * v), 0.5 * h / (vh * nl), 0.5 * h / (vh * v))
        )
    return np.nanmin(np.where(np.isnan(terms), np.inf, terms), axis=0)


# G1 on its own, for the weak white furnace test and for anyone who needs the masking term.
def G1_smith_ggx(*, NoV: ArrayLike, a: ArrayLike) -> np.ndarray:
    """GGX Smith masking of one direction, 1/(1 + Λ) = c / (c + cΛ(c))."""
    v = _cos(NoV)
    with np.errstate(divide="ignore", invalid="ignore"):
        return v / (v + c_lambda_ggx(v, np.asarray(a, np.float64)))


def G1_smith_beckmann(*, NoV: ArrayLike, a: ArrayLike) -> np.ndarray:
    """Beckmann Smith masking of one direction, 1/(1 + Λ) with the exact Λ."""
    v = _cos(NoV)
    with np.errstate(divide="ignore", invalid="ignore"):
        return v / (v + c_lambda_beckmann(v, np.asarray(a, np.float64)))


# The references this module contributes to the registry, by the name snippets use.
REFERENCES = {
    "V_smith_ggx_correlated": V_smith_ggx_correlated,
    "V_smith_ggx_separable": V_smith_ggx_separable,
    "V_smith_ggx_separable_remapped": V_smith_ggx_separable_remapped,
    "V_smith_beckmann_correlated": V_smith_beckmann_correlated,
    "V_smith_beckmann_separable": V_smith_beckmann_separable,
    "V_cook_torrance": V_cook_torrance,
}
