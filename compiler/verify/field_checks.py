"""What a scene's own distance function ([geometry]) promises and its GLSL cannot show, checked
by sampling it: a too-small `lipschitz` lets marches step through the surface (a holed
picture), and an id that `sceneMaterial` returns but `[geometry.materials]` does not map gets
another material. Both gave a wrong picture without a word.

The field is sampled on the GPU, in the composed shader itself: the user's file is any GLSL,
and glint's CPU evaluator runs only a subset of it (no unsigned integers, which hashes use).
The composed shader's own mainImage is renamed by the preprocessor and a probe's takes its
place: each pixel is one point of a grid over the scene's `bounds` (or a box around the
origin where it declares none), computed from gl_FragCoord.

The slope is measured as |d(p + h·u) − d(p)| / h along seven directions u (the axes and the
tetrahedron's four): by the definition of a Lipschitz bound each such quotient is at most the
bound, so a larger one is a measured violation, never a guess. It can only underestimate the
field's true bound (a gradient between the directions, a peak between grid points).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from glint.compiler.compose.codegen.user_geometry import DISTANCE, MATERIAL
from glint.compiler.render import render
from glint.compiler.scene.model import Scene

GRID = 24  # points per axis
STEP = 1e-3  # the finite difference, as a share of the box's diagonal
UNBOUNDED_HALF = 4.0  # half the side of the box sampled around the origin without bounds
ROUNDING = 1e-3  # float32 differences of d: a quotient this much over the bound is rounding
DIRECTIONS = [
    (1.0, 0.0, 0.0),
    (0.0, 1.0, 0.0),
    (0.0, 0.0, 1.0),
    *[tuple(c / math.sqrt(3.0) for c in v) for v in
      ((1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1))],
]  # fmt: skip


@dataclass(frozen=True)
class FieldSample:
    """What sampling found: the largest slope and where, and each material id returned near
    the surface with a point that returns it."""

    slope: float
    slope_at: tuple[float, float, float]
    ids: dict[int, tuple[float, float, float]]


def field_warnings(scene: Scene, text: str) -> list[str]:
    """The warnings for a scene's [geometry], from its composed ShaderToy code `text`; [] for
    a scene without one. Raises EnvironmentProblem where nothing can render."""
    geometry = scene.geometry
    if geometry is None:
        return []
    sample = sample_field(scene, text)
    where = geometry.path
    warnings = []
    if sample.slope > geometry.lipschitz * (1.0 + ROUNDING):
        warnings.append(
            f"{where}: the field changes by {sample.slope:.3g} per unit of distance near "
            f"{_point(sample.slope_at)}, more than lipschitz = {geometry.lipschitz:g}: marches "
            f"can step through the surface there (holes); declare lipschitz = "
            f"{math.ceil(sample.slope * 10) / 10:g} or more in [geometry] (sampling finds a "
            "lower bound of the field's slope, not its maximum)"
        )
    if geometry.materials:
        mapped = {int(key) for key in geometry.materials}
        for material_id, point in sorted(sample.ids.items()):
            if material_id not in mapped:
                warnings.append(
                    f"{where}: {MATERIAL} returns {material_id} near the surface (at "
                    f"{_point(point)}), which [geometry.materials] does not map: that part "
                    f"gets another material; map {material_id} to one"
                )
    return warnings


def sample_field(scene: Scene, text: str, grid: int = GRID) -> FieldSample:
    """Sample the scene's field over its bounds on the GPU (see the module's docstring)."""
    geometry = scene.geometry
    assert geometry is not None
    low, high = _box(scene)
    step = STEP * float(np.linalg.norm(high - low))
    cell = (high - low) / grid
    distances = _pass(text, low, cell, grid, _distances(step, DIRECTIONS[:3], centre=True))
    tilted = _pass(text, low, cell, grid, _distances(step, DIRECTIONS[3:]))
    centre = distances[:, 0]
    slopes = np.abs(np.concatenate([distances[:, 1:], tilted], axis=1) - centre[:, None])
    slopes = np.nanmax(np.where(np.isfinite(slopes), slopes, np.nan), axis=1) / step
    points = _points(low, cell, grid)
    worst = int(np.nanargmax(slopes)) if np.isfinite(slopes).any() else 0
    ids: dict[int, tuple[float, float, float]] = {}
    # Where every id maps to one material, composing prunes sceneMaterial: any id gets it.
    if geometry.materials and re.search(rf"\bint\s+{MATERIAL}\s*\(", text):
        material = _pass(text, low, cell, grid, f"vec4(float({MATERIAL}(p)), 0.0, 0.0, 1.0)")
        near = np.abs(centre) < float(np.linalg.norm(cell))  # within one cell of the surface
        for index in np.flatnonzero(near):
            ids.setdefault(int(round(material[index, 0])), _triple(points[index]))
    return FieldSample(float(np.nan_to_num(slopes[worst])), _triple(points[worst]), ids)


def _box(scene: Scene) -> tuple[np.ndarray, np.ndarray]:
    geometry = scene.geometry
    assert geometry is not None
    if geometry.bounds is not None:
        return np.array(geometry.bounds[0], float), np.array(geometry.bounds[1], float)
    return np.full(3, -UNBOUNDED_HALF), np.full(3, UNBOUNDED_HALF)


def _distances(step: float, directions: list[tuple[float, ...]], centre: bool = False) -> str:
    """The probe's result, four values: d a step along each direction, after d at p itself
    with `centre`."""
    taps = [f"{DISTANCE}(p)"] if centre else []
    taps += [
        f"{DISTANCE}(p + {step!r} * vec3({', '.join(repr(c) for c in u)}))" for u in directions
    ]
    return f"vec4({', '.join(taps)})"


def _pass(text: str, low: np.ndarray, cell: np.ndarray, grid: int, result: str) -> np.ndarray:
    """One render of the composed code with a probe's mainImage: one point per pixel, the
    grid's x and y along the picture's width and z along its height; (points, 4)."""
    vec = lambda v: f"vec3({', '.join(repr(float(c)) for c in v)})"  # noqa: E731
    probe = (
        "#define mainImage glintComposedImage\n" + text + "\n#undef mainImage\n"
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    ivec2 pixel = ivec2(fragCoord);\n"
        f"    ivec3 i = ivec3(pixel.x % {grid}, pixel.x / {grid}, pixel.y);\n"
        f"    vec3 p = {vec(low)} + (vec3(i) + 0.5) * {vec(cell)};\n"
        f"    fragColor = {result};\n"
        "}\n"
    )
    image = render(probe, grid * grid, grid)
    return image[::-1].reshape(-1, 4)  # rows from the bottom: z = 0 first


def _points(low: np.ndarray, cell: np.ndarray, grid: int) -> np.ndarray:
    """The grid's points in the order of _pass's rows: x fastest, then y, then z."""
    z, y, x = np.meshgrid(*(np.arange(grid),) * 3, indexing="ij")
    index = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    return low + (index + 0.5) * cell


def _triple(point: np.ndarray) -> tuple[float, float, float]:
    return (float(point[0]), float(point[1]), float(point[2]))


def _point(point: tuple[float, float, float]) -> str:
    return "(" + ", ".join(f"{c:.3g}" for c in point) + ")"
