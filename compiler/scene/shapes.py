"""The objects of a scene: primitives, each placed by a position, a rotation and a uniform
scale, and the groups that combine them (union, intersection, subtraction, sharp or smooth,
nested up to scene_values.MAX_GROUP_DEPTH levels) or repeat them on a grid.

A top-level object carries the material of everything under it; the parts of a group take
their group's. Rotation is in degrees about the x, then the y, then the z axis, all fixed
(world) axes: R = Rz · Ry · Rx. A point is placed by p' = R · (s · p_local) + position.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, model_validator

from glint.compiler.scene.values import (
    NonNegative,
    NonNegativeVec3,
    Number,
    Positive,
    PositiveVec3,
    Vec3,
    direction_problem,
    integer,
)

MAX_SUBDIVISIONS = 7  # a level-7 uv_sphere has 1024 x 512 quads: finer is no longer useful


class Strict(BaseModel):
    # A string under a field is its description: the docs site's scene reference shows it.
    model_config = ConfigDict(extra="forbid", strict=True, use_attribute_docstrings=True)


class Placed(Strict):
    """What every object has: where it is, how it is turned and how large."""

    position: Vec3 = [0.0, 0.0, 0.0]
    """Where the object's origin goes."""
    rotation: Vec3 = [0.0, 0.0, 0.0]
    """Degrees about the x, then the y, then the z axis (fixed axes)."""
    scale: Positive = 1.0
    """Uniform scale; distances stay exact (the field is scaled with the shape)."""
    material: str | None = None
    """The name of a table under [materials]; required on a top-level object, not allowed on
    the parts of a group, which take their group's."""

    @property
    def placed(self) -> bool:
        return any(self.rotation) or self.scale != 1.0 or any(self.position)


class Centred(Placed):
    """Spheres and boxes had `center` before objects had `position`: it still means that."""

    @model_validator(mode="before")
    @classmethod
    def _center_is_position(cls, data: Any) -> Any:
        if isinstance(data, dict) and "center" in data:
            if "position" in data:
                raise ValueError("give center or position, not both (they mean the same)")
            data = dict(data)
            data["position"] = data.pop("center")
        return data


class Sphere(Centred):
    shape: Literal["sphere"]
    radius: Positive = 1.0


class Box(Centred):
    shape: Literal["box"]
    size: PositiveVec3
    """Half extents along x, y and z."""


class RoundedBox(Placed):
    shape: Literal["rounded_box"]
    size: PositiveVec3
    """Half extents along x, y and z, rounding included."""
    rounding: NonNegative = 0.1
    """Radius of the rounded edges and corners, at most the smallest half extent."""

    @model_validator(mode="after")
    def _fits(self) -> RoundedBox:
        if self.rounding > min(self.size):
            raise ValueError(f"rounding {self.rounding} is larger than the smallest half extent")
        return self


class Plane(Placed):
    shape: Literal["plane"]
    normal: Vec3 = [0.0, 1.0, 0.0]
    """The plane's normal; need not be unit length."""
    offset: Number = 0.0
    """The plane is dot(p, normal) + offset = 0."""

    @model_validator(mode="after")
    def _nonzero(self) -> Plane:
        problem = direction_problem(self.normal)
        if problem is not None:
            raise ValueError(f"normal {problem}")
        return self


class Torus(Placed):
    shape: Literal["torus"]
    radius: Positive = 1.0
    """Radius of the ring (centre to the middle of the tube), in the xz plane."""
    thickness: Positive = 0.25
    """Radius of the tube."""


class Capsule(Placed):
    shape: Literal["capsule"]
    height: NonNegative = 1.0
    """Distance between the centres of the two caps, along y."""
    radius: Positive = 0.25


class Cylinder(Placed):
    shape: Literal["cylinder"]
    height: Positive = 1.0
    """Length along y, flat caps included."""
    radius: Positive = 0.5


class Cone(Placed):
    shape: Literal["cone"]
    height: Positive = 1.0
    """Length along y."""
    bottom_radius: NonNegative = 0.5
    """Radius at the bottom (y = -height / 2)."""
    top_radius: NonNegative = 0.0
    """Radius at the top (y = +height / 2); 0 for a pointed cone."""

    @model_validator(mode="after")
    def _has_width(self) -> Cone:
        if self.bottom_radius == 0.0 and self.top_radius == 0.0:
            raise ValueError("a cone needs a nonzero bottom_radius or top_radius")
        return self


class Ellipsoid(Placed):
    """Its field is a bound, not the exact distance (none has a closed form): marching stays
    correct, only slower near the surface."""

    shape: Literal["ellipsoid"]
    radii: PositiveVec3 = [1.0, 0.5, 0.75]
    """Semi-axes along x, y and z."""


class Group(Placed):
    """A combination of its parts: union (any part), intersection (every part) or subtraction
    (the first part with the others carved out)."""

    shape: Literal["union", "intersection", "subtraction"]
    children: Annotated[list[Shape], Field(min_length=1)]
    """The parts, as [[objects.children]] tables (nested: [[objects.children.children]])."""
    blend: NonNegative = 0.0
    """Radius of the smooth blend between parts (fillets, rounded cuts); 0 is a sharp edge."""


class Repeat(Placed):
    """Copies of its parts on a grid, centred on the object's position (finite repetition of
    the domain). Distances are exact while each copy stays inside its own cell."""

    shape: Literal["repeat"]
    children: Annotated[list[Shape], Field(min_length=1)]
    """The parts of one copy (their union)."""
    spacing: NonNegativeVec3
    """Distance between copies along x, y and z; 0 on an axis that is not repeated."""
    count: Annotated[list[integer(1)], Field(min_length=3, max_length=3)]
    """Copies along x, y and z (1 on an axis that is not repeated), at most 2^24 each."""

    @model_validator(mode="after")
    def _axes(self) -> Repeat:
        for axis, (gap, n) in enumerate(zip(self.spacing, self.count, strict=True)):
            if (gap == 0.0) != (n == 1):
                raise ValueError(
                    f"axis {'xyz'[axis]}: spacing {gap} and count {n} disagree (an axis is "
                    "repeated with spacing > 0 and count > 1, or not at all: 0 and 1)"
                )
        return self


class Mesh(Placed):
    """A triangle mesh, drawn by rasterizing (a mesh scene: compose with --target mesh-webgl2 or
    mesh-desktop). From a file, or a built-in shape of unit size (a sphere of radius 1, a cube
    of half extent 1, a torus of ring radius 1 and tube radius 0.25) that `scale` sizes."""

    shape: Literal["mesh"]
    file: str | None = None
    """An OBJ (or another format trimesh reads), relative to the scene file. Its vertex
    normals are used when it has them, else trimesh's smooth vertex normals."""
    builtin: Literal["uv_sphere", "icosphere", "torus", "cube"] | None = None
    """A tessellated shape with exact (analytic) normals."""
    subdivisions: integer(0, MAX_SUBDIVISIONS) = 3
    """Refinement of a built-in shape, 0 to 7: each level halves the edges (uv_sphere:
    8·2^n segments around, 4·2^n bands; icosphere: trimesh's subdivisions of an icosahedron;
    torus: 8·2^n around the ring, 4·2^n around the tube; cube: 2^n × 2^n quads a face)."""

    @model_validator(mode="after")
    def _one_source(self) -> Mesh:
        if (self.file is None) == (self.builtin is None):
            raise ValueError(
                "give file (a mesh file) or builtin (uv_sphere, icosphere, torus, cube), one "
                "of them"
            )
        if self.file is not None and "subdivisions" in self.model_fields_set:
            raise ValueError("subdivisions refines a builtin shape, not a mesh file")
        return self

    # The file's triangles (scene/mesh_files.py, MeshArrays), read when the scene is loaded.
    _arrays: Any = PrivateAttr(None)

    @property
    def arrays(self) -> Any:
        if self._arrays is None:
            raise ValueError(f"mesh file {self.file!r} was not read (load the scene with glint)")
        return self._arrays

    def keep(self, arrays: Any) -> None:
        """Keep the triangles read from the file."""
        self._arrays = arrays


Shape = Annotated[
    Sphere
    | Box
    | RoundedBox
    | Plane
    | Torus
    | Capsule
    | Cylinder
    | Cone
    | Ellipsoid
    | Group
    | Repeat
    | Mesh,
    Field(discriminator="shape"),
]
Group.model_rebuild()
Repeat.model_rebuild()

PRIMITIVES = (Sphere, Box, RoundedBox, Plane, Torus, Capsule, Cylinder, Cone, Ellipsoid)
# Shape name -> model, for error messages that must drop pydantic's union tags.
SHAPE_TAGS: dict[str, type[BaseModel]] = {
    name: model
    for model in (*PRIMITIVES, Group, Repeat, Mesh)
    for name in model.model_fields["shape"].annotation.__args__  # type: ignore[union-attr]
}


def parts(shape: Placed) -> list[Placed]:
    """The shape and everything under it, depth first."""
    found = [shape]
    for child in getattr(shape, "children", []):
        found += parts(child)
    return found


def exact(shape: Placed) -> bool:
    """Whether the shape's field is its exact distance everywhere: no ellipsoid (a bound), no
    smooth blend (a bound near the blend), no repetition (exact only inside the cells) and no
    intersection or subtraction (the max of two distances is a bound off the surface)."""
    for part in parts(shape):
        if isinstance(part, Ellipsoid | Repeat):
            return False
        if isinstance(part, Group) and (part.blend > 0.0 or part.shape != "union"):
            return False
    return True
