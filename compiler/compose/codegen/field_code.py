"""GLSL for the distance of one scene object: its primitive in its own frame, placed by its
position, rotation and scale, and combined with others by its groups.

A point enters an object's frame as q = Rᵀ · (p − position) / scale, and the distance leaves it
multiplied by the scale: a uniform scale keeps a distance a distance. The rotation is worked
out here, in Python, so the shader holds a constant matrix and no trigonometry.

An unplaced sphere, box or plane is written inline in `map` (as scenes were before objects
could be placed); anything else gets a function of its own, `objectN(p)`, which `map` and
`materialAt` both call.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from glint.compiler.catalog.loader import glsl_float, glsl_value
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


@dataclass
class ObjectCode:
    expression: str  # the distance at `p`
    requires: list[str]
    name: str = ""  # `objectN`, when the object has a function of its own
    function: str = ""  # that function's definition


def object_code(obj: Placed, index: int) -> ObjectCode:
    """The distance of the top-level object `index` at the point `p`."""
    inline = _inline(obj)
    if inline is not None:
        return inline
    writer = _Writer()
    result = writer.distance(obj, "p")
    name = f"object{index}"
    lines = [f"// objects[{index}]: {_describe(obj)}.", f"float {name}(vec3 p) {{"]
    lines += [f"    {line}" for line in writer.lines]
    lines += [f"    return {result};", "}"]
    return ObjectCode(f"{name}(p)", sorted(writer.requires), name, "\n".join(lines) + "\n")


def _inline(obj: Placed) -> ObjectCode | None:
    """The forms `map` has always written for unrotated, unscaled spheres, boxes and planes."""
    if any(obj.rotation) or obj.scale != 1.0:
        return None
    if isinstance(obj, Sphere):
        call = f"sdSphere({_offset(obj.position)}, {glsl_float(obj.radius)})"
        return ObjectCode(call, ["sdSphere"])
    if isinstance(obj, Box):
        return ObjectCode(f"sdBox({_offset(obj.position)}, {_vec3(obj.size)})", ["sdBox"])
    if isinstance(obj, Plane) and not any(obj.position):
        normal, offset = _plane(obj)
        return ObjectCode(f"sdPlane(p, {normal}, {offset})", ["sdPlane"])
    return None


@dataclass
class _Writer:
    """The lines of an object's function: one local point per placed part, one distance per
    group."""

    lines: list[str] = field(default_factory=list)
    requires: set[str] = field(default_factory=set)
    points: int = 0
    distances: int = 0

    def distance(self, shape: Placed, p: str) -> str:
        q = self._point(shape, p)
        d = self._local(shape, q)
        return f"{d} * {glsl_float(shape.scale)}" if shape.scale != 1.0 else d

    def _point(self, shape: Placed, p: str) -> str:
        if not shape.placed:
            return p
        expr = _offset(shape.position, p)
        if any(shape.rotation):
            expr = f"{_inverse_rotation(shape.rotation)} * ({expr})"
        if shape.scale != 1.0:
            expr = f"({expr}) / {glsl_float(shape.scale)}"
        self.points += 1
        name = f"q{self.points}"
        self.lines.append(f"vec3 {name} = {expr};")
        return name

    def _local(self, shape: Placed, q: str) -> str:
        if isinstance(shape, Group):
            return self._group(shape, q)
        if isinstance(shape, Repeat):
            self.points += 1
            cell = f"q{self.points}"
            spacing = _vec3(shape.spacing)
            count = _vec3([float(n) for n in shape.count])
            self.lines.append(f"vec3 {cell} = opRepeat({q}, {spacing}, {count});")
            self.requires.add("opRepeat")
            return self._combine("min", "", [self.distance(c, cell) for c in shape.children])
        call, function = _primitive(shape, q)
        self.requires.add(function)
        return call

    def _group(self, group: Group, q: str) -> str:
        terms = [self.distance(child, q) for child in group.children]
        if group.blend == 0.0:
            sharp = {"union": "min", "intersection": "max", "subtraction": "carve"}[group.shape]
            return self._combine(sharp, "", terms)
        smooth = {"union": "opSmoothUnion", "intersection": "opSmoothIntersection",
                  "subtraction": "opSmoothSubtraction"}[group.shape]  # fmt: skip
        self.requires.add(smooth)
        return self._combine(smooth, glsl_float(group.blend), terms)

    def _combine(self, how: str, blend: str, terms: list[str]) -> str:
        """Fold the terms left to right into one local distance."""
        if len(terms) == 1:
            return terms[0]
        self.distances += 1
        name = f"d{self.distances}"
        self.lines.append(f"float {name} = {terms[0]};")
        for term in terms[1:]:
            if how == "carve":
                combined = f"max({name}, -({term}))"
            elif blend:
                combined = f"{how}({name}, {term}, {blend})"
            else:
                combined = f"{how}({name}, {term})"
            self.lines.append(f"{name} = {combined};")
        return name


def _primitive(shape: Placed, q: str) -> tuple[str, str]:
    """The call of the primitive's distance in its own frame, and the function it calls."""
    f = glsl_float
    if isinstance(shape, Sphere):
        return f"sdSphere({q}, {f(shape.radius)})", "sdSphere"
    if isinstance(shape, Box):
        return f"sdBox({q}, {_vec3(shape.size)})", "sdBox"
    if isinstance(shape, RoundedBox):
        return f"sdRoundBox({q}, {_vec3(shape.size)}, {f(shape.rounding)})", "sdRoundBox"
    if isinstance(shape, Plane):
        normal, offset = _plane(shape)
        return f"sdPlane({q}, {normal}, {offset})", "sdPlane"
    if isinstance(shape, Torus):
        return f"sdTorus({q}, {f(shape.radius)}, {f(shape.thickness)})", "sdTorus"
    if isinstance(shape, Capsule):
        return f"sdCapsule({q}, {f(shape.height / 2)}, {f(shape.radius)})", "sdCapsule"
    if isinstance(shape, Cylinder):
        call = f"sdCappedCylinder({q}, {f(shape.radius)}, {f(shape.height / 2)})"
        return call, "sdCappedCylinder"
    if isinstance(shape, Cone):
        radii = f"{f(shape.bottom_radius)}, {f(shape.top_radius)}"
        return f"sdCappedCone({q}, {f(shape.height / 2)}, {radii})", "sdCappedCone"
    if isinstance(shape, Ellipsoid):
        return f"sdEllipsoid({q}, {_vec3(shape.radii)})", "sdEllipsoid"
    raise TypeError(f"not a primitive: {shape!r}")


def _plane(plane: Plane) -> tuple[str, str]:
    length = sum(c * c for c in plane.normal) ** 0.5
    normal = [c / length for c in plane.normal]
    return _vec3(normal), glsl_float(plane.offset / length)


def _describe(obj: Placed) -> str:
    shape = str(getattr(obj, "shape", "object"))
    children = getattr(obj, "children", None)
    if children:
        return f"{shape} of " + ", ".join(str(getattr(c, "shape", "?")) for c in children)
    return shape


def _vec3(v: list[float]) -> str:
    return glsl_value(v, "vec3")


def _offset(position: list[float], p: str = "p") -> str:
    return p if not any(position) else f"{p} - {_vec3(position)}"


def rotation_matrix(degrees: list[float]) -> list[list[float]]:
    """R = Rz · Ry · Rx for rotations in degrees about the fixed x, y and z axes (rows)."""
    ax, ay, az = (math.radians(a) for a in degrees)
    cx, sx, cy, sy, cz, sz = (math.cos(ax), math.sin(ax), math.cos(ay), math.sin(ay),
                              math.cos(az), math.sin(az))  # fmt: skip
    rx = [[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]]
    ry = [[cy, 0.0, sy], [0.0, 1.0, 0.0], [-sy, 0.0, cy]]
    rz = [[cz, -sz, 0.0], [sz, cz, 0.0], [0.0, 0.0, 1.0]]
    return _product(rz, _product(ry, rx))


def _product(a: list[list[float]], b: list[list[float]]) -> list[list[float]]:
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def _inverse_rotation(degrees: list[float]) -> str:
    """Rᵀ as a GLSL mat3 (column-major: its columns are R's rows)."""
    rows = rotation_matrix(degrees)
    clean = [[_tidy(x) for x in row] for row in rows]
    # Rᵀ's column j is R's row j
    return "mat3(" + ", ".join(glsl_float(x) for row in clean for x in row) + ")"


def _tidy(x: float) -> float:
    """Nine decimals (far below float32's resolution), and no -0.0 or 1e-17 for a zero."""
    x = round(x, 9)
    return 0.0 if x == 0.0 else x
