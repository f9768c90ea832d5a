"""Float64 references for the empirical specular lobes (slot specular), for F = 1.

Each takes the shading geometry (`NoL` signed, `NoV`, `phi`, see `geometry`) and the perceptual
`roughness`, and returns what `specular(s, d, F)` returns with F = vec3(1): BRDF × cosine where
the model has one. The shininess follows D.blinn_phong: n = 2/a² − 2 with a = roughness²
(Walter et al. 2007), a floored at `MIN_A`; Phong's lobe around R is about four times wider in
angle than Blinn-Phong's around N for the same exponent, so Phong takes n/4 (Fisher and Woo
1994). The Cook-Torrance lobe is checked through its D, F and V terms.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from glint.compiler.verify.references.distribution import D_ggx, blinn_phong_exponent
from glint.compiler.verify.references.geometry import dots
from glint.compiler.verify.references.visibility import V_smith_ggx_correlated

MIN_A = 1e-3  # as MIN_BLINN_PHONG_A in the GLSL


def shininess(roughness: ArrayLike) -> np.ndarray:
    return blinn_phong_exponent(np.maximum(np.asarray(roughness, np.float64) ** 2, MIN_A))


def _pow(base: np.ndarray, n: np.ndarray) -> np.ndarray:
    """base^n for base in [0, 1], with 0^0 = 1 (the uniform lobe at roughness 1)."""
    base, n = np.broadcast_arrays(np.clip(base, 0.0, 1.0), n)
    with np.errstate(divide="ignore"):
        return np.where(base > 0.0, base**n, np.where(n > 0.0, 0.0, 1.0))


def specular_phong(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, roughness: ArrayLike
) -> np.ndarray:
    """Classic Phong, (R·V)^(n/4) with R the mirror of L about N, unnormalised and without a
    cosine factor, as it was written; zero when the light is below the horizon."""
    d = dots(NoL, NoV, phi)
    r_dot_v = 2.0 * d["NoLsigned"] * d["NoV"] - d["LoV"]
    return np.where(d["NoLsigned"] > 0.0, _pow(r_dot_v, shininess(roughness) / 4.0), 0.0)


def specular_blinn_phong(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, roughness: ArrayLike
) -> np.ndarray:
    """Unnormalised Blinn-Phong, (N·H)^n, without a cosine factor; zero below the horizon."""
    d = dots(NoL, NoV, phi)
    return np.where(d["NoLsigned"] > 0.0, _pow(d["NoH"], shininess(roughness)), 0.0)


def specular_blinn_phong_normalized(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, roughness: ArrayLike
) -> np.ndarray:
    """Normalised Blinn-Phong BRDF, (n + 8)/(8π) (N·H)^n, times N·L (Akenine-Möller et al.,
    Real-Time Rendering): bright and sharp for low roughness, energy-conserving only roughly."""
    d = dots(NoL, NoV, phi)
    n = shininess(roughness)
    return (n + 8.0) / (8.0 * np.pi) * _pow(d["NoH"], n) * d["NoL"]


def specular_cook_torrance_ggx(
    *, NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike, roughness: ArrayLike
) -> np.ndarray:
    """D_GGX · V_Smith-GGX-correlated · N·L with F = 1: the balanced tier's Cook-Torrance lobe,
    for the energy tests (the GLSL lobe is checked through its terms)."""
    d = dots(NoL, NoV, phi)
    a = np.asarray(roughness, np.float64) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        value = D_ggx(NoH=d["NoH"], a=a) * V_smith_ggx_correlated(**d, a=a) * d["NoL"]
    return np.where(d["NoL"] > 0.0, value, 0.0)


REFERENCES = {
    "specular_phong": specular_phong,
    "specular_blinn_phong": specular_blinn_phong,
    "specular_blinn_phong_normalized": specular_blinn_phong_normalized,
    "specular_cook_torrance_ggx": specular_cook_torrance_ggx,
}
