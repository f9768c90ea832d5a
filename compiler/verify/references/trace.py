"""Float64 references of the `trace` snippets: a ray's first hit on a sphere, a box or the
ground, and its signed angular clearance from them, found without their closed forms.

The hit comes from the exact parameter interval of the ray inside each solid (the reference
scenes' `inside`). The clearance, the signed angle between the ray and the solid's outline seen
from its origin, comes from a search over cones of rays about it: for a ray that misses, the
least angle θ at which some ray on the circle of angle θ about it meets the solid (between 0 and
the direction of the solid's centre, which lies in the solid's outline, the circle at θ meets a
convex solid exactly from the clearance on); for a ray that hits, minus the greatest θ at which
every ray on that circle still meets it. Both by bisection, CIRCLE rays per circle.
"""

from __future__ import annotations

import numpy as np

from glint.compiler.verify.references.scenes import Box, Ground, Primitive, Sphere

CIRCLE = 2048
BISECTIONS = 30


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def first_hit(prim: Primitive, ro: np.ndarray, rd: np.ndarray) -> np.ndarray:
    """t of the ray's first point in the solid (0 from inside), or -1 when it never enters."""
    t0, t1 = prim.inside(ro, rd)
    hits = (t0 <= t1) & (t1 >= 0.0)
    return np.where(hits, np.maximum(t0, 0.0), -1.0)


def _meets(prim: Primitive, ro: np.ndarray, dirs: np.ndarray) -> np.ndarray:
    """Whether each ray ro (N, 3) + t·dirs (N, M, 3), t > 0, meets the solid: (N, M)."""
    t0, t1 = prim.inside(np.broadcast_to(ro[:, None, :], dirs.shape), dirs)
    return (t0 <= t1) & (t1 > 0.0)


def _circle(rd: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """CIRCLE unit directions at angle theta (N,) about each unit rd (N, 3): (N, CIRCLE, 3)."""
    side = np.where(np.abs(rd[:, 1:2]) < 0.9, [[0.0, 1.0, 0.0]], [[1.0, 0.0, 0.0]])
    u = _unit(np.cross(rd, side))
    v = np.cross(rd, u)
    phi = np.linspace(0.0, 2.0 * np.pi, CIRCLE, endpoint=False)
    ring = np.cos(phi)[None, :, None] * u[:, None, :] + np.sin(phi)[None, :, None] * v[:, None, :]
    return np.cos(theta)[:, None, None] * rd[:, None, :] + np.sin(theta)[:, None, None] * ring


def _centre(prim: Primitive, ro: np.ndarray) -> np.ndarray:
    if isinstance(prim, Ground):
        return np.broadcast_to([0.0, -1.0, 0.0], ro.shape)  # straight down lies in the half-space
    assert isinstance(prim, Sphere | Box)
    return _unit(np.asarray(prim.center) - ro)


def clearance(prim: Primitive, ro: np.ndarray, rd: np.ndarray) -> np.ndarray:
    """The signed angle (radians) between each ray and the solid's outline (see the module)."""
    ro = np.asarray(ro, np.float64).reshape(-1, 3)
    rd = _unit(np.asarray(rd, np.float64).reshape(-1, 3))
    hit = first_hit(prim, ro, rd) >= 0.0
    lo = np.zeros(len(ro))
    to_centre = np.arccos(np.clip(np.sum(rd * _centre(prim, ro), axis=-1), -1.0, 1.0))
    hi = np.where(hit, np.pi / 2, to_centre)
    for _ in range(BISECTIONS):
        mid = 0.5 * (lo + hi)
        meets = _meets(prim, ro, _circle(rd, mid))
        # a hit: still inside while the whole circle meets it; a miss: there once any ray does
        beyond = np.where(hit, ~meets.all(axis=1), meets.any(axis=1))
        hi = np.where(beyond, mid, hi)
        lo = np.where(beyond, lo, mid)
    angle = 0.5 * (lo + hi)
    return np.where(hit, -angle, angle)
