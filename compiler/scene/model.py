"""The scene description: TOML in, a validated model out, or one error naming the key path.

A scene says what is in the picture (camera, SDF objects, materials, lights, environment,
effects, post) and how much accuracy to pay for (quality). Nothing in it executes code.
"""

from __future__ import annotations

import math
import re
import tomllib
from collections.abc import Mapping
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, Field, PrivateAttr, ValidationError, model_validator

from glint.compiler.errors import InputError, UsageError
from glint.compiler.files import MiB, read_user_text
from glint.compiler.scene.shapes import SHAPE_TAGS, Mesh, Shape, Strict, exact, parts
from glint.compiler.scene.values import (
    DIRECTION_RANGE,
    AtLeastOne,
    Color,
    ConeAngle,
    FieldOfView,
    NonNegative,
    Number,
    Positive,
    PositiveVec3,
    Radiometric,
    SignedUnit,
    Unit,
    Vec3,
    direction_problem,
    integer,
    key_path,
    nesting_problem,
    shown,
)

# The largest files a scene reads: its own TOML and a [geometry] GLSL file (a scene or a
# distance function of a few MiB is already far beyond what anyone writes by hand).
SCENE_FILE_LIMIT = 4 * MiB
GEOMETRY_FILE_LIMIT = 4 * MiB


# The lens of every camera, with the meaning the site's scene reference shows.
Focal = Annotated[
    Positive,
    Field(
        description="Distance from the eye to a screen two units tall (1.5 sees 67.4° from the "
        "bottom of the picture to its top): larger zooms in. `fov` sets it by the angle instead."
    ),
]
FieldOfViewKey = Annotated[
    FieldOfView | None,
    Field(
        description="Vertical field of view in degrees, bottom to top of the picture; replaces "
        "focal (focal = 1 / tan(fov / 2))."
    ),
]
Roll = Annotated[
    Number,
    Field(
        description="Turns the picture about the line of sight, in degrees (positive turns it "
        "clockwise)."
    ),
]


def _fov_sets_focal(camera: OrbitCamera | LookAtCamera | PathCamera) -> None:
    """A camera given by its field of view gets the focal length it stands for: everything
    downstream reads `focal`. Given both, they must agree."""
    if camera.fov is None:
        return
    focal = 1.0 / math.tan(math.radians(camera.fov) / 2.0)
    if "focal" in camera.model_fields_set and abs(camera.focal - focal) > 1e-6 * focal:
        raise ValueError(
            f"focal {camera.focal:g} and fov {camera.fov:g} disagree (fov {camera.fov:g} is "
            f"focal {focal:.6g}); give one of them"
        )
    camera.focal = focal


class OrbitCamera(Strict):
    type: Literal["orbit"]
    target: Vec3 = [0.0, 0.0, 0.0]
    """The point the camera looks at and circles."""
    radius: Positive = 3.0
    """Distance from the target, in the ground plane."""
    height: Number = 1.5
    """Height of the camera above the target."""
    speed: Number = 0.3
    """Radians per second of the orbit (0 holds still)."""
    start: Number = 0.0
    """The orbit's angle at iTime = 0, in degrees: 0 puts the eye on +x, 90 on +z."""
    focal: Focal = 1.5
    fov: FieldOfViewKey = None
    roll: Roll = 0.0

    @model_validator(mode="after")
    def _eye_apart(self) -> OrbitCamera:
        _check_line_of_sight([self.radius, self.height, 0.0], self.target, "radius and height")
        _fov_sets_focal(self)
        return self


class LookAtCamera(Strict):
    type: Literal["lookat"]
    position: Vec3 = [0.0, 1.0, 4.0]
    """Where the camera stands."""
    target: Vec3 = [0.0, 0.0, 0.0]
    """The point it looks at."""
    focal: Focal = 1.5
    fov: FieldOfViewKey = None
    roll: Roll = 0.0

    @model_validator(mode="after")
    def _distinct(self) -> LookAtCamera:
        _fov_sets_focal(self)
        if self.position == self.target:
            raise ValueError("position and target must differ")
        sight = [t - p for p, t in zip(self.position, self.target, strict=True)]
        _check_line_of_sight(sight, [*self.position, *self.target], "position and target")
        return self


class PathKey(Strict):
    """Where the camera is at one moment of its path."""

    time: NonNegative
    """Seconds of iTime."""
    position: Vec3
    """Where the eye is."""
    target: Vec3 = [0.0, 0.0, 0.0]
    """The point it looks at."""


class PathCamera(Strict):
    """A camera flown through keyframes: a smooth curve (Catmull-Rom) through the keys'
    positions and targets, at the keys' times."""

    type: Literal["path"]
    keys: Annotated[list[PathKey], Field(min_length=2, max_length=64)]
    """The keyframes, at increasing times, as [[camera.keys]] tables."""
    loop: bool = False
    """After the last key, start again from the first (the curve closes through it); else the
    camera holds at the last key."""
    focal: Focal = 1.5
    fov: FieldOfViewKey = None
    roll: Roll = 0.0

    @model_validator(mode="after")
    def _keys(self) -> PathCamera:
        _fov_sets_focal(self)
        times = [key.time for key in self.keys]
        for i, (a, b) in enumerate(zip(times, times[1:], strict=False)):
            if b <= a:
                raise ValueError(
                    f"keys[{i + 1}].time: {b:g} is not after keys[{i}].time {a:g}; give the keys "
                    "in the order the camera passes them, each later than the one before"
                )
        for i, key in enumerate(self.keys):
            if key.position == key.target:
                raise ValueError(f"keys[{i}]: position and target must differ")
            sight = [t - p for p, t in zip(key.position, key.target, strict=True)]
            _check_line_of_sight(sight, [*key.position, *key.target], f"keys[{i}]")
        return self


# float32 tells two points apart when they are at least this share of their distance from the
# origin apart (its precision is 6e-8: the line of sight is then good to a few per cent)
_SIGHT_PRECISION = 1e-6


def _check_line_of_sight(sight: list[float], points: list[float], keys: str) -> None:
    """The camera's line of sight (from the eye to the target) must be a direction the shader
    can normalise, and the eye a point float32 tells apart from the target."""
    length = max(abs(x) for x in sight)
    far = max((abs(x) for x in points), default=0.0)
    if length < far * _SIGHT_PRECISION:
        raise ValueError(
            f"{keys}: the eye is {length:g} from the target, {far:g} from the origin: too "
            "close for float32, which then sees one point; move the eye further from the "
            f"target (at least {far * _SIGHT_PRECISION:g})"
        )
    low, high = DIRECTION_RANGE
    if not low <= length <= high:
        raise ValueError(
            f"{keys}: the eye is {length:g} from the target (along an axis), too "
            f"{'close' if length < low else 'far'} for float32 to normalise the line of sight "
            f"{shown(sight)}; keep them between {low:g} and {high:g} apart"
        )


ShadingMode = Literal["gouraud", "phong", "flat"]


class Material(Strict):
    albedo: Color
    """Base colour, linear RGB."""
    roughness: Unit = 0.5
    """Perceptual roughness: 0 is a mirror, 1 fully rough."""
    metallic: Unit = 0.0
    """0 for a dielectric, 1 for a metal whose albedo tints its reflection."""
    pattern: Literal["none", "checker"] = "none"
    """A procedural pattern mixing albedo and pattern_albedo."""
    pattern_albedo: Color | None = None
    """The second colour of a pattern."""
    diffuse_roughness: Unit | None = None
    """Oren-Nayar's σ, the slope deviation of the diffuse microfacets in radians (0 is Lambert);
    the rough-diffuse variants read it. Absent: the specular roughness stands in for it."""
    subsurface: Color | None = None
    """Light that passes through the body and scatters toward the eye (translucency), per
    channel: the interior's scattering colour. Absent: the material is opaque."""
    albedo_texture: integer(0, 3) | None = None  # type: ignore[valid-type]
    """A picture on ShaderToy channel N (0 to 3) wrapped onto the surface by triplanar mapping,
    its sRGB decoded to linear: the albedo is the picture's colour times `albedo`. Bind the
    picture in ShaderToy, or render with `glint render --channel N=picture.png`."""
    texture_scale: Positive = 1.0
    """The world size of one repeat of the picture."""
    emission: Color | None = None
    """Light the surface gives off itself, linear RGB added after lighting (a lamp's shade, a
    screen, lava): unlit and unshadowed, and seen in reflections."""
    subsurface_g: SignedUnit = 0.5
    """Asymmetry g of the interior's phase function: > 0 scatters forward (glows when back-lit)."""
    shading: ShadingMode | None = None
    """Mesh scenes only: where the light is computed on this material's meshes (gouraud: per
    vertex; phong: per pixel from interpolated normals; flat: per pixel from the face's
    normal). Absent: [mesh] shading."""
    models: dict[str, str] = {}
    """Mesh scenes only: lighting models of this material's program, slot = variant, e.g.
    { diffuse = "toon", specular = "phong" }; they replace the tier's and [quality.variants]."""

    @model_validator(mode="after")
    def _pattern(self) -> Material:
        if self.pattern != "none" and self.albedo_texture is not None:
            raise ValueError("give a pattern or an albedo_texture, not both")
        if self.pattern != "none" and self.pattern_albedo is None:
            raise ValueError(f"pattern '{self.pattern}' needs pattern_albedo, a second colour")
        return self


class DirectionalLight(Strict):
    type: Literal["directional"]
    direction: Vec3
    """Toward the light."""
    color: Color = [1.0, 1.0, 1.0]
    """Linear RGB."""
    intensity: Radiometric = 1.0
    """Multiplies the colour."""
    shadow: bool = True
    """Whether it casts shadows (the `shadow` slot)."""
    shadow_distance: Positive = 5.0
    """How far a shadow ray looks for an occluder."""
    penumbra: PositiveVec3 | None = None
    """Per-channel exponents applied to the shadow, e.g. [1.0, 1.2, 1.5]: penumbrae turn cool."""

    @model_validator(mode="after")
    def _nonzero(self) -> DirectionalLight:
        _check_direction(self.direction)
        return self


def _check_direction(direction: list[float] | None) -> None:
    problem = direction_problem(direction) if direction is not None else None
    if problem is not None:
        raise ValueError(f"direction {problem}")


class PointLight(Strict):
    type: Literal["point"]
    position: Vec3
    """Where the light is."""
    color: Color = [1.0, 1.0, 1.0]
    intensity: Radiometric = 1.0
    range: Positive = 10.0
    """Where the attenuation reaches zero (for the attenuation variants that have a range)."""
    shadow: bool = True
    """Whether it casts shadows (the `shadow` slot)."""


class SpotLight(Strict):
    """A point light that shines into a cone: full inside `inner`, none outside `outer`."""

    type: Literal["spot"]
    position: Vec3
    """Where the light is."""
    direction: Vec3 | None = None
    """The way it shines (from the light into the scene), e.g. [0, -1, 0] for straight down."""
    target: Vec3 | None = None
    """A point it shines at, instead of `direction`."""
    color: Color = [1.0, 1.0, 1.0]
    intensity: Radiometric = 1.0
    """Multiplies the colour, as a point light's (on the cone's axis it is one)."""
    inner: ConeAngle = 20.0
    """Half-angle of the full-strength cone, degrees from the axis."""
    outer: ConeAngle = 30.0
    """Half-angle where the light reaches zero, degrees from the axis."""
    range: Positive = 10.0
    """Where the attenuation reaches zero (for the attenuation variants that have a range)."""
    shadow: bool = True
    """Whether it casts shadows (the `shadow` slot)."""

    @model_validator(mode="after")
    def _aim(self) -> SpotLight:
        if (self.direction is None) == (self.target is None):
            raise ValueError("give direction (the way it shines) or target (a point), one of them")
        if self.target is not None:
            if self.target == self.position:
                raise ValueError("target: the point it shines at must not be its position")
            self.direction = [t - p for p, t in zip(self.position, self.target, strict=True)]
            self.target = None
        _check_direction(self.direction)
        if self.inner > self.outer:
            raise ValueError(
                f"inner {self.inner:g} is wider than outer {self.outer:g}; the full-strength "
                "cone lies inside the outer one"
            )
        return self


class _AreaLight(Strict):
    """What every area light has. Its `intensity` is that of the point light it looks like
    from far away (the same units as a point light's): the surface's radiance is the
    intensity over its (projected) area."""

    position: Vec3
    """The light's centre."""
    color: Color = [1.0, 1.0, 1.0]
    intensity: Radiometric = 1.0
    """Multiplies the colour: a point light's intensity, spread over the light's area."""
    shadow: bool = True
    """Whether it casts shadows (the `shadow` slot, softened by the light's size)."""


class SphereLight(_AreaLight):
    """A glowing ball (a bulb): it shines every way."""

    type: Literal["sphere"]
    radius: Positive = 0.25


class DiscLight(_AreaLight):
    """A glowing disc that shines from one face (a ceiling lamp, a softbox)."""

    type: Literal["disc"]
    direction: Vec3 = [0.0, -1.0, 0.0]
    """The way its lit face looks (from the light into the scene)."""
    radius: Positive = 0.5

    @model_validator(mode="after")
    def _nonzero(self) -> DiscLight:
        _check_direction(self.direction)
        return self


class RectLight(_AreaLight):
    """A glowing rectangle that shines from one face (a window, a panel)."""

    type: Literal["rect"]
    direction: Vec3 = [0.0, -1.0, 0.0]
    """The way its lit face looks (from the light into the scene)."""
    size: Annotated[list[Positive], Field(min_length=2, max_length=2)] = [1.0, 1.0]
    """Width and height."""
    up: Vec3 | None = None
    """Which way its height runs (made perpendicular to direction); by default the world's y,
    or z for a rectangle facing straight up or down."""

    @model_validator(mode="after")
    def _nonzero(self) -> RectLight:
        _check_direction(self.direction)
        if self.up is not None:
            problem = direction_problem(self.up)
            if problem is not None:
                raise ValueError(f"up {problem}")
            if _parallel(self.up, self.direction):
                raise ValueError("up is along direction; it must say which way the height runs")
        return self


def _parallel(a: list[float], b: list[float]) -> bool:
    cross = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    scale = math.sqrt(sum(x * x for x in a) * sum(x * x for x in b))
    return math.sqrt(sum(x * x for x in cross)) <= 1e-6 * scale


AREA_LIGHTS = (SphereLight, DiscLight, RectLight)


class SkyLight(Strict):
    type: Literal["sky"]
    color: Color = [0.2, 0.5, 1.0]
    """Colour of the light from the sky above."""
    intensity: Radiometric = 1.0


class BackLight(Strict):
    type: Literal["back"]
    direction: Vec3 | None = None
    """Toward the light; by default the key light's direction mirrored and made horizontal."""
    color: Color = [0.15, 0.1, 0.08]
    intensity: Radiometric = 1.0

    @model_validator(mode="after")
    def _nonzero(self) -> BackLight:
        _check_direction(self.direction)
        return self


class BounceLight(Strict):
    type: Literal["bounce"]
    direction: Vec3 | None = None
    """Toward the light; by default the key light's direction mirrored and made horizontal."""
    color: Color = [0.40, 0.28, 0.20]
    intensity: Radiometric = 1.0

    @model_validator(mode="after")
    def _nonzero(self) -> BounceLight:
        _check_direction(self.direction)
        return self


class EnvironmentLight(Strict):
    """Diffuse light from the scene's environment, by the `irradiance` slot's variant."""

    type: Literal["environment"]
    intensity: Radiometric = 1.0


Light = Annotated[
    DirectionalLight
    | PointLight
    | SpotLight
    | SphereLight
    | DiscLight
    | RectLight
    | SkyLight
    | BackLight
    | BounceLight
    | EnvironmentLight,
    Field(discriminator="type"),
]
Camera = Annotated[OrbitCamera | LookAtCamera | PathCamera, Field(discriminator="type")]


class Geometry(Strict):
    """The user's own distance function, written in GLSL: glint lights it. The file defines
    `float sceneDistance(vec3 p)`, the signed distance to the surface (or a field whose
    gradient is at most `lipschitz` long); optionally `int sceneMaterial(vec3 p)`, the id of the
    material at p (a key of `materials`), and `vec3 sceneAlbedo(vec3 p, int id, vec3 albedo)`,
    a procedural albedo from the material's own. It may call the catalog's functions (sdTorus,
    opSmoothUnion, checker ...) and define helpers of its own, whose names must not be the
    catalog's or glint's."""

    file: str
    """The GLSL file, relative to the scene file."""
    lipschitz: AtLeastOne = 1.0
    """A bound on how fast the field changes (1 for an exact distance; more for displaced or
    noisy fields): every march divides its steps by it."""
    material: str | None = None
    """The material of the whole field (without sceneMaterial)."""
    materials: dict[str, str] = {}
    """Material by the id sceneMaterial returns, e.g. { 1 = "rock", 2 = "moss" }."""
    bounds: Annotated[list[Vec3], Field(min_length=2, max_length=2)] | None = None
    """Two opposite corners of a box that holds every surface of the field a ray can see, e.g.
    [[-3, -1, -3], [3, 1, 3]]: marches skip the rest of the ray. Without it they march it all."""

    setup: str | None = None
    """A `void NAME()` function of the file that runs once per pixel before the march: it
    sets the globals the distance function reads (a rotation from iTime, a precomputed
    shape), so that they are not recomputed at every step."""
    detail: str | None = None
    """A `float NAME(vec3 p)` function of the file: a small height added along the normal for
    shading only (bumps, grain), never marched; its gradient tilts the normal."""
    detail_strength: Positive = 1.0
    """Multiplies the detail height (0.5 halves the bumps)."""

    _source: str = PrivateAttr("")
    _path: str = PrivateAttr("")

    @model_validator(mode="after")
    def _one_way_to_material(self) -> Geometry:
        if (self.material is None) == (not self.materials):
            raise ValueError(
                "give material (one for the whole field) or materials (by the id "
                "sceneMaterial returns), one of them"
            )
        for key in self.materials:
            if not re.fullmatch(r"-?[0-9]{1,10}", key) or not -(2**31) < int(key) < 2**31:
                raise ValueError(
                    f"materials: key {shown(key)} is not an integer id (a GLSL int, from "
                    f"{-(2**31) + 1} to {2**31 - 1})"
                )
        return self

    @model_validator(mode="after")
    def _ordered_bounds(self) -> Geometry:
        if self.bounds is not None and any(a > b for a, b in zip(*self.bounds, strict=True)):
            raise ValueError("bounds: the first corner must be below the second on every axis")
        return self

    def material_names(self) -> list[str]:
        return [self.material] if self.material is not None else list(self.materials.values())

    def material_keys(self) -> list[tuple[str, str]]:
        if self.material is not None:
            return [("geometry.material", self.material)]
        return [(f"geometry.materials.{key}", name) for key, name in self.materials.items()]

    @property
    def source(self) -> str:
        """The file's text (read when the scene is loaded)."""
        return self._source

    @property
    def path(self) -> str:
        """The file as source markers and messages name it."""
        return self._path or self.file

    def read(self, base: Path) -> None:
        """Read the file, relative to the scene's folder `base`."""
        found = base / self.file
        if not found.exists() and not found.is_symlink():
            raise InputError(
                f"geometry.file: {self.file}: no such file (looked for {found}); the path is "
                "relative to the scene file"
            )
        try:
            self._source = read_user_text(found, GEOMETRY_FILE_LIMIT, "GLSL file")
        except InputError as exc:
            raise InputError(f"geometry.file: {exc.message}") from None
        self._path = _shown_path(found)


def _shown_path(path: Path) -> str:
    """The path relative to the working folder when it is under it (shorter messages and
    markers), else absolute."""
    try:
        return str(path.resolve().relative_to(Path.cwd().resolve()))
    except ValueError:
        return str(path.resolve())


class Environment(Strict):
    type: Literal["gradient"] = "gradient"
    top: Color = [0.5, 0.7, 1.0]
    """Colour of the sky straight up."""
    bottom: Color = [0.8, 0.85, 0.9]
    """Colour toward the horizon and below."""
    reflection: bool = True
    """Whether surfaces reflect the environment (the `env` slot)."""


class Medium(Strict):
    """A homogeneous participating medium between the eye and the surfaces: fog, or water
    below a level. Beer-Lambert extinction with the medium's own glow (the `media` slot)."""

    extinction: Color = [2.0794415, 2.4953298, 3.7429947]
    """σ per unit distance (natural log), per channel; by default the seed's water, which takes
    red first and blue last."""
    inscatter: Color = [0.02, 0.12, 0.16]
    """What a long path through the medium converges to: its colour under the ambient light."""
    level: Number | None = None
    """Water: the medium fills y < level. Absent: it fills all of space (fog)."""


class Background(Strict):
    sun: bool = True
    """Draw a glow and a disc around the key light."""
    color: Color | None = None
    """A flat colour for rays that hit nothing, in place of the environment (which surfaces
    still reflect and are lit by). Absent: the background shows the environment."""
    tonemap: bool = True
    """Whether the background goes through exposure and the tone map as the lit surfaces do;
    false shows `color` (or the environment) as given, so [1, 1, 1] is white on screen."""


class Effects(Strict):
    ao: bool = True
    """Ambient occlusion (the `ao` slot)."""
    reflections: bool = False
    """Mirror reflections: a smooth surface (roughness below 0.3, fading in toward 0) reflects
    the scene itself, one bounce, at the balanced and reference tiers; what it sees is lit as
    the scene is, emission included. The fast tier, and rough surfaces, reflect only the
    environment. A second march for each smooth pixel: about twice its cost."""


class Post(Strict):
    tonemap: Literal["none", "reinhard", "aces"] = "reinhard"
    """The tone map applied before output."""
    output: Literal["gamma22", "srgb", "none"] = "gamma22"
    """The transfer function to the display; none writes the linear colour (for a buffer
    another pass reads, or a runner that encodes it)."""
    exposure: Positive = 1.0
    """Scales the linear colour before the tone map (2 is one stop brighter)."""


class MeshSettings(Strict):
    """How mesh scenes are shaded (a scene whose objects are meshes)."""

    shading: ShadingMode = "phong"
    """The shading mode of materials that do not set their own."""


class Quality(Strict):
    tier: Literal["fast", "balanced", "reference"] = "balanced"
    """The quality tier: which variant fills each slot."""
    variants: dict[str, str] = {}
    """Slot -> variant, overriding the tier, e.g. { shadow = "hard" }."""
    params: dict[str, integer(-(2**24)) | Number | Vec3] = {}  # type: ignore[valid-type]
    """Values of the chosen snippets' parameters, e.g. { SHADOW_K = 16, AO_STEPS = 8 }: they
    replace the defaults and the values glint derives (see `glint catalog show SLOT.VARIANT`
    for each snippet's parameters and their ranges)."""
    aa: integer(1, 8) = 1  # type: ignore[valid-type]
    """Anti-aliasing: each pixel averages aa × aa samples spread over its area (1: one sample,
    the ray through its centre). The cost grows as aa²."""


class Scene(Strict):
    name: str = "scene"
    """Shown in the shader's header."""
    description: str = ""
    camera: Camera = OrbitCamera(type="orbit")
    """An orbit, a look-at or a keyframed path camera."""
    objects: list[Shape] = []
    """The shapes, as [[objects]] tables with a shape key (primitives, or groups of them)."""
    geometry: Geometry | None = None
    """The user's own distance function, in a GLSL file."""
    materials: dict[str, Material]
    """Named materials, as [materials.NAME] tables."""
    lights: list[Light] = []
    """The lights, as [[lights]] tables with a type key."""
    environment: Environment | None = Environment()
    """The sky gradient, which the background shows and surfaces reflect."""
    medium: Medium | None = None
    """Fog or water between the eye and the surfaces."""
    background: Background = Background()
    effects: Effects = Effects()
    post: Post = Post()
    mesh: MeshSettings = MeshSettings()
    """Mesh scenes only: the default shading mode."""
    quality: Quality = Quality()
    channels: dict[Literal["0", "1", "2", "3"], str] = {}
    """Pictures for ShaderToy's channels, by number, e.g. { 0 = "stone.png" } (relative to the
    scene file): `glint render` binds them (its --channel replaces one), and the composed
    shader names them for binding in ShaderToy."""

    _base: Path = PrivateAttr(Path("."))

    def channel_files(self) -> dict[int, Path]:
        """[channels] as paths, relative to the scene file's folder."""
        return {int(unit): self._base / name for unit, name in self.channels.items()}

    def picture_files(self, given: Mapping[int, str | Path] | None = None) -> dict[int, Path]:
        """The picture of each channel a material reads, by [channels], replaced or joined by
        `given` (glint render --channel)."""
        read = self.bound_channels()
        files = {unit: path for unit, path in self.channel_files().items() if unit in read}
        return files | {unit: Path(path) for unit, path in (given or {}).items()}

    def bound_pictures(self, given: Mapping[int, str | Path] | None = None) -> dict[int, Path]:
        """picture_files, where every channel a material reads has one: a channel with none
        would sample black, a wrong picture without a word, and is a UsageError naming the
        material that reads it and how to bind it."""
        files = self.picture_files(given)
        missing = sorted(self.bound_channels() - set(files))
        if missing:
            unit = missing[0]
            material = next(
                name for name in self.used_materials()
                if self.materials[name].albedo_texture == unit
            )  # fmt: skip
            raise UsageError(
                f"materials.{material}.albedo_texture = {unit}: nothing is bound to "
                f"iChannel{unit}, which would sample black; give a picture ([channels] {unit} = "
                f'"FILE" in the scene, glint render --channel {unit}=FILE, or '
                f"channels={{{unit}: FILE}})"
            )
        return files

    @property
    def is_mesh(self) -> bool:
        """Whether the scene is made of triangle meshes (rasterized, not raymarched)."""
        return any(isinstance(obj, Mesh) for obj in self.objects)

    def shading_of(self, material: str) -> str:
        """The shading mode of a material of a mesh scene."""
        return self.materials[material].shading or self.mesh.shading

    @property
    def exact_distance(self) -> bool:
        """Whether `map` is the exact distance to the scene: no user field (whose exactness
        glint cannot know) and no part whose field is only a bound (shapes.exact)."""
        return self.geometry is None and all(exact(obj) for obj in self.objects)

    def bound_channels(self) -> set[int]:
        """The ShaderToy channels the scene's materials in use read a picture from."""
        channels = (self.materials[m].albedo_texture for m in self.used_materials())
        return {c for c in channels if c is not None}

    def used_materials(self) -> list[str]:
        """Names of the materials in use, in order of first use (objects, then the user's
        geometry); unused ones emit nothing."""
        names = [obj.material for obj in self.objects if obj.material is not None]
        if self.geometry is not None:
            names += self.geometry.material_names()
        return list(dict.fromkeys(names))

    @model_validator(mode="after")
    def _references(self) -> Scene:
        if not self.objects and self.geometry is None:
            raise ValueError("objects: a scene needs at least one object or a [geometry] file")
        named = [(f"objects[{i}].material", obj.material) for i, obj in enumerate(self.objects)]
        for i, obj in enumerate(self.objects):
            if obj.material is None:
                raise ValueError(f"objects[{i}].material: required key is missing")
            for j, part in enumerate(parts(obj)[1:]):
                if part.material is not None:
                    raise ValueError(
                        f"objects[{i}]: part {j + 1} ({part.shape}) has a material; the parts "
                        "of a group take the group's: set material on the top-level object"
                    )
        self._check_meshes()
        if self.geometry is not None:
            named += self.geometry.material_keys()
        known = ", ".join(sorted(self.materials)) or "none defined"
        for key, name in named:
            if name not in self.materials:
                raise ValueError(f"{key}: '{name}' is not a material (materials: {known})")
        return self

    def _check_meshes(self) -> None:
        """A scene is all meshes (rasterized) or has none (raymarched): each needs its own
        program and camera model. Mesh-only keys stay out of raymarched scenes."""
        meshes = [i for i, obj in enumerate(self.objects) if isinstance(obj, Mesh)]
        for i, obj in enumerate(self.objects):
            for j, part in enumerate(parts(obj)[1:]):
                if isinstance(part, Mesh):
                    raise ValueError(
                        f"objects[{i}]: part {j + 1} is a mesh; a mesh is a top-level object, "
                        "not a part of a group"
                    )
        if not meshes:
            # by value, not by the keys given: a dumped scene validates again as it was
            for name, material in self.materials.items():
                for key in ("shading", "models"):
                    if getattr(material, key):
                        raise ValueError(
                            f'materials.{name}.{key}: only mesh scenes (shape = "mesh") '
                            "have it; a raymarched scene shades every material in one program"
                        )
            if self.mesh != MeshSettings():
                raise ValueError('mesh: only mesh scenes (shape = "mesh") take [mesh]')
            return
        other = next((i for i, obj in enumerate(self.objects) if i not in meshes), None)
        if other is not None:
            raise ValueError(
                f"objects[{other}].shape: {self.objects[other].shape!r} in a scene with meshes "
                f"(objects[{meshes[0]}]); a scene is either all meshes (rasterized) or has "
                "none (raymarched): make every object a mesh, or none"
            )
        for name in self.used_materials():
            if not _FILE_NAME_PART.fullmatch(name):
                raise ValueError(
                    f"materials: the name {shown(name)} names a program of a mesh scene, and "
                    "so its files (BASE.NAME.vert); use letters, digits, '_' and '-' (at most "
                    "64 of them)"
                )
        if self.geometry is not None:
            raise ValueError("geometry: a mesh scene has no distance field; remove [geometry]")
        # what the rasterized programs do not draw yet: refused rather than dropped unseen
        unsupported = [
            ("camera.roll", self.camera.roll != 0.0),
            ("channels", bool(self.channels)),
            ('camera.type = "path"', isinstance(self.camera, PathCamera)),
            ("quality.aa", self.quality.aa != 1),
            ("background.color", self.background.color is not None),
            ("background.tonemap", not self.background.tonemap),
            *(
                (f"materials.{n}.albedo_texture", m.albedo_texture is not None)
                for n, m in self.materials.items()
            ),
            *(
                (f"materials.{n}.emission", m.emission is not None)
                for n, m in self.materials.items()
            ),
        ]
        for key, given in unsupported:
            if given:
                raise ValueError(f"{key}: not available in mesh scenes yet; remove it")
        if self.medium is not None:
            raise ValueError("medium: not available in mesh scenes yet; remove [medium]")


# A mesh scene's material name, which names its program's files.
_FILE_NAME_PART = re.compile(r"[A-Za-z0-9_-]{1,64}")


def default_scene_path() -> Path:
    return Path(str(resources.files("glint.snippets") / "scenes" / "default.toml"))


def load_scene(path: str | Path | None = None) -> Scene:
    """Read and validate a scene file; None means the embedded default scene."""
    path = Path(path) if path is not None else default_scene_path()
    if not path.exists() and not path.is_symlink():
        raise InputError(f"{path}: no such scene file")
    text = read_user_text(path, SCENE_FILE_LIMIT, "scene TOML file")
    return parse_scene(text, str(path))


def parse_scene(text: str, filename: str = "<scene>") -> Scene:
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{filename}: not valid TOML: {exc}") from None
    except RecursionError:  # tomllib parses nested arrays and inline tables recursively
        raise InputError(
            f"{filename}: arrays or inline tables nested too deep to read (thousands of "
            "levels); no value of a scene nests that deep"
        ) from None
    return scene_from_dict(data, filename)


def scene_from_dict(data: Mapping[str, Any], filename: str = "<scene>") -> Scene:
    """A scene from the tables of a scene file (a dict), validated, with one message naming
    the first problem's key."""
    if not isinstance(data, Mapping):
        raise InputError(f"{filename}: a scene is a table of tables, not {type(data).__name__}")
    problem = nesting_problem(data)
    if problem is not None:
        raise InputError(f"{filename}: {problem}")
    try:
        scene = Scene.model_validate(dict(data))
    except ValidationError as exc:
        first = exc.errors()[0]
        more = len(exc.errors()) - 1
        suffix = f" (and {more} more problem{'s' if more > 1 else ''})" if more else ""
        raise InputError(f"{filename}: {describe_error(first)}{suffix}") from None
    base = Path(filename).parent if not filename.startswith("<") else Path.cwd()
    scene._base = base
    try:
        if scene.geometry is not None:
            scene.geometry.read(base)
        _read_meshes(scene, base)
    except InputError as exc:
        raise InputError(f"{filename}: {exc}") from None
    return scene


def _read_meshes(scene: Scene, base: Path) -> None:
    """Read the mesh files of the scene's objects, relative to the scene's folder `base`."""
    from glint.compiler.scene.mesh_files import read_mesh_file

    for i, obj in enumerate(scene.objects):
        if isinstance(obj, Mesh) and obj.file is not None:
            obj.keep(read_mesh_file(base / obj.file, f"objects[{i}].file"))


def describe_error(error: Any) -> str:
    """One pydantic error as `key.path: what is wrong (got value); expected ...`."""
    loc = _key_path(error["loc"])
    kind = error["type"]
    value = error.get("input")
    if kind == "extra_forbidden":
        return f"{loc}: unknown key; {_allowed_keys(error['loc'])}"
    if kind == "missing":
        return f"{loc}: required key is missing"
    ctx = error.get("ctx", {})
    if kind == "union_tag_invalid":
        key = f"{loc}.{ctx['discriminator'].strip(chr(39))}"
        return f"{key}: unknown value {ctx['tag']!r}; expected one of {ctx['expected_tags']}"
    if kind == "literal_error":
        return f"{loc}: unknown value {value!r}; expected one of {ctx['expected']}"
    if kind == "union_tag_not_found":
        return f"{loc}: needs a {ctx.get('discriminator', 'type')} key"
    message = error["msg"].removeprefix("Value error, ")
    if kind == "value_error":
        return f"{loc}: {message}" if loc else message
    return f"{loc}: {message[0].lower()}{message[1:]} (got {shown(value)})"


_TAGS: dict[str, type[BaseModel]] = {
    "orbit": OrbitCamera,
    "lookat": LookAtCamera,
    "path": PathCamera,
    **SHAPE_TAGS,
    "directional": DirectionalLight,
    "point": PointLight,
    "spot": SpotLight,
    "sphere": SphereLight,
    "disc": DiscLight,
    "rect": RectLight,
    "sky": SkyLight,
    "back": BackLight,
    "bounce": BounceLight,
    "environment": EnvironmentLight,
}
_SECTIONS = (Geometry, Environment, Medium, Background, Effects, Post, MeshSettings, Quality)
_MATERIALS = "materials"  # marks the table whose keys are material names


def _walk(loc: tuple[Any, ...]) -> tuple[str, Any]:
    """('lights', 0, 'directional', 'color', 1) -> ('lights[0].color[1]', model of the last key).

    Union tags that pydantic puts in the location are not keys of the file and are dropped.
    """
    path: list[Any] = []
    model: Any = Scene
    for item in loc:
        if isinstance(item, int):
            path.append(item)
            continue
        fields = getattr(model, "model_fields", {})
        if model is _MATERIALS:
            model = Material
        elif item not in fields and item in _TAGS:
            model = _TAGS[item]
            continue
        else:
            model = _section(fields[item].annotation, item) if item in fields else None
        path.append(item)
    return key_path(tuple(path)), model


def _section(annotation: Any, key: str) -> Any:
    if key == "materials":
        return _MATERIALS
    return next((m for m in _SECTIONS if annotation in (m, m | None)), None)


def _key_path(loc: tuple[Any, ...]) -> str:
    return _walk(loc)[0]


def _allowed_keys(loc: tuple[Any, ...]) -> str:
    model = _walk(loc[:-1])[1] if loc[:-1] else Scene
    fields = getattr(model, "model_fields", None)
    if not fields:
        return "see the scene reference in the README"
    return "allowed keys here: " + ", ".join(fields)
