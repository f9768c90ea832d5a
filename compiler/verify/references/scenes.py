"""Reference SDF scenes for the snippets that query the scene (AO, shadows): each one exact in
float64 numpy (a signed distance, and where a ray is inside each solid, in closed form) and as
the GLSL `map` that the probes run (`Scene.glsl()` is a `scene_stub` for `run_probe`).

Scenes are unions of spheres, axis-aligned boxes and the ground plane y = 0. The box distance is
exact (Quilez, "distance functions"); the union's `min` is exact outside the solids, which is
where the snippets evaluate it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from glint.compiler.compose.codegen.trace_code import Analytic, trace_glsl

Vec3 = tuple[float, float, float]


def _vec(v: Vec3) -> str:
    return "vec3(" + ", ".join(repr(float(x)) for x in v) + ")"


@dataclass(frozen=True)
class Sphere:
    center: Vec3
    radius: float

    def sdf(self, p: np.ndarray) -> np.ndarray:
        return np.linalg.norm(p - np.asarray(self.center), axis=-1) - self.radius

    def inside(self, ro: np.ndarray, rd: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The ray's parameter interval inside the solid, (t0, t1); t0 > t1 when it misses.
        `rd` must be unit length."""
        oc = ro - np.asarray(self.center)
        b = np.sum(oc * rd, axis=-1)
        c = np.sum(oc * oc, axis=-1) - self.radius**2
        disc = b * b - c
        root = np.sqrt(np.maximum(disc, 0.0))
        miss = disc < 0.0
        return np.where(miss, np.inf, -b - root), np.where(miss, -np.inf, -b + root)

    def glsl(self) -> str:
        return f"length(p - {_vec(self.center)}) - {float(self.radius)!r}"

    def analytic(self) -> Analytic:
        return Analytic("sphere", _vec(self.center), repr(float(self.radius)))


@dataclass(frozen=True)
class Box:
    center: Vec3
    half: Vec3  # half the size along x, y, z

    def sdf(self, p: np.ndarray) -> np.ndarray:
        q = np.abs(p - np.asarray(self.center)) - np.asarray(self.half)
        outside = np.linalg.norm(np.maximum(q, 0.0), axis=-1)
        return outside + np.minimum(q.max(axis=-1), 0.0)

    def inside(self, ro: np.ndarray, rd: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Slab test: the latest entry and the earliest exit over the three axes."""
        lo = np.asarray(self.center) - np.asarray(self.half)
        hi = np.asarray(self.center) + np.asarray(self.half)
        with np.errstate(divide="ignore", invalid="ignore"):
            ta, tb = (lo - ro) / rd, (hi - ro) / rd
        near, far = np.minimum(ta, tb), np.maximum(ta, tb)
        # A ray parallel to a slab is inside it for every t, or for none.
        within = (ro >= lo) & (ro <= hi)
        parallel = rd == 0.0
        near = np.where(parallel, np.where(within, -np.inf, np.inf), near)
        far = np.where(parallel, np.where(within, np.inf, -np.inf), far)
        return near.max(axis=-1), far.min(axis=-1)

    def glsl(self) -> str:
        return f"sdBoxAt(p, {_vec(self.center)}, {_vec(self.half)})"

    def analytic(self) -> Analytic:
        return Analytic("box", _vec(self.center), _vec(self.half))


@dataclass(frozen=True)
class Ground:
    """The half-space y < 0."""

    def sdf(self, p: np.ndarray) -> np.ndarray:
        return p[..., 1]

    def inside(self, ro: np.ndarray, rd: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        y, dy = ro[..., 1], rd[..., 1]
        with np.errstate(divide="ignore", invalid="ignore"):
            cross = -y / dy
        # Along the ground (dy = 0) the ray is below it for every t, or for none.
        flat_t0 = np.where(y < 0.0, -np.inf, np.inf)
        flat_t1 = -flat_t0
        t0 = np.where(dy < 0.0, cross, np.where(dy > 0.0, -np.inf, flat_t0))
        t1 = np.where(dy > 0.0, cross, np.where(dy < 0.0, np.inf, flat_t1))
        return t0, t1

    def glsl(self) -> str:
        return "p.y"

    def analytic(self) -> Analytic:
        return Analytic("plane", normal="vec3(0.0, 1.0, 0.0)", offset="0.0")


Primitive = Sphere | Box | Ground

BOX_GLSL = """float sdBoxAt(vec3 p, vec3 center, vec3 halfSize) {
    vec3 q = abs(p - center) - halfSize;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}
"""
# A ray starting on a surface and leaving it is inside that solid up to t = 0 only; counting
# hits from this parameter on keeps such a start from shadowing itself.
T_EPSILON = 1e-9


@dataclass(frozen=True)
class Scene:
    name: str
    primitives: tuple[Primitive, ...]

    def sdf(self, p: ArrayLike) -> np.ndarray:
        p = np.asarray(p, np.float64)
        return np.min([prim.sdf(p) for prim in self.primitives], axis=0)

    def blocked(self, ro: ArrayLike, rd: ArrayLike, tmax: float = np.inf) -> np.ndarray:
        """Whether the ray ro + t·rd (rd unit) meets a solid for t in (0, tmax]."""
        ro, rd = np.broadcast_arrays(np.asarray(ro, np.float64), np.asarray(rd, np.float64))
        hit = np.zeros(ro.shape[:-1], bool)
        for prim in self.primitives:
            t0, t1 = prim.inside(ro, rd)
            hit |= (t0 <= t1) & (t1 > T_EPSILON) & (t0 <= tmax)
        return hit

    def glsl(self, queries: bool = False) -> str:
        """The scene as the `scene_stub` of a probe: `map` and a single material; with
        `queries`, also its closed-form queries for the analytic variants (they call the
        catalog's `trace` snippets, which the probe's resolver adds)."""
        terms = [prim.glsl() for prim in self.primitives]
        expr = terms[0]
        for term in terms[1:]:
            expr = f"min({expr}, {term})"
        helper = BOX_GLSL if any(isinstance(p, Box) for p in self.primitives) else ""
        return (
            f"{helper}float map(vec3 p) {{ return {expr}; }}\n"
            "int materialAt(vec3 p) { return 0; }\n"
        ) + (trace_glsl([prim.analytic() for prim in self.primitives]) if queries else "")


SCENES: dict[str, Scene] = {
    scene.name: scene
    for scene in (
        # A unit sphere resting on the ground: a contact point, a round shadow, a crevice.
        Scene("sphere_on_plane", (Ground(), Sphere((0.0, 1.0, 0.0), 1.0))),
        # A unit cube on the ground: straight shadow edges and a long flat wall.
        Scene("box_on_plane", (Ground(), Box((0.0, 0.5, 0.0), (0.5, 0.5, 0.5)))),
        # Two walls meeting the ground: a concave corner where three faces meet.
        Scene(
            "corner",
            (
                Ground(),
                Box((-1.25, 1.0, 0.0), (0.25, 1.0, 1.5)),
                Box((0.25, 1.0, -1.25), (1.25, 1.0, 0.25)),
            ),
        ),
    )
}


def scene(name: str) -> Scene:
    try:
        return SCENES[name]
    except KeyError:
        raise KeyError(f"unknown reference scene '{name}'; known: {', '.join(SCENES)}") from None
