"""The `trace` snippets, run by the numpy evaluator at float32, against the float64 references of
compiler/verify/references/trace.py: the first hit of rays from around each primitive, the
signed angular clearance (the quantity the analytic soft shadow turns into a penumbra), and the
box's face normal; and the scene queries written from them (compose/codegen/trace_code.py)."""

from __future__ import annotations

import numpy as np
import pytest

from glint.compiler.catalog.loader import load_catalog
from glint.compiler.compose.codegen.trace_code import analytic, scene_primitives
from glint.compiler.evaluator.api import evaluate
from glint.compiler.scene.model import parse_scene
from glint.compiler.verify.references.scenes import Box, Ground, Sphere
from glint.compiler.verify.references.trace import clearance, first_hit

CATALOG = load_catalog()
COUNT = 240
# The light's angular radius at SHADOW_K = 8: clearances beyond it light the disc fully, so the
# shadow needs them only up to there; the test compares up to twice that.
LIGHT = float(np.arctan(1.0 / 8.0))

SPHERE = Sphere((0.0, 0.0, 0.0), 0.8)
BOX = Box((0.0, 0.0, 0.0), (0.6, 0.3, 0.45))


def rays(seed: int, aim: float) -> tuple[np.ndarray, np.ndarray]:
    """Origins 1.5 to 4 from the origin, directions toward a point within `aim` of it."""
    rng = np.random.default_rng(seed)
    ro = rng.normal(size=(COUNT, 3))
    ro *= (rng.uniform(1.5, 4.0, COUNT) / np.linalg.norm(ro, axis=1))[:, None]
    target = rng.uniform(-aim, aim, (COUNT, 3))
    rd = target - ro
    return ro, rd / np.linalg.norm(rd, axis=1, keepdims=True)


def glsl(snippet: str, function: str, **args: object) -> np.ndarray:
    values = {k: np.asarray(v, np.float32) for k, v in args.items()}
    body = CATALOG.get(snippet).body
    if snippet == "trace.box":  # it bounds the box by a sphere first
        body = CATALOG.get("trace.sphere").body + body
    return np.asarray(evaluate(body, function, values, dtype=np.float32), np.float64)


def sphere_args(ro: np.ndarray, rd: np.ndarray) -> dict[str, object]:
    return {"ro": ro, "rd": rd, "r": SPHERE.radius}


def box_args(ro: np.ndarray, rd: np.ndarray) -> dict[str, object]:
    return {"ro": ro, "rd": rd, "b": BOX.half}


CASES = [
    ("trace.sphere", "traceSphere", "clearanceSphere", SPHERE, sphere_args),
    ("trace.box", "traceBox", "clearanceBox", BOX, box_args),
]


@pytest.mark.parametrize(("snippet", "trace", "clear", "prim", "args"), CASES, ids=lambda c: c)
def test_first_hit_matches_the_exact_interval(snippet, trace, clear, prim, args) -> None:  # noqa: ANN001
    ro, rd = rays(1, 0.6)
    got = glsl(snippet, trace, **args(ro, rd))
    want = first_hit(prim, ro, rd)
    assert ((got >= 0.0) == (want >= 0.0)).mean() > 0.995  # only rays grazing the outline differ
    both = (got >= 0.0) & (want >= 0.0)
    assert both.sum() > COUNT // 4
    assert np.abs(got[both] - want[both]).max() < 1e-5 * 4.0


@pytest.mark.parametrize(("snippet", "trace", "clear", "prim", "args"), CASES, ids=lambda c: c)
def test_clearance_matches_the_cone_search(snippet, trace, clear, prim, args) -> None:  # noqa: ANN001
    ro, rd = rays(2, 1.0)
    reach = {"reach": 10.0} if snippet == "trace.box" else {}
    got = glsl(snippet, clear, **args(ro, rd), tmax=100.0, **reach)
    want = clearance(prim, ro, rd)
    near = np.abs(want) < 2.0 * LIGHT
    assert near.sum() > COUNT // 10 and (want < 0.0).sum() > COUNT // 10
    # Within 1% of the light's radius, where it shapes the penumbra; the sign everywhere.
    assert np.abs(got - want)[near].max() < 0.01 * LIGHT
    assert (np.sign(got) == np.sign(want))[np.abs(want) > 1e-3].all()


def test_plane_clearance_is_the_elevation_above_the_reachable_horizon() -> None:
    rng = np.random.default_rng(3)
    ro = rng.uniform([-2.0, 0.0, -2.0], [2.0, 2.0, 2.0], (COUNT, 3))
    rd = rng.normal(size=(COUNT, 3))
    rd /= np.linalg.norm(rd, axis=1, keepdims=True)
    args = {"ro": ro, "rd": rd, "n": (0.0, 1.0, 0.0), "h": 0.0}
    far = glsl("trace.plane", "clearancePlane", **args, tmax=1e6)
    want = clearance(Ground(), ro, rd)
    assert np.abs(far - want).max() < 1e-3
    # Within tmax only: the plane's reachable points sit asin(height / tmax) below the horizon.
    near = glsl("trace.plane", "clearancePlane", **args, tmax=5.0)
    np.testing.assert_allclose(near - far, np.arcsin(np.minimum(ro[:, 1] / 5.0, 1.0)), atol=1e-5)
    hit = glsl("trace.plane", "tracePlane", **args)
    np.testing.assert_allclose(hit, first_hit(Ground(), ro, rd), atol=1e-4)


def test_box_normal_is_the_face_of_the_nearest_surface_point() -> None:
    rng = np.random.default_rng(4)
    half = np.asarray(BOX.half)
    axis = rng.integers(0, 3, COUNT)
    side = rng.choice([-1.0, 1.0], COUNT)
    p = rng.uniform(-0.9, 0.9, (COUNT, 3)) * half
    p[np.arange(COUNT), axis] = side * half[axis]
    got = glsl("trace.box", "normalBox", p=p, b=half)
    want = np.zeros((COUNT, 3))
    want[np.arange(COUNT), axis] = side
    np.testing.assert_array_equal(got, want)


def test_the_scene_queries_cover_placed_spheres_and_unturned_boxes_and_planes() -> None:
    scene = parse_scene(
        """
name = "queries"
[[objects]]
shape = "sphere"
radius = 0.5
scale = 2.0
position = [1.0, 0.0, 0.0]
rotation = [10.0, 20.0, 30.0]
material = "m"
[[objects]]
shape = "plane"
offset = 1.0
position = [0.0, 0.5, 0.0]
material = "m"
[materials.m]
albedo = [0.5, 0.5, 0.5]
"""
    )
    primitives = scene_primitives(scene.objects)
    assert primitives is not None
    sphere, plane = primitives
    assert sphere.trace() == "traceSphere(ro - vec3(1.0, 0.0, 0.0), rd, 1.0)"
    # dot(p − position, n) + offset: the plane y = -0.5
    assert plane.distance() == "sdPlane(p, vec3(0.0, 1.0, 0.0), 0.5)"
    turned = scene.objects[1].model_copy(update={"rotation": [0.0, 0.0, 5.0]})
    assert analytic(turned) is None
