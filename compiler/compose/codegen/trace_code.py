"""The closed-form ray queries of a scene made only of analytic primitives.

When every object is a sphere, an axis-aligned box or a plane, a ray's first hit, its angular
clearance from the occluders (what a soft shadow needs) and the normal at a hit all have closed
forms (the `trace` snippets), and the scene needs no marching. This writes the scene's three
queries from them, the functions the analytic variants of the raymarch, shadow and normal slots
require:

- `traceScene(ro, rd, tmax)`: the nearest hit before tmax, or -1;
- `sceneClearance(ro, rd, tmax, reach)`: the least signed angle between the ray and an
  object's outline (negative when the ray enters one), occluders beyond tmax left out; angles
  beyond `reach` (what the caller cares about) need only be known to be beyond it;
- `sceneNormal(p)`: the normal of the object whose surface p is nearest.

The same writer serves the example scenes and the float64 reference scenes of the probes
(compiler/verify/references/scenes.py), so that both run the code a composed shader runs.
"""

from __future__ import annotations

from dataclasses import dataclass

from glint.compiler.catalog.loader import glsl_float, glsl_value
from glint.compiler.compose.units import Unit, generated
from glint.compiler.scene.shapes import Box, Placed, Plane, Sphere

QUERIES = ["traceScene", "sceneClearance", "sceneNormal"]
TRACE_UNIT = "scene.trace"


@dataclass(frozen=True)
class Analytic:
    """One primitive in world space, each field a GLSL expression."""

    kind: str  # "sphere" | "box" | "plane"
    centre: str = "vec3(0.0)"  # sphere, box
    size: str = ""  # the sphere's radius, the box's half extents
    normal: str = ""  # plane: unit normal
    offset: str = ""  # plane: dot(p, normal) + offset = 0

    def _local(self, point: str) -> str:
        return point if self.centre == "vec3(0.0)" else f"{point} - {self.centre}"

    def trace(self) -> str:
        if self.kind == "plane":
            return f"tracePlane(ro, rd, {self.normal}, {self.offset})"
        name = "traceSphere" if self.kind == "sphere" else "traceBox"
        return f"{name}({self._local('ro')}, rd, {self.size})"

    def clearance(self) -> str:
        if self.kind == "plane":
            return f"clearancePlane(ro, rd, {self.normal}, {self.offset}, tmax)"
        if self.kind == "sphere":
            return f"clearanceSphere({self._local('ro')}, rd, {self.size}, tmax)"
        return f"clearanceBox({self._local('ro')}, rd, {self.size}, tmax, reach)"

    def distance(self) -> str:
        if self.kind == "plane":
            return f"sdPlane(p, {self.normal}, {self.offset})"
        name = "sdSphere" if self.kind == "sphere" else "sdBox"
        return f"{name}({self._local('p')}, {self.size})"

    def surface_normal(self) -> str:
        if self.kind == "plane":
            return self.normal
        if self.kind == "sphere":
            return f"normalize({self._local('p')})"
        return f"normalBox({self._local('p')}, {self.size})"

    def requires(self) -> list[str]:
        return {
            "sphere": ["traceSphere", "clearanceSphere", "sdSphere"],
            "box": ["traceBox", "clearanceBox", "normalBox", "sdBox"],
            "plane": ["tracePlane", "clearancePlane", "sdPlane"],
        }[self.kind]


def analytic(obj: Placed) -> Analytic | None:
    """The object as an analytic primitive, or None: a sphere wherever it is placed, a box
    moved and scaled but not turned, a plane moved or scaled but not turned."""
    scale = obj.scale
    centre = glsl_value(list(obj.position), "vec3") if any(obj.position) else "vec3(0.0)"
    if isinstance(obj, Sphere):
        return Analytic("sphere", centre, glsl_float(obj.radius * scale))
    if any(obj.rotation):
        return None
    if isinstance(obj, Box):
        return Analytic("box", centre, glsl_value([h * scale for h in obj.size], "vec3"))
    if isinstance(obj, Plane):
        length = sum(c * c for c in obj.normal) ** 0.5
        normal = [c / length for c in obj.normal]
        # dot(p − position, n) + scale·offset: the field of a moved and scaled plane
        offset = scale * obj.offset / length - sum(
            n * x for n, x in zip(normal, obj.position, strict=True)
        )
        return Analytic("plane", normal=glsl_value(normal, "vec3"), offset=glsl_float(offset))
    return None


def scene_primitives(objects: list[Placed]) -> list[Analytic] | None:
    """Every object as an analytic primitive, or None when one of them is not."""
    primitives = [analytic(obj) for obj in objects]
    if not primitives or any(p is None for p in primitives):
        return None
    return [p for p in primitives if p is not None]


def trace_glsl(primitives: list[Analytic]) -> str:
    """The three queries over `primitives` (see the module's docstring)."""
    hits = [f"    t = nearestHit(t, {p.trace()});" for p in primitives]
    clear = [f"    c = min(c, {p.clearance()});" for p in primitives[1:]]
    normal = [
        f"    float best = abs({primitives[0].distance()});",
        f"    vec3 n = {primitives[0].surface_normal()};",
    ]
    for i, p in enumerate(primitives[1:], start=1):
        normal += [
            f"    float d{i} = abs({p.distance()});",
            f"    if (d{i} < best) {{ best = d{i}; n = {p.surface_normal()}; }}",
        ]
    return "\n".join(
        [
            "// The nearer of two hits, where -1 is none.",
            "float nearestHit(float t, float hit) {",
            "    return hit >= 0.0 && (t < 0.0 || hit < t) ? hit : t;",
            "}",
            "",
            "// The first hit of the ray before tmax among the scene's objects, or -1.",
            "float traceScene(vec3 ro, vec3 rd, float tmax) {",
            "    float t = -1.0;",
            *hits,
            "    return t <= tmax ? t : -1.0;",
            "}",
            "",
            "// The least signed angle between the ray and an object's outline (negative inside);",
            "// angles past reach need not be exact.",
            "float sceneClearance(vec3 ro, vec3 rd, float tmax, float reach) {",
            f"    float c = {primitives[0].clearance()};",
            *clear,
            "    return c;",
            "}",
            "",
            "// The normal of the object whose surface p lies on (the least |distance|).",
            "vec3 sceneNormal(vec3 p) {",
            *normal,
            "    return n;",
            "}",
            "",
        ]
    )


def trace_requires(primitives: list[Analytic]) -> list[str]:
    return sorted({name for p in primitives for name in p.requires()})


def trace_unit(objects: list[Placed]) -> Unit | None:
    """The scene's closed-form queries, or None when an object is not analytic (or there is a
    field of the user's own)."""
    primitives = scene_primitives(objects)
    if primitives is None:
        return None
    return generated(
        TRACE_UNIT, [*QUERIES, "nearestHit"], trace_requires(primitives), trace_glsl(primitives)
    )
