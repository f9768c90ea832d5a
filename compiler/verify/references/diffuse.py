"""Float64 references for the diffuse lobes (slot diffuse), for a white albedo.

Every function takes the shading geometry (`NoL` signed, `NoV`, `phi`, see `geometry`) and the
perceptual `roughness`, and returns what the GLSL `diffuse(s, d)` returns for
`s.diffuseColor = vec3(1)`: the BRDF times its cosine factor.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from glint.compiler.verify.references.geometry import cos_phi, dots

_INV_PI = 1.0 / np.pi


def diffuse_lambert(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, **_: ArrayLike
) -> np.ndarray:
    """Lambert: 1/π · max(N·L, 0)."""
    return dots(NoL, NoV, phi)["NoL"] * _INV_PI


def diffuse_lambert_unnormalized(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, **_: ArrayLike
) -> np.ndarray:
    """Lambert without the 1/π: the form ShaderToy code writes, with lights π times dimmer."""
    return dots(NoL, NoV, phi)["NoL"]


def diffuse_half_lambert(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, **_: ArrayLike
) -> np.ndarray:
    """Valve's half-Lambert, ((N·L + 1)/2)², on the 1/π scale of Lambert."""
    signed = dots(NoL, NoV, phi)["NoLsigned"]
    return (0.5 * signed + 0.5) ** 2 * _INV_PI


def diffuse_wrapped(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, wrap: float = 0.5, **_: ArrayLike
) -> np.ndarray:
    """Energy-conserving wrap: max(N·L + w, 0) / (1 + w)² / π. Over the sphere of light
    directions ∫ max(cos θ + w, 0) dω = π (1 + w)², so uniform light is reflected as Lambert
    reflects it."""
    signed = dots(NoL, NoV, phi)["NoLsigned"]
    return np.maximum(signed + wrap, 0.0) / (1.0 + wrap) ** 2 * _INV_PI


def diffuse_generalized(
    *,
    NoL: ArrayLike,
    NoV: ArrayLike,
    phi: ArrayLike,
    multiply: float = 1.0,
    add: float = 0.0,
    power: float = 1.0,
    **_: ArrayLike,
) -> np.ndarray:
    """Generalized Lambert, max(N·L · multiply + add, 0)^power / π: Lambert at (1, 0, 1),
    half-Lambert at (0.5, 0.5, 2)."""
    signed = dots(NoL, NoV, phi)["NoLsigned"]
    return np.maximum(signed * multiply + add, 0.0) ** power * _INV_PI


def diffuse_oren_nayar(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, roughness: ArrayLike, albedo: float = 1.0
) -> np.ndarray:
    """Oren and Nayar's full model (1994, eqs. 30 and 39) for a V-cavity surface whose facet
    slopes have standard deviation σ = roughness (radians): the direct term with its three
    coefficients and the interreflection term, times N·L."""
    d = dots(NoL, NoV, phi)
    nol, nov = d["NoL"], d["NoV"]
    s2 = np.asarray(roughness, np.float64) ** 2
    theta_i, theta_r = np.arccos(np.clip(nol, 0, 1)), np.arccos(np.clip(nov, 0, 1))
    alpha, beta = np.maximum(theta_i, theta_r), np.minimum(theta_i, theta_r)
    cp = cos_phi(nol, nov, d["LoV"])
    c1 = 1.0 - 0.5 * s2 / (s2 + 0.33)
    c2 = (
        0.45
        * s2
        / (s2 + 0.09)
        * np.where(cp >= 0, np.sin(alpha), np.sin(alpha) - (2 * beta / np.pi) ** 3)
    )
    c3 = 0.125 * s2 / (s2 + 0.09) * (4 * alpha * beta / np.pi**2) ** 2
    with np.errstate(over="ignore", invalid="ignore"):
        tan_beta = np.tan(beta)
        tan_mid = np.tan(0.5 * (alpha + beta))
    direct = c1 + cp * c2 * tan_beta + (1 - np.abs(cp)) * c3 * tan_mid
    bounce = 0.17 * albedo * s2 / (s2 + 0.13) * (1 - cp * (2 * beta / np.pi) ** 2)
    value = albedo * _INV_PI * (direct + bounce) * nol
    # At N·L = 0 the factor N·L wins over tan β's growth (β ≤ θr < π/2 there).
    return np.where(nol > 0, value, 0.0)


def diffuse_burley(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, roughness: ArrayLike
) -> np.ndarray:
    """Burley's Disney diffuse (2012): 1/π (1 + (F90 − 1)(1 − N·L)⁵)(1 + (F90 − 1)(1 − N·V)⁵)
    with F90 = 0.5 + 2 roughness (L·H)², times N·L."""
    d = dots(NoL, NoV, phi)
    f90 = 0.5 + 2.0 * np.asarray(roughness, np.float64) * d["VoH"] ** 2
    light = 1.0 + (f90 - 1.0) * (1.0 - d["NoL"]) ** 5
    view = 1.0 + (f90 - 1.0) * (1.0 - d["NoV"]) ** 5
    return light * view * _INV_PI * d["NoL"]


def _smoothstep(edge0: float, edge1: float, x: np.ndarray) -> np.ndarray:
    t = np.clip((x - edge0) / (edge1 - edge0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def diffuse_toon(
    *,
    NoL: ArrayLike,
    NoV: ArrayLike,
    phi: ArrayLike,
    bands: float = 3.0,
    softness: float = 0.1,
    rim: float = 0.5,
    rim_edge: float = 0.6,
    rim_power: float = 0.3,
    **_: ArrayLike,
) -> np.ndarray:
    """Toon shading as diffuse.toon defines it (a stylised model is its own reference): N·L as
    a staircase of `bands` steps with smoothstep risers, plus a rim (1 − N·V)(N·L)^p passed
    through a narrow smoothstep at `rim_edge`; all over π."""
    d = dots(NoL, NoV, phi)
    scaled = np.clip(d["NoLsigned"], 0.0, 1.0) * bands
    level = np.floor(scaled)
    lit = (level + _smoothstep(1.0 - softness, 1.0, scaled - level)) / bands
    edge = (1.0 - d["NoV"]) * np.maximum(d["NoL"], 1e-6) ** rim_power
    glow = _smoothstep(rim_edge - 0.01, rim_edge + 0.01, edge) * rim
    return (lit + glow) * _INV_PI


REFERENCES = {
    "diffuse_lambert": diffuse_lambert,
    "diffuse_lambert_unnormalized": diffuse_lambert_unnormalized,
    "diffuse_half_lambert": diffuse_half_lambert,
    "diffuse_wrapped": diffuse_wrapped,
    "diffuse_generalized": diffuse_generalized,
    "diffuse_oren_nayar": diffuse_oren_nayar,
    "diffuse_burley": diffuse_burley,
    "diffuse_toon": diffuse_toon,
}
