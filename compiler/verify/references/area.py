"""Float64 reference for area lights (slot area): the light a sphere, disc or rectangle of
uniform radiance sends to the eye off a surface, integrated over the light.

The surface is the balanced tier's BRDF (GGX, height-correlated Smith, Schlick's Fresnel, and
Lambert weighted by 1 − F(v·h)), white (albedo 1, f0 = DIELECTRIC_F0) with its normal on +z:
any case is one of these, turned. The light is given as areaLight takes it: `center`,
`right`, `up` (right × up is the way a disc or rectangle shines; a sphere's radius is
|right|), `shape` (0 sphere, 1 disc, 2 rectangle), radiance 1.

The integral is taken two ways at once and the two combined by the balance heuristic (Veach
& Guibas 1995, multiple importance sampling): a midpoint rule over the light (a sphere's cone
of directions by solid angle, a disc's or rectangle's surface by area), which resolves the
diffuse and broad lobes, and a midpoint rule over the GGX lobe (half vectors through GGX's
inverse CDF, each reflected and kept where it meets the light), which resolves the sharp
highlight of a glossy surface seen at a grazing angle, where samples over the light miss it.
Each direction counts f / (n² (p_light + p_lobe)), p the density of each rule at it.
"""

from __future__ import annotations

import numpy as np

from glint.compiler.verify.references.distribution import D_ggx
from glint.compiler.verify.references.visibility import V_smith_ggx_correlated

DIELECTRIC_F0 = 0.04
MIN_NOV = 1e-4  # as core.surface's
# Samples per side of each rule: within 1 % (0.0043) of 512's at the worst of the bench cases.
GRID = 256
SPHERE, DISC, RECT = 0, 1, 2


def _directions(
    center: np.ndarray, right: np.ndarray, up: np.ndarray, shape: int, n: int
) -> tuple[np.ndarray, np.ndarray]:
    """Unit directions from the origin toward the light's samples, (n², 3), and the weight of
    each (its solid angle)."""
    u = (np.arange(n) + 0.5) / n
    uu, vv = (x.ravel() for x in np.meshgrid(u, u, indexing="ij"))
    dist2 = center @ center
    if shape == SPHERE:
        r2 = right @ right
        cos_max = np.sqrt(max(1.0 - r2 / dist2, 0.0))
        axis = center / np.sqrt(dist2)
        helper = np.array([0.0, 1.0, 0.0]) if abs(axis[1]) < 0.99 else np.array([1.0, 0.0, 0.0])
        t1 = np.cross(axis, helper)
        t1 /= np.linalg.norm(t1)
        t2 = np.cross(axis, t1)
        cos_t = 1.0 - uu * (1.0 - cos_max)
        sin_t = np.sqrt(np.maximum(1.0 - cos_t * cos_t, 0.0))
        phi = 2.0 * np.pi * vv
        dirs = (
            cos_t[:, None] * axis
            + (sin_t * np.cos(phi))[:, None] * t1
            + (sin_t * np.sin(phi))[:, None] * t2
        )
        omega = 2.0 * np.pi * (1.0 - cos_max)
        return dirs, np.full(len(dirs), omega / (n * n))
    if shape == DISC:
        radius = np.sqrt(uu)
        q = np.stack([radius * np.cos(2 * np.pi * vv), radius * np.sin(2 * np.pi * vv)], axis=1)
        area = np.pi * (right @ right)
    else:
        q = np.stack([2 * uu - 1, 2 * vv - 1], axis=1)
        area = 4.0 * np.linalg.norm(right) * np.linalg.norm(up)
    points = center + q[:, :1] * right + q[:, 1:] * up
    d2 = np.sum(points * points, axis=1)
    dirs = points / np.sqrt(d2)[:, None]
    facing = np.cross(right, up)
    facing /= np.linalg.norm(facing)
    cos_light = np.maximum(-(dirs @ facing), 0.0)
    return dirs, area * cos_light / d2 / (n * n)


def _hits(
    dirs: np.ndarray, center: np.ndarray, right: np.ndarray, up: np.ndarray, shape: int
) -> tuple[np.ndarray, np.ndarray]:
    """Whether each direction from the origin meets the light's lit side, and the density (per
    solid angle) of the light rule at it (0 where it misses)."""
    if shape == SPHERE:
        r2 = right @ right
        b = dirs @ center
        hit = (b > 0.0) & (b * b - (center @ center - r2) >= 0.0)
        cos_max = np.sqrt(max(1.0 - r2 / (center @ center), 0.0))
        return hit, np.where(hit, 1.0 / (2.0 * np.pi * (1.0 - cos_max)), 0.0)
    facing = np.cross(right, up)
    facing /= np.linalg.norm(facing)
    across = dirs @ facing
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (center @ facing) / across
    q = t[:, None] * dirs - center
    if shape == DISC:
        inside = np.sum(q * q, axis=1) <= right @ right
        area = np.pi * (right @ right)
    else:
        half_w, half_h = np.linalg.norm(right), np.linalg.norm(up)
        inside = (np.abs(q @ (right / half_w)) <= half_w) & (np.abs(q @ (up / half_h)) <= half_h)
        area = 4.0 * half_w * half_h
    hit = (across < 0.0) & (t > 0.0) & inside
    with np.errstate(divide="ignore", invalid="ignore"):
        density = np.where(hit, t * t / (area * np.abs(across)), 0.0)
    return hit, density


def _lobe_directions(v: np.ndarray, roughness: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Directions l reflected about GGX half vectors on an n × n midpoint grid of (ξ1, ξ2), and
    the density of that rule per solid angle of l: D(h)(n·h) / (4 v·h)."""
    a = max(roughness * roughness, 1e-6)
    u = (np.arange(n) + 0.5) / n
    x1, x2 = (x.ravel() for x in np.meshgrid(u, u, indexing="ij"))
    cos2 = (1.0 - x1) / (1.0 + (a * a - 1.0) * x1)
    cos_h, sin_h = np.sqrt(cos2), np.sqrt(1.0 - cos2)
    phi = 2.0 * np.pi * x2
    h = np.stack([sin_h * np.cos(phi), sin_h * np.sin(phi), cos_h], axis=1)
    vh = h @ v
    dirs = 2.0 * vh[:, None] * h - v
    with np.errstate(divide="ignore", invalid="ignore"):
        density = D_ggx(NoH=cos_h, a=a) * cos_h / (4.0 * np.abs(vh))
    return dirs, np.where(vh > 0.0, density, 0.0)


def _lobe_density(dirs: np.ndarray, v: np.ndarray, roughness: float) -> np.ndarray:
    """The density per solid angle at which _lobe_directions reaches each direction l."""
    a = max(roughness * roughness, 1e-6)
    h = dirs + v
    h /= np.maximum(np.linalg.norm(h, axis=1, keepdims=True), 1e-300)
    cos_h = np.maximum(h[:, 2], 0.0)
    vh = h @ v
    with np.errstate(divide="ignore", invalid="ignore"):
        density = D_ggx(NoH=cos_h, a=a) * cos_h / (4.0 * np.abs(vh))
    return np.where(vh > 0.0, density, 0.0)


def _response(to_light: np.ndarray, v: np.ndarray, roughness: float) -> np.ndarray:
    """(1 − F) ρ/π (n·l) + D V F (n·l) for a white dielectric with n = +z, per direction l."""
    nl = to_light[:, 2]
    nv = max(v[2], MIN_NOV)
    h = to_light + v
    h /= np.maximum(np.linalg.norm(h, axis=1, keepdims=True), 1e-300)
    nh = np.maximum(h[:, 2], 0.0)
    vh = np.maximum(h @ v, 0.0)
    fresnel = DIELECTRIC_F0 + (1.0 - DIELECTRIC_F0) * (1.0 - vh) ** 5
    a = roughness * roughness
    lit = nl > 0.0
    nl = np.maximum(nl, 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        lobe = D_ggx(NoH=nh, a=a) * V_smith_ggx_correlated(NoL=nl, NoV=nv, a=a) * fresnel * nl
    value = (1.0 - fresnel) * nl / np.pi + np.where(lit, lobe, 0.0)
    return np.where(lit, value, 0.0)


def area_light(
    *,
    v: np.ndarray,
    roughness: np.ndarray,
    center: np.ndarray,
    right: np.ndarray,
    up: np.ndarray,
    shape: np.ndarray,
    grid: int = GRID,
) -> np.ndarray:
    """Outgoing radiance per unit light radiance, one per case (arrays of cases: v, center,
    right, up (k, 3); roughness, shape (k,)). A disc or rectangle seen from behind gives 0."""
    out = np.zeros(len(roughness))
    for k in range(len(roughness)):
        c, r, u = (np.asarray(x[k], np.float64) for x in (center, right, up))
        kind = int(shape[k])
        if kind != SPHERE and np.cross(r, u) @ (-c) <= 0.0:
            continue  # behind its lit face
        dirs, weights = _directions(c, r, u, kind, grid)
        out[k] = np.sum(
            _response(dirs, np.asarray(v[k], np.float64), float(roughness[k])) * weights
        )
    return out


REFERENCES = {"area_light": area_light}
