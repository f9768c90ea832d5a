"""Toon bands and rim fall where the formulas say (snippets/diffuse/toon.glsl), on a finely
tessellated sphere under phong shading and one directional light.

The band risers are smoothsteps over fract(N·x) in [1 − s, 1], so the middle of the k-th riser
(halfway between two levels) is at N·L = (k + 1 − s/2) / N; the rim's edge is where
(1 − N·V)·(N·L)^p = e. N·L and N·V at each pixel are computed here independently of the
renderer: the pixel's ray from the camera model that compiler/compose/mesh/camera.py documents
(normalize(uv.x·right + uv.y·up + focal·forward), uv = (2·fragCoord − iResolution.xy) /
iResolution.y), intersected with the exact unit sphere. The rendered image's edges (where
the luminance jumps between neighbouring pixels) must lie within two pixels of those contours,
and every contour must have its edge.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glint
from glint.compiler.catalog.loader import load_catalog

pytestmark = pytest.mark.render

SIZE = 256  # square: uv spans [-1, 1] both ways
EYE = np.array([0.0, 0.0, 4.0])
FOCAL = 3.0  # the sphere's silhouette about 99 pixels in radius
LIGHT = np.array([1.0, 0.6, 0.8]) / np.linalg.norm([1.0, 0.6, 0.8])
TOLERANCE_PX = 2.0
JUMP = 0.01  # linear luminance between neighbours: a riser step is ~0.03, shading drift < 0.003


def _toon() -> dict[str, float]:
    return {name: p.default for name, p in load_catalog().get("diffuse.toon").params.items()}


def _scene() -> dict[str, Any]:
    sphere = {"shape": "mesh", "builtin": "uv_sphere", "subdivisions": 6, "material": "toon"}
    return {
        "name": "toon bands",
        "camera": {"type": "lookat", "position": EYE.tolist(), "focal": FOCAL},
        "objects": [sphere],
        # fully rough: the specular lobe is a faint smooth sheen with no edge of its own
        "materials": {
            "toon": {"albedo": [0.8, 0.8, 0.8], "roughness": 1.0, "models": {"diffuse": "toon"}}
        },
        "lights": [{"type": "directional", "direction": LIGHT.tolist(), "shadow": False}],
        "mesh": {"shading": "phong"},
        "environment": {"reflection": False},
        "effects": {"ao": False},
        "post": {"tonemap": "none", "output": "gamma22"},
    }


def _analytic() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """N·L, N·V and the sphere's mask per pixel (row 0 at the top), from the camera's rays."""
    forward = -EYE / np.linalg.norm(EYE)
    right = np.cross(forward, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    centres = np.arange(SIZE) + 0.5
    x = (2.0 * centres - SIZE) / SIZE
    y = (2.0 * (SIZE - centres) - SIZE) / SIZE  # fragCoord.y counts from the bottom
    u, v = np.meshgrid(x, y)
    rays = u[..., None] * right + v[..., None] * up + FOCAL * forward
    rays /= np.linalg.norm(rays, axis=-1, keepdims=True)
    b = rays @ EYE
    disc = b * b - (EYE @ EYE - 1.0)
    mask = disc > 0.0
    t = -b - np.sqrt(np.maximum(disc, 0.0))
    normal = EYE + t[..., None] * rays
    return normal @ LIGHT, -(normal * rays).sum(-1), mask


def _pixel_distance(field: np.ndarray, level: float) -> np.ndarray:
    """How many pixels each pixel is from the contour field = level (first order)."""
    gy, gx = np.gradient(field)
    return np.abs(field - level) / np.maximum(np.hypot(gx, gy), 1e-9)


def _edges(linear: np.ndarray) -> np.ndarray:
    """Where the luminance steps: pixels whose central-difference gradient exceeds JUMP and
    is the largest of the pixel and its two neighbours across the step (a one-pixel ridge
    along the middle of each riser)."""
    lum = linear.mean(axis=-1)
    gy, gx = np.gradient(lum)
    size = np.hypot(gx, gy)
    across_x = np.abs(gx) >= np.abs(gy)
    padded = np.pad(size, 1)
    left, right = padded[1:-1, :-2], padded[1:-1, 2:]
    above, below = padded[:-2, 1:-1], padded[2:, 1:-1]
    ridge = np.where(across_x, (size >= left) & (size >= right), (size >= above) & (size >= below))
    return (size > JUMP) & ridge


Contour = tuple[np.ndarray, np.ndarray]  # per pixel: distance to it (pixels); sharp enough


def _contours(bands: float, riser: float, rim_edge: float, rim_power: float) -> list[Contour]:
    """The band risers' middles at N·L = (k + 1 − riser) / bands, then the rim's edge: per
    pixel its distance to the contour in pixels, and whether the riser is steep enough there
    to be seen as an edge. A riser is a smoothstep over TOON_SOFTNESS / bands of N·L: near
    N·L = 1, where N·L hardly changes across the screen, it spreads over many pixels and
    steps by less than JUMP between neighbours (the top band's riser, 0.967 to 1, is one)."""
    nol, nov, _ = _analytic()
    gy, gx = np.gradient(nol)
    steepest = 1.5 * 0.8 / np.pi * np.hypot(gx, gy) / (2.0 * riser)  # step / riser, in pixels
    found = [
        (_pixel_distance(nol, (k + 1.0 - riser) / bands), steepest > 3.0 * JUMP)
        for k in range(int(bands))
    ]
    rim = (1.0 - np.clip(nov, 1e-4, 1.0)) * np.maximum(nol, 1e-6) ** rim_power
    found.append((_pixel_distance(rim, rim_edge), np.ones_like(nol, dtype=bool)))
    return found


@pytest.fixture(scope="module")
def rendered_edges() -> tuple[np.ndarray, np.ndarray]:
    """The rendered image's edges, and the pixels checked: the sphere, less three pixels at
    its silhouette (the mesh's polygon and the sky's edge)."""
    image = glint.render(glint.compose_mesh(_scene()), size=(SIZE, SIZE))
    assert image.finite
    linear = np.clip(image.pixels, 0.0, 1.0) ** 2.2  # undo output.gamma22; tonemap none
    _, nov, mask = _analytic()
    inside = mask & (_pixel_distance(np.where(mask, nov, 0.0), 0.0) > 3.0)
    return _edges(linear) & inside, inside


def _misplaced(
    edges: np.ndarray, inside: np.ndarray, contours: list[Contour]
) -> tuple[float, list[float]]:
    """The share of edge pixels farther than TOLERANCE_PX from every contour, and per contour
    the share of its steep enough pixels (inside) with no edge pixel within TOLERANCE_PX."""
    near_any = np.zeros_like(edges)
    for distance, _ in contours:
        near_any |= distance <= TOLERANCE_PX
    stray = float((edges & ~near_any).sum() / max(edges.sum(), 1))
    # an edge within TOLERANCE_PX of each contour pixel: grow the edges by that many pixels
    reach = int(np.ceil(TOLERANCE_PX))
    grown = edges.copy()
    for dy in range(-reach, reach + 1):
        for dx in range(-reach, reach + 1):
            if dy * dy + dx * dx <= TOLERANCE_PX**2:
                grown |= np.roll(np.roll(edges, dy, axis=0), dx, axis=1)
    missed = []
    for distance, sharp in contours:
        on = inside & sharp & (distance <= 0.5)
        if on.sum() >= 20:  # a contour that crosses the checked part of the sphere
            missed.append(float((on & ~grown).sum() / on.sum()))
    return stray, missed


def test_toon_bands_and_rim_fall_where_the_formulas_say(
    rendered_edges: tuple[np.ndarray, np.ndarray],
) -> None:
    toon = _toon()
    contours = _contours(
        toon["TOON_BANDS"],
        toon["TOON_SOFTNESS"] / 2.0,
        toon["TOON_RIM_EDGE"],
        toon["TOON_RIM_POWER"],
    )
    edges, inside = rendered_edges
    assert edges.sum() > 300  # three band boundaries and a rim, each a curve across the sphere
    stray, missed = _misplaced(edges, inside, contours)
    assert len(missed) == 3  # two band edges and the rim (the top band's riser is too gentle)
    assert stray < 0.01, f"{stray:.1%} of the edge pixels are on no contour"
    assert max(missed) < 0.05, f"share of each contour with no edge near it: {missed}"


@pytest.mark.parametrize(
    "moved",
    [
        {"riser": 0.5},  # band edges halfway through the step, not at the top of fract
        {"bands": 4.0},  # one band more than the snippet draws
        {"rim_edge": 0.5},  # the rim where (1 - N.V)(N.L)^p = 0.5, not TOON_RIM_EDGE
    ],
    ids=["riser", "bands", "rim_edge"],
)
def test_the_check_fails_when_a_contour_is_moved(
    rendered_edges: tuple[np.ndarray, np.ndarray], moved: dict[str, float]
) -> None:
    toon = _toon()
    formula = {
        "bands": toon["TOON_BANDS"],
        "riser": toon["TOON_SOFTNESS"] / 2.0,
        "rim_edge": toon["TOON_RIM_EDGE"],
        "rim_power": toon["TOON_RIM_POWER"],
    }
    edges, inside = rendered_edges
    stray, missed = _misplaced(edges, inside, _contours(**(formula | moved)))
    assert stray >= 0.01 or max(missed) >= 0.05, (stray, missed)
