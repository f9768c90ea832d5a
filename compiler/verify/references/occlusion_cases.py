"""Where the shadow and AO snippets are held to ground truth: points on the surfaces of the
reference scenes (the ground near the objects and in the open, the objects themselves), with
their normals, and the light directions of each scene.

Points buried in another solid (the ground under a box, a wall's face against the floor) are
left out; every point is deterministic.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np

from glint.compiler.verify.references.scenes import Box, Scene, Sphere
from glint.compiler.verify.references.scenes import scene as reference_scene

# Directions toward a distant light, per scene: a high sun (the default scene's) and a low one
# whose shadows are long, so that a march with few steps falls short of the occluder.
LIGHTS: dict[str, tuple[tuple[float, float, float], ...]] = {
    "sphere_on_plane": ((0.6, 0.8, -0.5), (1.0, 0.35, 0.3)),
    "box_on_plane": ((0.6, 0.8, -0.5), (-0.9, 0.4, 0.6)),
    "corner": ((-0.5, 0.8, -0.4), (-0.8, 0.45, -0.3)),
}


@dataclass(frozen=True)
class SurfacePoints:
    scene: str
    p: np.ndarray  # (N, 3) points on the surface
    n: np.ndarray  # (N, 3) unit outward normals


@dataclass(frozen=True)
class ShadowCase:
    scene: str
    light: np.ndarray  # (3,) unit direction toward the light
    ro: np.ndarray  # (N, 3) lit-side surface points
    n: np.ndarray  # (N, 3) their normals


def ground_grid(scene: Scene, extent: float, count: int) -> SurfacePoints:
    """A count × count grid of the ground over [-extent, extent]², outside every object."""
    axis = np.linspace(-extent, extent, count)
    x, z = (a.ravel() for a in np.meshgrid(axis, axis, indexing="ij"))
    p = np.stack([x, np.zeros_like(x), z], -1)
    n = np.broadcast_to([0.0, 1.0, 0.0], p.shape).copy()
    return _exposed(scene, p, n)


def object_points(scene: Scene, per_object: int) -> SurfacePoints:
    """About `per_object` points on each object other than the ground, with their normals."""
    parts = [_sphere_points(s, per_object) for s in scene.primitives if isinstance(s, Sphere)]
    parts += [_box_points(b, per_object) for b in scene.primitives if isinstance(b, Box)]
    if not parts:
        return SurfacePoints(scene.name, np.zeros((0, 3)), np.zeros((0, 3)))
    p = np.concatenate([part[0] for part in parts])
    n = np.concatenate([part[1] for part in parts])
    return _exposed(scene, p, n)


def _sphere_points(sphere: Sphere, count: int) -> tuple[np.ndarray, np.ndarray]:
    # Fibonacci lattice: near-uniform over the sphere with no clustering at the poles.
    i = np.arange(count) + 0.5
    y = 1.0 - 2.0 * i / count
    r = np.sqrt(1.0 - y * y)
    phi = i * np.pi * (3.0 - np.sqrt(5.0))
    n = np.stack([r * np.cos(phi), y, r * np.sin(phi)], -1)
    return np.asarray(sphere.center) + sphere.radius * n, n


def _box_points(box: Box, count: int) -> tuple[np.ndarray, np.ndarray]:
    side = max(2, int(np.sqrt(count / 6)))
    cells = (np.arange(side) + 0.5) / side * 2.0 - 1.0  # centres of cells, clear of the edges
    u, v = (a.ravel() for a in np.meshgrid(cells, cells, indexing="ij"))
    points, normals = [], []
    for axis in range(3):
        others = [a for a in range(3) if a != axis]
        for sign in (-1.0, 1.0):
            local = np.zeros((len(u), 3))
            local[:, axis] = sign
            local[:, others[0]], local[:, others[1]] = u, v
            normal = np.zeros((len(u), 3))
            normal[:, axis] = sign
            points.append(np.asarray(box.center) + local * np.asarray(box.half))
            normals.append(normal)
    return np.concatenate(points), np.concatenate(normals)


def _exposed(scene: Scene, p: np.ndarray, n: np.ndarray) -> SurfacePoints:
    """The points that lie on the scene's boundary and face open space."""
    keep = (np.abs(scene.sdf(p)) < 1e-9) & (scene.sdf(p + 1e-6 * n) > 0.0)
    return SurfacePoints(scene.name, p[keep], n[keep])


def _unit(v: tuple[float, float, float]) -> np.ndarray:
    v = np.asarray(v, np.float64)
    return v / np.linalg.norm(v)


@cache
def shadow_cases() -> tuple[ShadowCase, ...]:
    """Per scene and light: the ground around the objects (their shadows and penumbrae, and
    open ground) and the objects' own lit faces (grazing light near the terminator)."""
    cases = []
    for name, lights in LIGHTS.items():
        scene = reference_scene(name)
        ground = ground_grid(scene, 4.0, 41)
        objects = object_points(scene, 200)
        p = np.concatenate([ground.p, objects.p])
        n = np.concatenate([ground.n, objects.n])
        for light in lights:
            direction = _unit(light)
            lit = n @ direction > 0.05  # facing the light: where a shadow factor matters
            cases.append(ShadowCase(name, direction, p[lit], n[lit]))
    return tuple(cases)


@cache
def ao_cases() -> tuple[SurfacePoints, ...]:
    """Per scene: the ground near and away from the objects, and every exposed object face."""
    cases = []
    for name in LIGHTS:
        scene = reference_scene(name)
        ground = ground_grid(scene, 2.0, 41)  # every 0.1: contact zones are narrow
        objects = object_points(scene, 300)
        cases.append(
            SurfacePoints(
                name, np.concatenate([ground.p, objects.p]), np.concatenate([ground.n, objects.n])
            )
        )
    return tuple(cases)
