"""Subsurface variants on reference spheres: the probe at points on a sphere of radius r toward
random light directions, against the exact transmittance through it, exp(−σ·chord)
(references/scattering.subsurface_sphere). The probe test (tests/verify/test_scattering.py) and the
benchmark both take their samples from here.
"""

from __future__ import annotations

import numpy as np

from glint.compiler.bench.samples import ProbeSet
from glint.compiler.verify.references.scattering import subsurface_sphere

# From thin parts (a twentieth of a unit) to a body much thicker than the probe reaches.
RADII = [0.05, 0.1, 0.2, 0.5, 1.0, 3.0]
SAMPLES = 4000  # per sphere
SEED = 11


def sphere_scene(radius: float) -> str:
    return (
        f"float map(vec3 p) {{ return length(p) - {radius!r}; }}\n"
        "int materialAt(vec3 p) { return 0; }\n"
    )


def _unit_rows(rng: np.random.Generator, count: int) -> np.ndarray:
    v = rng.normal(size=(count, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def sphere_directions(rng: np.random.Generator, count: int) -> tuple[np.ndarray, np.ndarray]:
    """Surface normals n (points n·r of the sphere) and light directions L, uniform."""
    n = _unit_rows(rng, count)
    return n, _unit_rows(rng, count)


def subsurface_set(radius: float, n: np.ndarray, L: np.ndarray) -> ProbeSet:  # noqa: N803
    """The probe at p = n·radius (on the surface, as a raymarcher's hit is) toward L, with the
    exact transmittance at the float32 values the GPU receives."""
    p = n * radius
    inputs = {f"p{i}": p[:, i] for i in range(3)} | {f"L{i}": L[:, i] for i in range(3)}
    p32, L32 = p.astype(np.float32), L.astype(np.float32)  # noqa: N806
    exact = subsurface_sphere(
        p0=p32[:, 0],
        p1=p32[:, 1],
        p2=p32[:, 2],
        L0=L32[:, 0],
        L1=L32[:, 1],
        L2=L32[:, 2],
        radius=radius,
    )
    return ProbeSet(inputs, sphere_scene(radius), exact)


def subsurface_sets(samples: int = SAMPLES, seed: int = SEED) -> list[ProbeSet]:
    """One pass per radius of RADII, the directions drawn in turn from one generator."""
    rng = np.random.default_rng(seed)
    return [subsurface_set(r, *sphere_directions(rng, samples)) for r in RADII]
