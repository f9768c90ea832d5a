"""Reference SDF scenes in float64, with their analytic normals and the same scenes in GLSL.

The normal slot estimates the gradient of the scene's distance field. Each scene here gives the
distance (`sdf`), the exact outward unit normal (`normal`), points on its surface (`surface`,
found in float64) and the GLSL of the same `map` (`glsl`), so a normal variant can be run on
the GPU against the scene it is meant for and compared with the exact answer in degrees.

The registry entry `sdf_normal(p=..., scene=...)` is that exact normal, by scene name.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

Field = Callable[[np.ndarray], np.ndarray]

BOX_HALF = np.array([1.0, 0.5, 0.75])
PLANE_NORMAL = np.array([1.0, 2.0, 0.5]) / np.linalg.norm([1.0, 2.0, 0.5])
PLANE_OFFSET = 0.3
# The smooth union: a unit sphere and a rounded box beside it (an inner box of half extents
# BLOB_HALF grown by BLOB_ROUND, so that it has no sharp edge), blended over SMOOTH_K.
BLOB_CENTER = np.array([1.1, 0.0, 0.0])
BLOB_HALF = np.array([0.5, 0.5, 0.5])
BLOB_ROUND = 0.1
SMOOTH_K = 0.5


@dataclass(frozen=True)
class Scene:
    name: str
    sdf: Field  # (N, 3) -> (N,)
    normal: Field  # (N, 3) -> (N, 3), unit, pointing out of the solid
    surface: Callable[[np.random.Generator, int], np.ndarray]  # rng, count -> (count, 3)
    glsl: str  # defines float map(vec3 p) and int materialAt(vec3 p)


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _directions(rng: np.random.Generator, count: int) -> np.ndarray:
    return _unit(rng.normal(size=(count, 3)))


def _glsl(map_body: str) -> str:
    return f"float map(vec3 p) {{\n{map_body}}}\nint materialAt(vec3 p) {{ return 0; }}\n"


# --- sphere: |p| - 1, normal p / |p| -------------------------------------------------------


def sphere_sdf(p: np.ndarray) -> np.ndarray:
    return np.linalg.norm(p, axis=-1) - 1.0


def sphere_normal(p: np.ndarray) -> np.ndarray:
    return _unit(p)


def sphere_surface(rng: np.random.Generator, count: int) -> np.ndarray:
    return _directions(rng, count)


# --- box: exact distance to an axis-aligned box (Quilez), normal of the nearest face -------


def box_sdf(p: np.ndarray, half: np.ndarray = BOX_HALF) -> np.ndarray:
    q = np.abs(p) - half
    outside = np.linalg.norm(np.maximum(q, 0.0), axis=-1)
    return outside + np.minimum(q.max(axis=-1), 0.0)


def box_normal(p: np.ndarray, half: np.ndarray = BOX_HALF) -> np.ndarray:
    """Outside: from the nearest point of the box to p. On or inside: the face whose plane is
    nearest (largest q); on an edge this picks one face, so samples keep off the edges."""
    q = np.abs(p) - half
    outside = np.maximum(q, 0.0)
    face = np.zeros_like(q)
    face[np.arange(len(q)), q.argmax(axis=-1)] = 1.0
    direction = np.where((q > 0.0).any(axis=-1, keepdims=True), outside, face)
    return _unit(direction * np.sign(p))


def box_surface(
    rng: np.random.Generator, count: int, half: np.ndarray = BOX_HALF, margin: float = 0.0
) -> np.ndarray:
    """Points on the faces, at least `margin` from every edge."""
    axis = rng.integers(0, 3, count)
    side = rng.choice([-1.0, 1.0], count)
    lo, hi = -half + margin, half - margin
    points = rng.uniform(lo, hi, size=(count, 3))
    points[np.arange(count), axis] = side * half[axis]
    return points


def box_edge_points(distances: ArrayLike, half: np.ndarray = BOX_HALF) -> np.ndarray:
    """For each distance δ, points on every face δ from each of its 4 edges (mid-edge)."""
    points = []
    for delta in np.atleast_1d(np.asarray(distances, np.float64)):
        for axis in range(3):  # the face's normal axis
            for side in (-1.0, 1.0):
                for along in [a for a in range(3) if a != axis]:  # toward which edge
                    for towards in (-1.0, 1.0):
                        p = np.zeros(3)
                        p[axis] = side * half[axis]
                        p[along] = towards * (half[along] - delta)
                        points.append(p)
    return np.array(points)


# --- tilted plane: n·p - h --------------------------------------------------------------


def plane_sdf(p: np.ndarray) -> np.ndarray:
    return p @ PLANE_NORMAL - PLANE_OFFSET


def plane_normal(p: np.ndarray) -> np.ndarray:
    return np.broadcast_to(PLANE_NORMAL, p.shape).copy()


def plane_surface(rng: np.random.Generator, count: int) -> np.ndarray:
    raw = rng.uniform(-3.0, 3.0, size=(count, 3))
    return raw - (plane_sdf(raw) - 0.0)[:, None] * PLANE_NORMAL  # project onto the plane


# --- smooth union of a sphere and a box (polynomial smin, Quilez) --------------------------


def _smin_weight(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.clip(0.5 + 0.5 * (b - a) / SMOOTH_K, 0.0, 1.0)


def _rounded_box(p: np.ndarray) -> np.ndarray:
    return box_sdf(p - BLOB_CENTER, BLOB_HALF) - BLOB_ROUND


def blob_sdf(p: np.ndarray) -> np.ndarray:
    a, b = sphere_sdf(p), _rounded_box(p)
    h = _smin_weight(a, b)
    return b + h * (a - b) - SMOOTH_K * h * (1.0 - h)


def blob_normal(p: np.ndarray) -> np.ndarray:
    """Gradient of smin(a, b) = b + h (a − b) − k h (1 − h), h = clamp(½ + ½ (b − a)/k):
    ∇ = h ∇a + (1 − h) ∇b + (a − b − k (1 − 2h)) ∇h, with ∇h = (∇b − ∇a)/(2k) inside the blend.
    The last factor vanishes identically there (a − b = k (1 − 2h)), which leaves the mix.
    The rounded box's surface keeps BLOB_ROUND off the inner box, where its gradient is smooth."""
    a, b = sphere_sdf(p), _rounded_box(p)
    h = _smin_weight(a, b)[:, None]
    grad_a, grad_b = sphere_normal(p), box_normal(p - BLOB_CENTER, BLOB_HALF)
    return _unit(h * grad_a + (1.0 - h) * grad_b)


def blob_surface(rng: np.random.Generator, count: int) -> np.ndarray:
    """Along rays from a point inside both shapes, the zero of the field by bisection (float64).
    The union is star-shaped about that point, so each ray crosses the surface once."""
    origin = np.array([0.8, 0.0, 0.0])
    directions = _directions(rng, count)
    lo, hi = np.zeros(count), np.full(count, 4.0)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        inside = blob_sdf(origin + mid[:, None] * directions) < 0.0
        lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
    return origin + (0.5 * (lo + hi))[:, None] * directions


BOX_GLSL = """float boxDistance(vec3 p, vec3 b) {
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}
"""
SMIN_GLSL = """float sminPoly(float a, float b, float k) {
    float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
    return mix(b, a, h) - k * h * (1.0 - h);
}
"""


def _vec3(v: np.ndarray) -> str:
    return "vec3(" + ", ".join(repr(float(x)) for x in v) + ")"


SCENES: dict[str, Scene] = {
    scene.name: scene
    for scene in (
        Scene(
            "sphere", sphere_sdf, sphere_normal, sphere_surface,
            _glsl("    return length(p) - 1.0;\n"),
        ),
        Scene(
            "box", box_sdf, box_normal, box_surface,
            BOX_GLSL + _glsl(f"    return boxDistance(p, {_vec3(BOX_HALF)});\n"),
        ),
        Scene(
            "plane", plane_sdf, plane_normal, plane_surface,
            _glsl(f"    return dot(p, {_vec3(PLANE_NORMAL)}) - {PLANE_OFFSET!r};\n"),
        ),
        Scene(
            "smooth_union", blob_sdf, blob_normal, blob_surface,
            BOX_GLSL + SMIN_GLSL + _glsl(
                f"    float b = boxDistance(p - {_vec3(BLOB_CENTER)}, {_vec3(BLOB_HALF)})"
                f" - {BLOB_ROUND!r};\n"
                f"    return sminPoly(length(p) - 1.0, b, {SMOOTH_K!r});\n"
            ),
        ),
    )
}  # fmt: skip


def sdf_normal(*, p: ArrayLike, scene: str) -> np.ndarray:
    """The exact outward unit normal of reference scene `scene` at points p (N, 3)."""
    if scene not in SCENES:
        raise KeyError(f"unknown reference scene '{scene}'; scenes: {', '.join(SCENES)}")
    return SCENES[scene].normal(np.atleast_2d(np.asarray(p, np.float64)))


def angle_deg(a: ArrayLike, b: ArrayLike) -> np.ndarray:
    """Angle between rows of a and b in degrees, accurate at small angles (atan2 of |a×b|, a·b)."""
    a, b = _unit(np.asarray(a, np.float64)), _unit(np.asarray(b, np.float64))
    sine = np.linalg.norm(np.cross(a, b), axis=-1)
    cosine = np.sum(a * b, axis=-1)
    return np.degrees(np.arctan2(sine, cosine))


REFERENCES = {
    "sdf_normal": sdf_normal,
}
