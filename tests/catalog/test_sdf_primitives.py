"""The sdf slot's primitives and smooth operators: each snippet's own GLSL, run by the numpy
evaluator at float32, against the float64 references of compiler/verify/references/primitives.py
(distances on a grid inside and outside, normals near the surface), the ellipsoid as a bound of
the true distance, and the smooth operators against what the polynomial smooth minimum
guarantees."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import pytest

from glint.compiler.catalog.loader import load_catalog, parse_snippet
from glint.compiler.errors import InputError
from glint.compiler.evaluator.api import evaluate
from glint.compiler.verify.references import primitives, reference
from glint.compiler.verify.references.normals import angle_deg

CATALOG = load_catalog()
RNG_SEED = 7


@dataclass(frozen=True)
class Case:
    snippet: str  # catalog id
    function: str  # GLSL entry
    reference: str  # registry name of the float64 distance; its normal is `<name>_normal`
    params: dict[str, Any]  # by GLSL parameter name
    extent: tuple[float, float, float]  # half extents of the shape's bounding box

    def __str__(self) -> str:
        return f"{self.snippet}{self.params}"


EXACT = [
    Case("sdf.torus", "sdTorus", "sdf_torus", {"major": 1.0, "minor": 0.25}, (1.25, 0.25, 1.25)),
    Case("sdf.torus", "sdTorus", "sdf_torus", {"major": 0.4, "minor": 0.3}, (0.7, 0.3, 0.7)),
    Case(
        "sdf.capsule", "sdCapsule", "sdf_capsule",
        {"halfLength": 0.7, "radius": 0.3}, (0.3, 1.0, 0.3),
    ),
    Case(
        "sdf.capsule", "sdCapsule", "sdf_capsule",
        {"halfLength": 0.1, "radius": 0.8}, (0.8, 0.9, 0.8),
    ),
    Case(
        "sdf.capped_cylinder", "sdCappedCylinder", "sdf_capped_cylinder",
        {"radius": 0.6, "halfHeight": 0.4}, (0.6, 0.4, 0.6),
    ),
    Case(
        "sdf.capped_cylinder", "sdCappedCylinder", "sdf_capped_cylinder",
        {"radius": 0.2, "halfHeight": 1.2}, (0.2, 1.2, 0.2),
    ),
    Case(
        "sdf.capped_cone", "sdCappedCone", "sdf_capped_cone",
        {"halfHeight": 0.5, "bottomRadius": 0.8, "topRadius": 0.2}, (0.8, 0.5, 0.8),
    ),
    Case(
        "sdf.capped_cone", "sdCappedCone", "sdf_capped_cone",
        {"halfHeight": 0.8, "bottomRadius": 0.3, "topRadius": 0.7}, (0.7, 0.8, 0.7),
    ),
    Case(
        "sdf.capped_cone", "sdCappedCone", "sdf_capped_cone",
        {"halfHeight": 0.6, "bottomRadius": 0.5, "topRadius": 0.0}, (0.5, 0.6, 0.5),
    ),
    Case(
        "sdf.round_box", "sdRoundBox", "sdf_round_box",
        {"halfSize": [1.0, 0.5, 0.75], "rounding": 0.2}, (1.0, 0.5, 0.75),
    ),
    Case(
        "sdf.round_box", "sdRoundBox", "sdf_round_box",
        {"halfSize": [0.3, 0.6, 0.3], "rounding": 0.3}, (0.3, 0.6, 0.3),
    ),
]  # fmt: skip
ELLIPSOID_RADII = [(1.0, 0.2, 0.6), (0.5, 1.0, 0.8), (2.0, 0.05, 1.0), (0.7, 0.69, 0.71)]


def grid(extent: tuple[float, ...] | np.ndarray, n: int = 20) -> np.ndarray:
    """n^3 points over the box 1.5 times the shape's extent (an even n keeps off the planes of
    symmetry, where the ellipsoid's closest point is a special case)."""
    axes = [np.linspace(-1.5 * e, 1.5 * e, n) for e in extent]
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)


def glsl(snippet: str, function: str, p: np.ndarray, params: dict[str, Any]) -> np.ndarray:
    """The snippet's GLSL at float32 over points p (N, 3), as float64 for comparisons."""
    args = {"p": p.astype(np.float32)}
    args |= {k: np.asarray(v, np.float32) for k, v in params.items()}
    body = CATALOG.get(snippet).body
    return np.asarray(evaluate(body, function, args, dtype=np.float32), np.float64)


# --- exact distances ------------------------------------------------------------------------


@pytest.mark.parametrize("case", EXACT, ids=str)
def test_exact_distance_matches_reference(case: Case) -> None:
    p = grid(case.extent).astype(np.float32).astype(np.float64)  # the points float32 sees
    got = glsl(case.snippet, case.function, p, case.params)
    want = reference(case.reference)(p=p, **case.params)
    assert (want < 0).any() and (want > 0).any(), "the grid must straddle the surface"
    error = np.abs(got - want)
    worst = int(error.argmax())
    assert error[worst] <= 1e-4, f"at p = {p[worst]}: GLSL {got[worst]}, reference {want[worst]}"


@pytest.mark.parametrize("case", EXACT, ids=str)
def test_exact_primitives_are_marked_exact(case: Case) -> None:
    assert CATALOG.get(case.snippet).distance == "exact"


# --- normals --------------------------------------------------------------------------------

# Points on each surface, away from the rims of the cylinder and the cone (a margin of 0.15
# along their faces), so that offsetting them by |δ| < 0.05 along the normal stays off the
# creases: outside, the nearest point is still the face's; inside, the other faces are further.
MARGIN = 0.15


def _angles(rng: np.random.Generator, count: int) -> tuple[np.ndarray, np.ndarray]:
    u = rng.uniform(0.0, 2.0 * np.pi, count)
    return np.cos(u), np.sin(u)


def torus_surface(rng: np.random.Generator, count: int, major: float, minor: float) -> np.ndarray:
    (cu, su), (cv, sv) = _angles(rng, count), _angles(rng, count)
    ring = major + minor * cv
    return np.stack([ring * cu, minor * sv, ring * su], axis=-1)


def capsule_surface(
    rng: np.random.Generator,
    count: int,
    halfLength: float,
    radius: float,
) -> np.ndarray:
    d = rng.normal(size=(count, 3))
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    centre = np.zeros((count, 3))
    centre[:, 1] = np.where(rng.random(count) < 0.5, np.sign(d[:, 1]) * halfLength, 0.0)
    side = centre[:, 1] == 0.0  # on the cylinder part: horizontal normal, any height
    d[side, 1] = 0.0
    d[side] /= np.linalg.norm(d[side], axis=-1, keepdims=True)
    centre[side, 1] = rng.uniform(-halfLength, halfLength, int(side.sum()))
    return centre + radius * d


def profile_surface(
    rng: np.random.Generator, count: int, half_height: float, bottom: float, top: float
) -> np.ndarray:
    """On the side (from the bottom rim to the top rim) or a cap, MARGIN from the rims."""
    c, s = _angles(rng, count)
    which = rng.integers(0, 3, count)  # 0 side, 1 bottom cap, 2 top cap
    which[(which == 1) & (bottom <= MARGIN)] = 0  # a cap narrower than the margin (an apex)
    which[(which == 2) & (top <= MARGIN)] = 0  # has no point far enough from its rim
    side_length = np.hypot(bottom - top, 2.0 * half_height)
    t = rng.uniform(MARGIN / side_length, 1.0 - MARGIN / side_length, count)
    rho = np.where(which == 0, bottom + t * (top - bottom), 0.0)
    y = np.where(which == 0, -half_height + t * 2.0 * half_height, 0.0)
    for cap, radius, height in ((1, bottom, -half_height), (2, top, half_height)):
        on = which == cap
        if not on.any():
            continue
        rho[on] = rng.uniform(0.0, radius - MARGIN, int(on.sum()))
        y[on] = height
    return np.stack([rho * c, y, rho * s], axis=-1)


def round_box_surface(
    rng: np.random.Generator,
    count: int,
    halfSize: list[float],
    rounding: float,
) -> np.ndarray:
    """From points around the box, their nearest point of the inner box pushed out by the
    rounding: faces, rounded edges and corners alike (the surface is smooth everywhere)."""
    inner = np.asarray(halfSize) - rounding
    x = rng.uniform(-2.0, 2.0, size=(count, 3)) * np.asarray(halfSize)
    x = x[(np.abs(x) > inner).any(axis=-1)]
    nearest = np.clip(x, -inner, inner)
    away = x - nearest
    return nearest + rounding * away / np.linalg.norm(away, axis=-1, keepdims=True)


SURFACES: dict[str, Callable[..., np.ndarray]] = {
    "sdTorus": torus_surface,
    "sdCapsule": capsule_surface,
    "sdCappedCylinder": lambda rng, n, radius, halfHeight: profile_surface(
        rng, n, halfHeight, radius, radius
    ),
    "sdCappedCone": lambda rng, n, halfHeight, bottomRadius, topRadius: profile_surface(
        rng, n, halfHeight, bottomRadius, topRadius
    ),
    "sdRoundBox": round_box_surface,
}

# The tolerance of the finite-difference normal, from float32: each distance carries a rounding
# error of a few ulps of the coordinates (|p| <= 2, ulp 2.4e-7, so ~5e-7), and a central
# difference over 2h = 2e-3 turns that into ~5e-4 per component of a unit gradient, about
# 0.03 degrees over three components. The truncation error, h^2/6 times the third derivative
# (~1/ρ^2 for a level set of curvature radius ρ >= 0.15 here), is ~1e-5: negligible. 0.1
# degrees leaves room for the rounding and is ten times tighter than "about a degree".
NORMAL_TOLERANCE_DEG = 0.1
H = 1e-3


@pytest.mark.parametrize("case", EXACT, ids=str)
def test_central_difference_normal_matches_reference(case: Case) -> None:
    rng = np.random.default_rng(RNG_SEED)
    surface = SURFACES[case.function](rng, 400, **case.params)
    normal_at = reference(f"{case.reference}_normal")
    delta = rng.uniform(-0.04, 0.04, len(surface))
    p = surface + delta[:, None] * normal_at(p=surface, **case.params)
    distance = reference(case.reference)(p=p, **case.params)
    # The offset point is where it was meant to be: as far from the surface as δ, so its
    # nearest point is the face it came from (not another face, not a rim).
    np.testing.assert_allclose(distance, delta, atol=1e-9)

    steps = np.eye(3) * H
    shifted = np.concatenate([p[None] + steps[:, None], p[None] - steps[:, None]])  # (6, N, 3)
    values = glsl(case.snippet, case.function, shifted.reshape(-1, 3), case.params)
    values = values.reshape(6, len(p))
    gradient = (values[:3] - values[3:]).T / (2.0 * H)
    angles = angle_deg(gradient, normal_at(p=p, **case.params))
    worst = int(angles.argmax())
    assert angles[worst] < NORMAL_TOLERANCE_DEG, (
        f"at p = {p[worst]} (δ = {delta[worst]:.3g}): {angles[worst]:.3g} degrees"
    )


# --- ellipsoid: a bound of the true distance ------------------------------------------------

# The bound is compared at float32: a tie with the true distance (on a sphere, where the bound
# is exact) may come out a rounding error above it, a few ulps of |p| <= 3.
FLOAT32_SLACK = 1e-6


def ellipsoid(p: np.ndarray, radii: tuple[float, float, float]) -> np.ndarray:
    return glsl("sdf.ellipsoid", "sdEllipsoid", p, {"radii": list(radii)})


@pytest.mark.parametrize("radii", ELLIPSOID_RADII, ids=str)
def test_ellipsoid_is_a_lower_bound_of_the_true_distance(radii: tuple[float, float, float]) -> None:
    r = np.asarray(radii)
    p = grid(r).astype(np.float32).astype(np.float64)
    bound = ellipsoid(p, radii)
    true = primitives.ellipsoid_distance(p=p, radii=r)
    assert (true < 0).any() and (true > 0).any()
    assert np.all(np.sign(bound) * np.sign(true) >= 0), "the bound must have the distance's sign"
    excess = np.abs(bound) - np.abs(true)
    worst = int(excess.argmax())
    assert excess[worst] <= FLOAT32_SLACK, (
        f"at p = {p[worst]}: bound {bound[worst]}, true distance {true[worst]}"
    )
    # Not a trivial bound: at least as tight as the rigorous (|p / r| - 1) min(r).
    linear = (np.linalg.norm(p / r, axis=-1) - 1.0) * r.min()
    assert np.all(np.abs(bound) >= np.abs(linear) - FLOAT32_SLACK)


@pytest.mark.parametrize("radii", ELLIPSOID_RADII, ids=str)
def test_ellipsoid_is_zero_on_its_surface(radii: tuple[float, float, float]) -> None:
    d = np.random.default_rng(RNG_SEED).normal(size=(2000, 3))
    p = np.asarray(radii) * d / np.linalg.norm(d, axis=-1, keepdims=True)
    np.testing.assert_allclose(ellipsoid(p, radii), 0.0, atol=1e-5)


def test_ellipsoid_is_marked_as_a_bound() -> None:
    assert CATALOG.get("sdf.ellipsoid").distance == "bound"
    assert "bound" in CATALOG.get("sdf.ellipsoid").summary


def test_ellipsoid_reference_is_the_true_distance() -> None:
    """The reference itself: exact on a sphere, and never above (yet within the sampling step
    of) the distance to a dense sampling of the surface, flat ellipsoid included."""
    p = grid((1.0, 1.0, 1.0), 8)
    np.testing.assert_allclose(
        primitives.ellipsoid_distance(p=p, radii=(1.0, 1.0, 1.0)),
        np.linalg.norm(p, axis=-1) - 1.0,
        atol=1e-12,
    )
    radii = np.array([1.0, 0.2, 0.6])
    p = np.random.default_rng(RNG_SEED).uniform(-1.5, 1.5, (60, 3)) * radii
    theta, phi = np.meshgrid(np.linspace(0, np.pi, 400), np.linspace(0, 2 * np.pi, 800))
    samples = radii * np.stack(
        [np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), np.cos(theta)], axis=-1
    ).reshape(-1, 3)
    sampled = np.array([np.linalg.norm(samples - x, axis=-1).min() for x in p])
    true = np.abs(primitives.ellipsoid_distance(p=p, radii=radii))
    assert np.all(sampled >= true - 1e-12)
    assert np.all(sampled - true <= 5e-3)  # the sampling step is ~8e-3 on the long axis


# --- smooth operators -----------------------------------------------------------------------


def smooth(function: str, a: np.ndarray, b: np.ndarray, k: float) -> np.ndarray:
    args = {"a": a.astype(np.float32), "b": b.astype(np.float32), "k": np.float32(k)}
    body = CATALOG.get("sdf.smooth_ops").body
    return np.asarray(evaluate(body, function, args, dtype=np.float32), np.float64)


# Float32 slack for comparisons with the sharp min/max computed in float64 from the same
# float32 inputs: a few ulps of values up to 2 in magnitude.
OPS_SLACK = 1e-6
# (function, sharp, direction): union rounds down from min, the others round up from max.
OPS = [
    ("opSmoothUnion", lambda a, b: np.minimum(a, b), -1.0),
    ("opSmoothIntersection", lambda a, b: np.maximum(a, b), 1.0),
    ("opSmoothSubtraction", lambda a, b: np.maximum(a, -b), 1.0),
]


@pytest.mark.parametrize("k", [0.05, 0.3, 1.0])
@pytest.mark.parametrize(("function", "sharp", "direction"), OPS, ids=[o[0] for o in OPS])
def test_smooth_operator_against_sharp(
    function: str, sharp: Callable[..., np.ndarray], direction: float, k: float
) -> None:
    """Sharp where the operands differ by k or more (for subtraction the operands are a and -b);
    inside the blend, on the rounded side of sharp by at most k/4, which is reached where
    they are equal (h = 1/2)."""
    values = np.linspace(-2.0, 2.0, 161).astype(np.float32).astype(np.float64)
    a, b = (x.ravel() for x in np.meshgrid(values, values))
    got = smooth(function, a, b, k)
    want = sharp(a, b)
    second = -b if function == "opSmoothSubtraction" else b
    apart = np.abs(a - second) >= k
    np.testing.assert_allclose(got[apart], want[apart], atol=OPS_SLACK)
    offset = direction * (got - want)  # how far toward the rounded side
    assert offset.min() >= -OPS_SLACK, "the smooth operator must not cross the sharp one"
    assert offset.max() <= k / 4 + OPS_SLACK
    tie = np.abs(a - second) == 0.0
    np.testing.assert_allclose(offset[tie], k / 4, atol=OPS_SLACK)


# --- the front-matter key ---------------------------------------------------------------------

FRONT = """/* ---
id = "sdf.thing"
slot = "sdf"
summary = "a thing"
provides = ["sdThing"]
requires = []
sources = []
{extra}
--- */
float sdThing(vec3 p) {{ return length(p) - 1.0; }}
"""


def test_distance_key_defaults_to_exact_and_is_checked() -> None:
    relpath = "snippets/sdf/thing.glsl"
    assert parse_snippet(FRONT.format(extra=""), relpath).distance == "exact"
    assert parse_snippet(FRONT.format(extra='distance = "bound"'), relpath).distance == "bound"
    with pytest.raises(InputError, match="distance"):
        parse_snippet(FRONT.format(extra='distance = "approximate"'), relpath)
