"""The shading geometry the lobe references are written in, and the integrals the physics tests
need.

A lighting configuration is given by three numbers: `NoL` (cosine of the light's polar angle,
negative below the horizon), `NoV` (the same for the eye) and `phi` (the azimuth between the
two). In the frame N = +z, V = (sin θv, 0, cos θv) and L = (sin θl cos φ, sin θl sin φ, cos θl),
`dots` derives every dot product the GLSL `Dots` struct carries, clamped as `lightDots` clamps
them, so a reference and a GPU probe can be fed the same configuration.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike


def directions(NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Unit L and V (…, 3) in the frame with N = +z."""
    cl, cv = np.asarray(NoL, np.float64), np.asarray(NoV, np.float64)
    cl, cv, p = np.broadcast_arrays(np.clip(cl, -1, 1), np.clip(cv, -1, 1), phi)
    sl, sv = np.sqrt(1.0 - cl * cl), np.sqrt(1.0 - cv * cv)
    L = np.stack([sl * np.cos(p), sl * np.sin(p), cl], axis=-1)
    V = np.stack([sv, np.zeros_like(sv), cv], axis=-1)
    return L, V


def dots(NoL: ArrayLike, NoV: ArrayLike, phi: ArrayLike) -> dict[str, np.ndarray]:
    """The `Dots` fields of a configuration: NoL, NoV, NoH, VoH, LoV and NoLsigned. When V = −L
    the half vector is undefined; like `lightDots`, take H = 0 there (NoH = VoH = 0)."""
    L, V = directions(NoL, NoV, phi)
    H = L + V
    length = np.linalg.norm(H, axis=-1, keepdims=True)
    H = np.divide(H, length, out=np.zeros_like(H), where=length > 1e-12)
    signed = L[..., 2]
    return {
        "NoL": np.maximum(signed, 0.0),
        "NoV": V[..., 2],
        "NoH": np.maximum(H[..., 2], 0.0),
        "VoH": np.maximum(np.sum(V * H, axis=-1), 0.0),
        "LoV": np.sum(L * V, axis=-1),
        "NoLsigned": signed,
    }


def cos_phi(NoL: np.ndarray, NoV: np.ndarray, LoV: np.ndarray) -> np.ndarray:
    """Cosine of the azimuth between L and V, from their dot products; 0 where either lies
    along N and the azimuth is undefined (every term that uses it then vanishes)."""
    sin_l = np.sqrt(np.maximum(1.0 - NoL * NoL, 0.0))
    sin_v = np.sqrt(np.maximum(1.0 - NoV * NoV, 0.0))
    denom = sin_l * sin_v
    out = np.divide(LoV - NoL * NoV, denom, out=np.zeros_like(denom), where=denom > 1e-12)
    return np.clip(out, -1.0, 1.0)


# A lobe reference: a function of (NoL, NoV, phi, roughness) returning BRDF × cosine.
Lobe = Callable[..., np.ndarray]


def _gauss(lo: float, hi: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    x, w = np.polynomial.legendre.leggauss(n)
    return lo + (x + 1) * (hi - lo) / 2, w * (hi - lo) / 2


def directional_albedo(
    lobe: Lobe, NoV: float, roughness: float, n_theta: int = 192, n_phi: int = 192, **extra: float
) -> float:
    """∫ lobe(L, V) dω_L over the whole sphere of light directions (the lobes own their cosine,
    and wrapped models take light from below the horizon): the fraction of uniform incident
    radiance reflected toward V, for a white surface.

    Integrated over the half vector h rather than L (dω_L = 4 V·h dω_h, each L once for
    V·h > 0), because every specular lobe peaks at h = N, where the polar grid is finest:
    Gauss-Legendre in θh on [0, 0.25] and [0.25, π], midpoints in φh (symmetric about the
    plane of N and V, so [0, π] counted twice)."""
    near, w_near = _gauss(0.0, 0.25, n_theta)
    far, w_far = _gauss(0.25, np.pi, n_theta)
    theta, w_theta = np.concatenate([near, far]), np.concatenate([w_near, w_far])
    phi = (np.arange(n_phi) + 0.5) * np.pi / n_phi
    t, p = np.meshgrid(theta, phi, indexing="ij")
    h = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1)
    view = np.array([np.sqrt(max(1.0 - NoV * NoV, 0.0)), 0.0, NoV])
    voh = h @ view
    light = 2.0 * voh[..., None] * h - view
    values = lobe(
        NoL=np.clip(light[..., 2], -1.0, 1.0),
        NoV=NoV,
        phi=np.arctan2(light[..., 1], light[..., 0]),
        roughness=roughness,
        **extra,
    )
    weight = np.where(voh > 0.0, 4.0 * voh, 0.0) * np.sin(t) * w_theta[:, None]
    return float(2.0 * (np.pi / n_phi) * np.sum(np.asarray(values, np.float64) * weight))
