"""Where a scene's surfaces can be: an axis-aligned box around its finite objects, and its planes.

A march needs to run only where a ray can meet a surface. A ray that misses the box and every
plane hits nothing at all; one that meets them need not march before the first of them nor past
the last. `span_unit` writes that as `sceneSpan(ro, rd)`, which the bounded marchers require.

Each shape's box is taken in its own frame (from its size), then through its scale, rotation
and position (the box of the eight turned corners). Groups: a union holds its parts' boxes, an
intersection lies in each of them, a subtraction in its first part's; a smooth blend grows a
union by at most blend/4 (scene/shapes.py), taken as the whole blend. A repetition spreads its
parts' box over its copies. A plane is unbounded, and so is the user's own field unless its
[geometry] says where it lies.
"""

from __future__ import annotations

import itertools

import numpy as np

from glint.compiler.catalog.loader import glsl_value
from glint.compiler.compose.codegen.field_code import rotation_matrix
from glint.compiler.compose.codegen.trace_code import analytic
from glint.compiler.compose.units import Unit, generated
from glint.compiler.scene.shapes import (
    Box,
    Capsule,
    Cone,
    Cylinder,
    Ellipsoid,
    Group,
    Placed,
    Plane,
    Repeat,
    RoundedBox,
    Sphere,
    Torus,
)

Bounds = tuple[np.ndarray, np.ndarray]  # (lo, hi) corners
SPAN = "sceneSpan"
# Grown on every side by this share of the box's size (and at least MARGIN): a march stops a
# little short of a surface, so the box must hold the points where it stops.
MARGIN = 1e-3
# A box reaching further than this from the origin is not written: its corners (scaled,
# repeated values of a scene, each a float32) can pass float32's range, and a box of inf sides
# would cut rays wrongly. Such a scene marches the whole ray instead, as an unbounded one.
FARTHEST = 1e30


def _local(shape: Placed) -> Bounds | None:
    """The shape's box in its own frame, before its placement; None when it is unbounded."""
    if isinstance(shape, Sphere):
        half = np.full(3, shape.radius)
    elif isinstance(shape, Box | RoundedBox):
        half = np.asarray(shape.size, float)
    elif isinstance(shape, Torus):
        ring = shape.radius + shape.thickness
        half = np.array([ring, shape.thickness, ring])
    elif isinstance(shape, Capsule):
        half = np.array([shape.radius, shape.height / 2 + shape.radius, shape.radius])
    elif isinstance(shape, Cylinder):
        half = np.array([shape.radius, shape.height / 2, shape.radius])
    elif isinstance(shape, Cone):
        radius = max(shape.bottom_radius, shape.top_radius)
        half = np.array([radius, shape.height / 2, radius])
    elif isinstance(shape, Ellipsoid):
        half = np.asarray(shape.radii, float)
    elif isinstance(shape, Group):
        return _group(shape)
    elif isinstance(shape, Repeat):
        return _repeat(shape)
    else:  # a plane
        return None
    return -half, half


def _union(boxes: list[Bounds | None]) -> Bounds | None:
    if not boxes or any(b is None for b in boxes):
        return None
    los, his = zip(*boxes, strict=True)  # type: ignore[misc]
    return np.min(los, axis=0), np.max(his, axis=0)


def _group(group: Group) -> Bounds | None:
    boxes = [shape_bounds(child) for child in group.children]
    if group.shape == "union":
        found = _union(boxes)
    elif group.shape == "subtraction":
        found = boxes[0]
    else:
        finite = [b for b in boxes if b is not None]
        if not finite:
            return None
        found = np.max([b[0] for b in finite], axis=0), np.min([b[1] for b in finite], axis=0)
    if found is None:
        return None
    return found[0] - group.blend, found[1] + group.blend


def _repeat(repeat: Repeat) -> Bounds | None:
    found = _union([shape_bounds(child) for child in repeat.children])
    if found is None:
        return None
    reach = 0.5 * (np.asarray(repeat.count, float) - 1.0) * np.asarray(repeat.spacing, float)
    return found[0] - reach, found[1] + reach


def shape_bounds(shape: Placed) -> Bounds | None:
    """The shape's box in its parent's frame (after its scale, rotation and position)."""
    local = _local(shape)
    if local is None:
        return None
    lo, hi = local
    corners = np.array(list(itertools.product(*zip(lo, hi, strict=True)))) * shape.scale
    if any(shape.rotation):
        corners = corners @ np.asarray(rotation_matrix(list(shape.rotation))).T
    corners = corners + np.asarray(shape.position, float)
    return corners.min(axis=0), corners.max(axis=0)


def span_glsl(box: Bounds | None, planes: list[Placed], everywhere: bool) -> str:
    """`sceneSpan(ro, rd)`: the part (start, end) of the ray where a surface can be; end <
    start when there is none. `everywhere`: a part of the scene is unbounded (the user's field
    without bounds), so the whole ray, (0, 1e30)."""
    lines = [
        "// The part (start, end) of the ray where the scene's surfaces can be; end < start: none.",
        f"vec2 {SPAN}(vec3 ro, vec3 rd) {{",
    ]
    if everywhere:
        return "\n".join([*lines, "    return vec2(0.0, 1e30);", "}", ""])
    lines += ["    vec2 span = vec2(1e30, -1.0);"]
    if box is not None:
        size = box[1] - box[0]
        grow = np.maximum(MARGIN * size, MARGIN)
        # six digits: the margin holds the rounding
        centre = glsl_value([float(f"{x:.6g}") for x in 0.5 * (box[0] + box[1])], "vec3")
        half = glsl_value([float(f"{x:.6g}") for x in 0.5 * size + grow], "vec3")
        lines += [
            f"    vec2 inBox = boxSlabs(ro - {centre}, rd, {half});",
            "    if (inBox.x <= inBox.y && inBox.y >= 0.0) {",
            "        span = vec2(max(inBox.x, 0.0), inBox.y);",
            "    }",
        ]
    for i, plane in enumerate(planes):
        query = analytic(plane)
        assert query is not None
        lines += [
            f"    {'float ' if i == 0 else ''}toPlane = {query.trace()};",
            "    if (toPlane >= 0.0) span = vec2(min(span.x, toPlane), max(span.y, toPlane));",
        ]
    return "\n".join([*lines, "    return span;", "}", ""])


def span_unit(
    objects: list[Placed], user_field: bool, field_bounds: list[list[float]] | None = None
) -> Unit:
    """The scene's `sceneSpan` (see span_glsl): planes as they are, the rest in one box, the
    user's field (`user_field`) in its `field_bounds` when it gives them. A plane turned or
    placed so that it has no closed form leaves the whole ray to march."""
    planes = [obj for obj in objects if isinstance(obj, Plane)]
    boxes = [shape_bounds(obj) for obj in objects if not isinstance(obj, Plane)]
    if user_field and field_bounds is not None:
        boxes.append((np.asarray(field_bounds[0], float), np.asarray(field_bounds[1], float)))
        user_field = False
    box = _union(boxes)
    if box is not None and not np.abs(np.concatenate(box)).max() <= FARTHEST:  # or NaN
        box = None
    unbounded = user_field or any(analytic(p) is None for p in planes)
    unbounded = unbounded or (bool(boxes) and box is None)
    body = span_glsl(box, planes, unbounded)
    requires = [] if unbounded else (["boxSlabs"] if box is not None else [])
    requires += ["tracePlane"] if planes and not unbounded else []
    return generated(f"scene.{SPAN}", [SPAN], requires, body)
