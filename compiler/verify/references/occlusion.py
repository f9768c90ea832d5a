"""Ground truth for the snippets that query the scene: soft and hard shadows, ambient occlusion.

Each is estimated on a reference scene (`scenes.py`) with many rays, every ray intersected with
the scene in closed form in float64, so the only error is sampling, which stratification keeps
small (see `tests/verify/references/test_occlusion.py` for the measured standard error).

- Shadow: the fraction of a disc light of angular radius α that a point sees. The penumbra
  estimators of the shadow slot call the light fully visible once every miss h at distance t
  along the ray clears it by h/t ≥ 1/k: that is a disc whose rim lies at atan(1/k) from its
  centre, so tan α = 1/k. (They also draw the whole penumbra outside the hard shadow, giving 0
  where a ray grazes an occluder and the true disc is half visible; that is part of their error.)
- Hard shadow: one ray, the point light's visibility (α = 0).
- Ambient occlusion: the cosine-weighted fraction of the hemisphere around n that reaches
  `max_distance` without meeting the scene, the quantity AO stands for in the ambient term.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from glint.compiler.verify.references.scenes import scene as reference_scene

DEFAULT_SAMPLES = 256  # 16 × 16 strata per point
# Distance within which geometry occludes in the AO ground truth; see the AO tests for why.
AO_MAX_DISTANCE = 0.2


def stratified_disc(points: int, samples: int, seed: int = 0) -> np.ndarray:
    """(points, samples, 2) points of the unit disc, area-uniform: one jittered sample per
    stratum of a √samples × √samples grid, mapped by Shirley and Chiu's concentric map (which
    keeps strata compact), with fresh jitter per point."""
    side = math.isqrt(samples)
    if side * side != samples or side < 1:
        raise ValueError(f"samples must be a perfect square (16, 256, ...), got {samples}")
    rng = np.random.default_rng(seed)
    cell = np.stack(np.meshgrid(np.arange(side), np.arange(side), indexing="ij"), -1)
    uv = (cell.reshape(1, samples, 2) + rng.random((points, samples, 2))) / side
    a, b = 2.0 * uv[..., 0] - 1.0, 2.0 * uv[..., 1] - 1.0
    wide = np.abs(a) > np.abs(b)
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.where(wide, a, b)
        phi = np.where(wide, (np.pi / 4) * (b / a), np.pi / 2 - (np.pi / 4) * (a / b))
    phi = np.nan_to_num(phi)
    return np.stack([r * np.cos(phi), r * np.sin(phi)], -1)


def orthonormal_basis(axis: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors completing unit `axis` (..., 3) to a basis, without a branch on a
    reference vector (Duff et al., "Building an orthonormal basis, revisited", 2017)."""
    x, y, z = axis[..., 0], axis[..., 1], axis[..., 2]
    sign = np.where(z >= 0.0, 1.0, -1.0)
    a = -1.0 / (sign + z)
    b = x * y * a
    t = np.stack([1.0 + sign * x * x * a, sign * b, -sign * x], -1)
    u = np.stack([b, sign + y * y * a, -y], -1)
    return t, u


def _unit(v: ArrayLike) -> np.ndarray:
    v = np.asarray(v, np.float64)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _around(axis: np.ndarray, disc: np.ndarray, cos_theta: np.ndarray, sin_over_r: np.ndarray):
    t, u = orthonormal_basis(axis)
    x, y = disc[..., 0:1] * sin_over_r, disc[..., 1:2] * sin_over_r
    return x * t[:, None] + y * u[:, None] + cos_theta * axis[:, None]


def cone_directions(axis: ArrayLike, half_angle: float, samples: int, seed: int = 0):
    """(points, samples, 3) unit directions uniform in solid angle within `half_angle` of each
    unit `axis`: a disc radius r maps to 1 − cos θ = r² (1 − cos α)."""
    axis = _unit(axis)
    disc = stratified_disc(len(axis), samples, seed)
    r2 = np.sum(disc * disc, -1, keepdims=True)
    cos_theta = 1.0 - r2 * (1.0 - math.cos(half_angle))
    sin_theta = np.sqrt(np.maximum(1.0 - cos_theta * cos_theta, 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        sin_over_r = np.where(r2 > 0.0, sin_theta / np.sqrt(r2), 0.0)
    return _around(axis, disc, cos_theta, sin_over_r)


def cosine_directions(normal: ArrayLike, samples: int, seed: int = 0) -> np.ndarray:
    """(points, samples, 3) unit directions with density cos θ / π about each unit `normal`
    (Malley's method: the disc lifted onto the hemisphere)."""
    normal = _unit(normal)
    disc = stratified_disc(len(normal), samples, seed)
    r2 = np.sum(disc * disc, -1, keepdims=True)
    return _around(normal, disc, np.sqrt(np.maximum(1.0 - r2, 0.0)), np.ones_like(r2))


def shadow_disc_light(
    *,
    scene: str,
    ro: ArrayLike,
    rd: ArrayLike,
    k: float,
    tmax: float = np.inf,
    samples: int = DEFAULT_SAMPLES,
    seed: int = 0,
) -> np.ndarray:
    """Visible fraction of a disc light of angular radius atan(1/k) centred on unit `rd`, seen
    from each point `ro` (N, 3) of the named reference scene; occluders beyond `tmax` ignored."""
    if k <= 0.0:
        raise ValueError(f"k must be positive, got {k}")
    ro = np.asarray(ro, np.float64).reshape(-1, 3)
    dirs = cone_directions(
        np.asarray(rd, np.float64).reshape(-1, 3), math.atan(1.0 / k), samples, seed
    )
    blocked = reference_scene(scene).blocked(ro[:, None, :], dirs, tmax)
    return 1.0 - blocked.mean(axis=1)


def shadow_ray(*, scene: str, ro: ArrayLike, rd: ArrayLike, tmax: float = np.inf) -> np.ndarray:
    """1 where the ray from `ro` along unit `rd` leaves the scene (up to `tmax`), else 0."""
    ro = np.asarray(ro, np.float64).reshape(-1, 3)
    rd = _unit(np.asarray(rd, np.float64).reshape(-1, 3))
    return 1.0 - reference_scene(scene).blocked(ro, rd, tmax).astype(np.float64)


def ao_cosine_visibility(
    *,
    scene: str,
    p: ArrayLike,
    n: ArrayLike,
    max_distance: float = AO_MAX_DISTANCE,
    samples: int = DEFAULT_SAMPLES,
    seed: int = 0,
) -> np.ndarray:
    """Cosine-weighted fraction of the hemisphere about unit `n` from which a ray leaving `p`
    travels `max_distance` without meeting the named reference scene."""
    if max_distance <= 0.0:
        raise ValueError(f"max_distance must be positive, got {max_distance}")
    p = np.asarray(p, np.float64).reshape(-1, 3)
    dirs = cosine_directions(np.asarray(n, np.float64).reshape(-1, 3), samples, seed)
    blocked = reference_scene(scene).blocked(p[:, None, :], dirs, max_distance)
    return 1.0 - blocked.mean(axis=1)


REFERENCES = {
    "shadow_disc_light": shadow_disc_light,
    "shadow_ray": shadow_ray,
    "ao_cosine_visibility": ao_cosine_visibility,
}
