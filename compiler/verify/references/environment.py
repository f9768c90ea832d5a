"""Float64 references for environment lighting (slots irradiance and ibl).

- `irradiance_over_pi`: the cosine-weighted irradiance of an environment, over π,
  E(n)/π = (1/π) ∫ L(ω) max(n·ω, 0) dω, by Gauss quadrature on the hemisphere around each n.
  A Lambert surface of albedo ρ under that environment reflects ρ·E(n)/π.
- `dfg_split_sum`: the directional albedo of the GGX specular BRDF split into a scale and a
  bias of f0 (Karis 2013, "Real Shading in Unreal Engine 4", the split-sum approximation):
  ∫ f(l, v) (n·l) dl = f0·A + B when F is Schlick's, A = ∫ (1 − Fc) f/F (n·l), B = ∫ Fc f/F (n·l),
  Fc = (1 − v·h)⁵, with GGX D and the height-correlated Smith visibility.

- `specular_visible_fraction`: the share of the GGX specular lobe's reflected light (F = 1)
  that arrives from inside a visibility cone around n whose cosine-weighted visibility is the
  ambient occlusion, ao = sin²θv (Jimenez et al. 2016, "Practical Real-Time Strategies for
  Accurate Indirect Occlusion"): what specular occlusion from AO approximates.

The registry entry `irradiance_gradient` is the irradiance of `env.gradient` (the vertical
gradient from ENV_BOTTOM to ENV_TOP), taking the normal as `n0, n1, n2` like the probes do and
the environment's colours by their parameter names.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

import numpy as np
from numpy.typing import ArrayLike

from glint.compiler.verify.references.visibility import V_smith_ggx_correlated

Environment = Callable[[np.ndarray], np.ndarray]  # unit directions (..., 3) -> radiance (..., 3)

# env.gradient's defaults; tests/references/test_environment.py holds them equal to the snippet's.
ENV_TOP = (0.5, 0.7, 1.0)
ENV_BOTTOM = (0.8, 0.85, 0.9)


def gradient_environment(top: ArrayLike = ENV_TOP, bottom: ArrayLike = ENV_BOTTOM) -> Environment:
    """env.gradient in numpy: mix(bottom, top, clamp(0.5 + 0.5 y, 0, 1))."""
    top_ = np.asarray(top, np.float64)
    bottom_ = np.asarray(bottom, np.float64)

    def radiance(dirs: np.ndarray) -> np.ndarray:
        t = np.clip(0.5 + 0.5 * dirs[..., 1:2], 0.0, 1.0)
        return bottom_ + (top_ - bottom_) * t

    return radiance


def unit(n0: ArrayLike, n1: ArrayLike, n2: ArrayLike) -> np.ndarray:
    """Stack three components into unit vectors (..., 3)."""
    n = np.stack(np.broadcast_arrays(*(np.asarray(c, np.float64) for c in (n0, n1, n2))), -1)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def tangent_frame(n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors orthogonal to each unit n and to each other (Duff et al. 2017)."""
    sign = np.where(n[..., 2] >= 0.0, 1.0, -1.0)
    a = -1.0 / (sign + n[..., 2])
    b = n[..., 0] * n[..., 1] * a
    t = np.stack([1.0 + sign * n[..., 0] ** 2 * a, sign * b, -sign * n[..., 0]], -1)
    s = np.stack([b, sign + n[..., 1] ** 2 * a, -n[..., 1]], -1)
    return t, s


@cache
def _hemisphere_rule(n_mu: int, n_phi: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Nodes (μ = cosθ, φ) and weights of ∫∫ g(μ, φ) μ dμ dφ over the hemisphere: Gauss-Legendre
    in μ on [0, 1] and the trapezoid rule in φ, which is spectrally accurate for periodic g."""
    x, w = np.polynomial.legendre.leggauss(n_mu)
    mu = 0.5 * (x + 1.0)
    phi = (np.arange(n_phi) + 0.5) * (2.0 * np.pi / n_phi)
    weights = (0.5 * w * mu)[:, None] * np.full(n_phi, 2.0 * np.pi / n_phi)[None, :]
    return mu, phi, weights.ravel()


def irradiance_over_pi(
    env: Environment, normals: np.ndarray, n_mu: int = 24, n_phi: int = 48, chunk: int = 2048
) -> np.ndarray:
    """E(n)/π for unit normals (..., 3) under `env`, by a product rule on each normal's own
    hemisphere, so the kink of max(n·ω, 0) lies on the edge of the domain and the rule converges
    fast for smooth environments (a sharp sun needs its own treatment: see spherical_harmonics)."""
    normals = np.asarray(normals, np.float64)
    flat = normals.reshape(-1, 3)
    mu, phi, weights = _hemisphere_rule(n_mu, n_phi)
    sin = np.sqrt(1.0 - mu * mu)
    local = np.stack(
        [
            (sin[:, None] * np.cos(phi)[None, :]).ravel(),
            (sin[:, None] * np.sin(phi)[None, :]).ravel(),
            np.repeat(mu, len(phi)),
        ],
        -1,
    )
    out = np.empty_like(flat)
    for start in range(0, len(flat), chunk):
        n = flat[start : start + chunk]
        t, s = tangent_frame(n)
        dirs = (
            local[None, :, 0:1] * t[:, None, :]
            + local[None, :, 1:2] * s[:, None, :]
            + local[None, :, 2:3] * n[:, None, :]
        )
        out[start : start + chunk] = np.einsum("nkc,k->nc", env(dirs), weights) / np.pi
    return out.reshape(normals.shape)


def irradiance_gradient(
    *,
    n0: ArrayLike,
    n1: ArrayLike,
    n2: ArrayLike,
    ENV_TOP: ArrayLike = ENV_TOP,  # noqa: N803 - named like the snippet's parameter
    ENV_BOTTOM: ArrayLike = ENV_BOTTOM,  # noqa: N803
) -> np.ndarray:
    """E(n)/π of env.gradient by quadrature, for the normal normalize(n0, n1, n2): (..., 3)."""
    return irradiance_over_pi(gradient_environment(ENV_TOP, ENV_BOTTOM), unit(n0, n1, n2))


@cache
def _dfg_rule(n_xi: int, n_phi: int) -> tuple[np.ndarray, ...]:
    x, w = np.polynomial.legendre.leggauss(n_xi)
    y, v = np.polynomial.legendre.leggauss(n_phi)
    return 0.5 * (x + 1.0), 0.5 * w, 0.5 * (y + 1.0), 0.5 * v


def dfg_split_sum(
    roughness: ArrayLike, NoV: ArrayLike, n_xi: int = 96, n_phi: int = 48
) -> np.ndarray:
    """(A, B), shape (..., 2), of the split sum for perceptual roughness and N·V.

    The half vector is sampled through GGX's own inverse CDF, cos²θh = (1 − ξ)/(1 + (a² − 1)ξ),
    which turns D(h)(n·h) dωh into dξ dφ/2π (Walter et al. 2007, eq. 35) and keeps lobes as
    narrow as a = 0 resolved. With l the mirror of v about h, dωl = 4 (v·h) dωh, so

        ∫ f (n·l) dωl = ∫₀¹ dξ ∫ dφ/2π · F · V · 4 (n·l)(v·h) / (n·h).

    For each θh, n·l > 0 holds for |φ| below a bound found in closed form, so φ is integrated
    by Gauss-Legendre on exactly that arc (the integrand is smooth there) and doubled.
    """
    r, nv = np.broadcast_arrays(np.asarray(roughness, np.float64), np.asarray(NoV, np.float64))
    weight, body, nol, voh, *_ = _lobe(r * r, nv, n_xi, n_phi)
    fc = (1.0 - voh) ** 5
    scale = np.sum(weight * body * (1.0 - fc), axis=(-2, -1))
    bias = np.sum(weight * body * fc, axis=(-2, -1))
    return np.stack([scale, bias], -1)


def _lobe(a: np.ndarray, nv: np.ndarray, n_xi: int, n_phi: int) -> tuple[np.ndarray, ...]:
    """The quadrature of dfg_split_sum over the GGX lobe of roughness² `a` seen at N·V `nv`:
    each point's weight, the integrand without F (V · 4 (n·l)(v·h) / (n·h)), its n·l, its v·h,
    and the half vector's cos θh, sin θh and φ (from v's azimuth; the point stands for ±φ);
    shape (..., n_xi, n_phi)."""
    a = np.asarray(a, np.float64)[..., None, None]
    nv = np.clip(np.asarray(nv, np.float64), 0.0, 1.0)[..., None, None]
    sv = np.sqrt(1.0 - nv * nv)
    xi, w_xi, u, w_u = _dfg_rule(n_xi, n_phi)
    # No half vector beyond θh = (θv + π/2)/2 reflects v above the horizon: ξ stops at the
    # matching ξ*, so the integrand has no kink inside the interval.
    c2 = np.cos(0.5 * (np.arccos(nv) + 0.5 * np.pi)) ** 2
    xi_max = (1.0 - c2) / (1.0 + (a * a - 1.0) * c2)
    xi = xi_max * xi[:, None]
    w_xi = xi_max * w_xi[:, None]
    cos2h = (1.0 - xi) / (1.0 + (a * a - 1.0) * xi)
    ch = np.sqrt(cos2h)
    sh = np.sqrt(np.maximum(1.0 - cos2h, 0.0))
    # n·l = 2 (v·h)(n·h) − n·v with v·h = sv sh cosφ + nv ch: positive iff cosφ > bound.
    with np.errstate(divide="ignore", invalid="ignore"):
        bound = (nv / (2.0 * ch) - nv * ch) / (sv * sh)
    bound = np.where(np.isnan(bound), -1.0, bound)
    phi_max = np.arccos(np.clip(bound, -1.0, 1.0))
    phi = phi_max * u[None, :]
    voh = sv * sh * np.cos(phi) + nv * ch
    nol = np.maximum(2.0 * voh * ch - nv, 0.0)
    vis = V_smith_ggx_correlated(NoL=nol, NoV=nv, a=a)
    with np.errstate(invalid="ignore"):
        body = np.where(nol > 0.0, vis * 4.0 * nol * voh / ch, 0.0)
    # ∫ dφ/2π over (−φmax, φmax) = (φmax/π) Σ w_u (…); then Σ over ξ.
    weight = (phi_max / np.pi) * w_u[None, :] * w_xi
    return weight, body, nol, voh, ch, sh, phi


def specular_visible_fraction(
    *, NoV: ArrayLike, ao: ArrayLike, a: ArrayLike, n_xi: int = 128, n_phi: int = 64
) -> np.ndarray:
    """The share of the GGX lobe (roughness² `a`, F = 1, height-correlated Smith) seen at N·V
    that comes from within the visibility cone about n of half-angle θv, cos θv = √(1 − ao);
    1 where the lobe reflects nothing. In chunks: each sample integrates n_xi × n_phi points."""
    nv, occlusion, alpha = np.broadcast_arrays(*(np.asarray(x, np.float64) for x in (NoV, ao, a)))
    flat = [x.ravel() for x in (nv, occlusion, alpha)]
    out = np.empty(flat[0].shape)
    for start in range(0, len(out), 256):
        part = slice(start, start + 256)
        weight, body, nol, *_ = _lobe(flat[2][part], flat[0][part], n_xi, n_phi)
        cos_v = np.sqrt(np.clip(1.0 - flat[1][part], 0.0, 1.0))[:, None, None]
        total = np.sum(weight * body, axis=(-2, -1))
        seen = np.sum(weight * body * (nol > cos_v), axis=(-2, -1))  # ao = 0: none seen
        with np.errstate(divide="ignore", invalid="ignore"):
            out[part] = np.where(total > 0.0, seen / total, 1.0)
    return out.reshape(nv.shape)


def specular_environment(
    n: np.ndarray,
    v: np.ndarray,
    roughness: ArrayLike,
    f0: float = 0.04,
    environment: Environment | None = None,
    n_xi: int = 64,
    n_phi: int = 32,
) -> np.ndarray:
    """The light the GGX specular lobe (height-correlated Smith, Schlick's F of v·h with `f0`)
    reflects toward v from an environment (env.gradient's by default): ∫ f(l, v) L(l) (n·l) dl,
    by dfg_split_sum's quadrature with each half vector placed in the frame of n and v, both
    signs of φ. `n` and `v` are unit vectors (..., 3) with n·v > 0; returns RGB (..., 3)."""
    env = environment or gradient_environment()
    n, v = np.broadcast_arrays(np.asarray(n, np.float64), np.asarray(v, np.float64))
    r = np.broadcast_to(np.asarray(roughness, np.float64), n.shape[:-1])
    flat_n, flat_v, flat_r = n.reshape(-1, 3), v.reshape(-1, 3), r.ravel()
    out = np.empty(flat_n.shape)
    for start in range(0, len(out), 128):
        part = slice(start, start + 128)
        out[part] = _reflected(flat_n[part], flat_v[part], flat_r[part], f0, env, n_xi, n_phi)
    return out.reshape(n.shape)


def _reflected(
    n: np.ndarray,
    v: np.ndarray,
    r: np.ndarray,
    f0: float,
    env: Environment,
    n_xi: int,
    n_phi: int,
) -> np.ndarray:
    nv = np.clip(np.sum(n * v, axis=-1), 0.0, 1.0)
    # t: v's direction in the tangent plane (any tangent where v is along n), b completes it
    t = v - nv[:, None] * n
    length = np.linalg.norm(t, axis=-1, keepdims=True)
    t = np.where(length > 1e-12, t / np.maximum(length, 1e-300), tangent_frame(n)[0])
    b = np.cross(n, t)
    weight, body, _, voh, ch, sh, phi = _lobe(r * r, nv, n_xi, n_phi)
    fresnel = f0 + (1.0 - f0) * (1.0 - voh) ** 5
    total = np.zeros(n.shape)
    for sign in (1.0, -1.0):
        h = (
            (sh * np.cos(phi))[..., None] * t[:, None, None, :]
            + (sign * sh * np.sin(phi))[..., None] * b[:, None, None, :]
            + ch[..., None] * n[:, None, None, :]
        )
        light = 2.0 * voh[..., None] * h - v[:, None, None, :]
        light /= np.linalg.norm(light, axis=-1, keepdims=True)
        radiance = env(light)
        total += 0.5 * np.sum((weight * body * fresnel)[..., None] * radiance, axis=(1, 2))
    return total


REFERENCES = {
    "irradiance_gradient": irradiance_gradient,
    "specular_visible_fraction": specular_visible_fraction,
}
