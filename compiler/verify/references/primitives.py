"""Float64 signed distances and outward normals of the `sdf` slot's primitives.

Each exact distance here is computed from the shape's closest point, not from the GLSL's
closed form, so that a slip in a snippet shows up as a difference: the torus from the nearest
point of its ring circle, the capsule from the nearest point of its axis segment, the cylinder
and the cone from the 2D distance to their profile polygon in the (radial, height) half-plane,
the round box from the nearest point of its inner box. The normal is the direction from that
closest point (the gradient of the field), which is what a normal variant should estimate.

The ellipsoid snippet is only a bound, so its reference is the true distance, found from the
Lagrange condition for the closest point by bisection in float64; the test checks the bound
never exceeds it.

Every function takes points `p` (N, 3) and the shape's parameters by keyword, named as the
GLSL parameters are.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike


def _points(p: ArrayLike) -> np.ndarray:
    return np.atleast_2d(np.asarray(p, np.float64))


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _radial(p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The distance from the y axis and the unit direction away from it in the xz plane
    (+x on the axis itself, where every direction is as good)."""
    rho = np.hypot(p[:, 0], p[:, 2])
    safe = np.where(rho > 0.0, rho, 1.0)
    away = np.stack([p[:, 0] / safe, np.zeros_like(rho), p[:, 2] / safe], axis=-1)
    away[rho == 0.0] = (1.0, 0.0, 0.0)
    return rho, away


# --- torus and capsule: distance to a curve (ring circle, axis segment) minus a radius -------


def _ring_point(p: np.ndarray, major: float) -> np.ndarray:
    return major * _radial(p)[1]


def torus_distance(*, p: ArrayLike, major: float, minor: float) -> np.ndarray:
    p = _points(p)
    return np.linalg.norm(p - _ring_point(p, major), axis=-1) - minor


def torus_normal(*, p: ArrayLike, major: float, minor: float) -> np.ndarray:
    p = _points(p)
    return _unit(p - _ring_point(p, major))


def _axis_point(p: np.ndarray, half_length: float) -> np.ndarray:
    nearest = np.zeros_like(p)
    nearest[:, 1] = np.clip(p[:, 1], -half_length, half_length)
    return nearest


def capsule_distance(*, p: ArrayLike, halfLength: float, radius: float) -> np.ndarray:
    p = _points(p)
    return np.linalg.norm(p - _axis_point(p, halfLength), axis=-1) - radius


def capsule_normal(*, p: ArrayLike, halfLength: float, radius: float) -> np.ndarray:
    p = _points(p)
    return _unit(p - _axis_point(p, halfLength))


# --- solids of revolution: 2D distance to a convex profile polygon in (radial, height) -------


def _polygon_closest(q: np.ndarray, vertices: np.ndarray) -> tuple[np.ndarray, ...]:
    """For 2D points q (N, 2) and a convex polygon (counter-clockwise vertices), the signed
    distance, the closest boundary point, the outward normal of the nearest edge and whether
    that point is a vertex. Brute force over the edges: plain, as a reference should be."""
    starts, ends = vertices, np.roll(vertices, -1, axis=0)
    best = np.full(len(q), np.inf)
    closest = np.zeros_like(q)
    edge_normal = np.zeros_like(q)
    at_vertex = np.zeros(len(q), bool)
    inside = np.ones(len(q), bool)
    for a, b in zip(starts, ends, strict=True):
        edge = b - a
        length2 = edge @ edge
        if length2 == 0.0:
            continue  # a degenerate edge (a cone's apex): its neighbours cover it
        t = np.clip(((q - a) @ edge) / length2, 0.0, 1.0)
        foot = a + t[:, None] * edge
        dist = np.linalg.norm(q - foot, axis=-1)
        outward = np.array([edge[1], -edge[0]]) / np.sqrt(length2)  # right of a CCW edge
        inside &= (q - a) @ outward < 0.0
        nearer = dist < best
        best = np.where(nearer, dist, best)
        closest[nearer] = foot[nearer]
        edge_normal[nearer] = outward
        at_vertex[nearer] = ((t <= 0.0) | (t >= 1.0))[nearer]
    return np.where(inside, -best, best), closest, edge_normal, at_vertex


def _profile_distance(p: np.ndarray, vertices: np.ndarray) -> np.ndarray:
    rho, _ = _radial(p)
    return _polygon_closest(np.stack([rho, p[:, 1]], axis=-1), vertices)[0]


def _profile_normal(p: np.ndarray, vertices: np.ndarray) -> np.ndarray:
    """Outside, nearest to a rim (a vertex of the profile): from that rim point; otherwise the
    nearest edge's outward normal (the same direction outside, and well defined on the
    surface). The 2D normal (n_radial, n_y) turns into 3D away from the axis."""
    rho, away = _radial(p)
    q = np.stack([rho, p[:, 1]], axis=-1)
    signed, closest, edge_normal, at_vertex = _polygon_closest(q, vertices)
    from_rim = (signed > 0.0) & at_vertex
    normal2 = edge_normal.copy()
    normal2[from_rim] = _unit(q[from_rim] - closest[from_rim])
    normal = normal2[:, :1] * away
    normal[:, 1] += normal2[:, 1]
    return _unit(normal)


def _cylinder_profile(radius: float, half_height: float) -> np.ndarray:
    return _cone_profile(half_height, radius, radius)


def _cone_profile(half_height: float, bottom: float, top: float) -> np.ndarray:
    """The trapezoid mirrored across the axis (so that it is convex), counter-clockwise."""
    h = half_height
    return np.array([[-bottom, -h], [bottom, -h], [top, h], [-top, h]], np.float64)


def capped_cylinder_distance(*, p: ArrayLike, radius: float, halfHeight: float) -> np.ndarray:
    return _profile_distance(_points(p), _cylinder_profile(radius, halfHeight))


def capped_cylinder_normal(*, p: ArrayLike, radius: float, halfHeight: float) -> np.ndarray:
    return _profile_normal(_points(p), _cylinder_profile(radius, halfHeight))


def capped_cone_distance(
    *,
    p: ArrayLike,
    halfHeight: float,
    bottomRadius: float,
    topRadius: float,
) -> np.ndarray:
    return _profile_distance(_points(p), _cone_profile(halfHeight, bottomRadius, topRadius))


def capped_cone_normal(
    *,
    p: ArrayLike,
    halfHeight: float,
    bottomRadius: float,
    topRadius: float,
) -> np.ndarray:
    return _profile_normal(_points(p), _cone_profile(halfHeight, bottomRadius, topRadius))


# --- round box: the inner box (shrunk by the rounding), offset outward by it -----------------


def _inner_box(p: np.ndarray, half_size: ArrayLike, rounding: float) -> tuple[np.ndarray, ...]:
    """The inner box's half extents, the nearest point of the solid inner box, and the depth
    below each face's plane (positive inside)."""
    inner = np.asarray(half_size, np.float64) - rounding
    return inner, np.clip(p, -inner, inner), inner - np.abs(p)


def round_box_distance(*, p: ArrayLike, halfSize: ArrayLike, rounding: float) -> np.ndarray:
    p = _points(p)
    _, nearest, depth = _inner_box(p, halfSize, rounding)
    outside = np.linalg.norm(p - nearest, axis=-1)
    inner = np.where(outside > 0.0, outside, -depth.min(axis=-1))
    return inner - rounding


def round_box_normal(*, p: ArrayLike, halfSize: ArrayLike, rounding: float) -> np.ndarray:
    """Outside the inner box: from its nearest point. Inside it (deeper than the rounding):
    the nearest face's normal, one face on a crease."""
    p = _points(p)
    _, nearest, depth = _inner_box(p, halfSize, rounding)
    face = np.zeros_like(p)
    face[np.arange(len(p)), depth.argmin(axis=-1)] = 1.0
    face *= np.where(p < 0.0, -1.0, 1.0)
    outside = (np.abs(p - nearest) > 0.0).any(axis=-1, keepdims=True)
    return _unit(np.where(outside, p - nearest, face))


# --- ellipsoid: the true distance, from the Lagrange condition of the closest point ---------


def ellipsoid_closest(p: ArrayLike, radii: ArrayLike) -> np.ndarray:
    """The closest point of the ellipsoid's surface to each p (float64).

    With x = r² p / (r² + t) (componentwise), x is on the surface where
    F(t) = Σ (r_i p_i / (r_i² + t))² = 1; F falls from +∞ to 0 over t > −r_min², and the
    closest point is at its root there (Eberly, "Distance from a point to an ellipsoid").
    The root is found by bisection on s = t + r_min² in log space, so that a point near the
    plane of the shortest axis keeps its precision. When p lies in that plane and F stays
    below 1 (a point inside, near the centre of a flat ellipsoid), the closest point leaves
    the plane: t = −r_min² and its shortest-axis coordinate comes from the surface equation.
    Radii must be distinct for that last case; the grids in the tests avoid it anyway.
    """
    p = _points(p)
    r = np.asarray(radii, np.float64)
    a = np.abs(p)
    shortest = int(np.argmin(r))
    shift = r**2 - r[shortest] ** 2  # r_i² + t = shift_i + s

    def excess(s: np.ndarray) -> np.ndarray:
        return np.sum((r * a / (shift + s[:, None])) ** 2, axis=-1) - 1.0

    lo = np.full(len(p), 1e-150)
    hi = np.full(len(p), r.max() * np.linalg.norm(a, axis=-1) + r.max() ** 2 + 1.0)
    for _ in range(2200 // 2):  # log-space bisection over ~1e-150..1e3 to full precision
        mid = np.sqrt(lo * hi)
        above = excess(mid) > 0.0
        lo, hi = np.where(above, mid, lo), np.where(above, hi, mid)
        if np.all(hi <= lo * (1.0 + 4e-16)):
            break
    s = np.sqrt(lo * hi)
    x = r**2 * a / (shift + s[:, None])
    # The case with no root: t = −r_min², x_i = r_i² p_i / (r_i² − r_min²) off the shortest axis.
    flat = (a[:, shortest] == 0.0) & (excess(np.full(len(p), 1e-150)) <= 0.0)
    if flat.any():
        others = [i for i in range(3) if i != shortest]
        xf = np.zeros((int(flat.sum()), 3))
        xf[:, others] = r[others] ** 2 * a[flat][:, others] / shift[others]
        rest = 1.0 - np.sum((xf[:, others] / r[others]) ** 2, axis=-1)
        xf[:, shortest] = r[shortest] * np.sqrt(np.maximum(rest, 0.0))
        x[flat] = xf
    return np.sign(p) * x + (p == 0.0) * x  # back to p's octant (a zero coordinate keeps +)


def ellipsoid_distance(*, p: ArrayLike, radii: ArrayLike) -> np.ndarray:
    """The true signed distance to the ellipsoid (negative inside)."""
    p = _points(p)
    r = np.asarray(radii, np.float64)
    distance = np.linalg.norm(p - ellipsoid_closest(p, r), axis=-1)
    inside = np.sum((p / r) ** 2, axis=-1) < 1.0
    return np.where(inside, -distance, distance)


REFERENCES = {
    "sdf_torus": torus_distance,
    "sdf_torus_normal": torus_normal,
    "sdf_capsule": capsule_distance,
    "sdf_capsule_normal": capsule_normal,
    "sdf_capped_cylinder": capped_cylinder_distance,
    "sdf_capped_cylinder_normal": capped_cylinder_normal,
    "sdf_capped_cone": capped_cone_distance,
    "sdf_capped_cone_normal": capped_cone_normal,
    "sdf_round_box": round_box_distance,
    "sdf_round_box_normal": round_box_normal,
    "sdf_ellipsoid": ellipsoid_distance,
}
