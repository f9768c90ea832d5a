"""Normal variants against the exact normals of the reference SDF scenes
(references/normals.py), in degrees.

Gradient-based variants (they tap `map`) are probed point by point with the scene's GLSL as
`map`, at points on each surface and near the box's edges. The probe tests
(tests/verify/test_normal_probes.py) and the benchmark both take their points from here.
"""

from __future__ import annotations

import numpy as np

from glint.compiler.bench.samples import ProbeSet
from glint.compiler.catalog.loader import Snippet
from glint.compiler.verify.references.normals import SCENES, box_edge_points, box_surface

SAMPLES = 400  # points per scene
SEED = 17


def tap_reach(snippet: Snippet) -> float:
    """How far from p the variant taps `map`; a variant without taps (the derivative-based
    flat normal) is given the central differences' default, only to place the points."""
    param = snippet.params.get("NORMAL_EPS")
    return float(param.default) if param is not None else 1e-3


def surface_points(snippet: Snippet, scene: str) -> np.ndarray:
    """Float64 points on the surface, rounded to the float32 the GPU receives (the reference is
    then taken at the same points, so what is measured is the variant, not the rounding)."""
    rng = np.random.default_rng(SEED)
    if scene == "box":
        # Faces at least two tap reaches from every edge, and rows of points at 2, 5 and 10
        # reaches from each edge: where no tap crosses an edge the box is a plane to the taps.
        reach = tap_reach(snippet)
        faces = box_surface(rng, SAMPLES, margin=2.0 * reach)
        points = np.concatenate([faces, box_edge_points(np.array([2.0, 5.0, 10.0]) * reach)])
    else:
        points = SCENES[scene].surface(rng, SAMPLES)
    return points.astype(np.float32).astype(np.float64)


def point_inputs(points: np.ndarray) -> dict[str, np.ndarray]:
    return {f"p{axis}": points[:, axis] for axis in range(3)}


def normal_set(snippet: Snippet, scene: str, with_reference: bool = True) -> ProbeSet:
    """The variant at points of the reference `scene`, with the exact normals there."""
    points = surface_points(snippet, scene)
    exact = SCENES[scene].normal(points) if with_reference else None
    return ProbeSet(point_inputs(points), SCENES[scene].glsl, exact, metric="degrees")
