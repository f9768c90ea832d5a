"""The scene description: TOML in, a validated model out, or one error naming the key path.

A scene says what is in the picture (camera, SDF objects, materials, lights, environment,
effects, post) and how much accuracy to pay for (quality). Nothing in it executes code.
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from glint.compiler.errors import InputError

Number = Annotated[float, Field(strict=True, allow_inf_nan=False)]
Unit = Annotated[float, Field(strict=True, ge=0.0, le=1.0)]
Positive = Annotated[float, Field(strict=True, gt=0.0, allow_inf_nan=False)]
NonNegative = Annotated[float, Field(strict=True, ge=0.0, allow_inf_nan=False)]
Vec3 = Annotated[list[Number], Field(min_length=3, max_length=3)]
Color = Annotated[list[NonNegative], Field(min_length=3, max_length=3)]


class Strict(BaseModel):
    # A string under a field is its description: the docs site's scene reference shows it.
    model_config = ConfigDict(extra="forbid", strict=True, use_attribute_docstrings=True)


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
    focal: Positive = 1.5
    """Focal length in screen heights: larger zooms in."""


class LookAtCamera(Strict):
    type: Literal["lookat"]
    position: Vec3 = [0.0, 1.0, 4.0]
    """Where the camera stands."""
    target: Vec3 = [0.0, 0.0, 0.0]
    """The point it looks at."""
    focal: Positive = 1.5
    """Focal length in screen heights: larger zooms in."""

    @model_validator(mode="after")
    def _distinct(self) -> LookAtCamera:
        if self.position == self.target:
            raise ValueError("position and target must differ")
        return self


class Sphere(Strict):
    shape: Literal["sphere"]
    center: Vec3 = [0.0, 0.0, 0.0]
    radius: Positive = 1.0
    material: str
    """The name of a table under [materials]."""


class Plane(Strict):
    shape: Literal["plane"]
    normal: Vec3 = [0.0, 1.0, 0.0]
    """The plane's normal; need not be unit length."""
    offset: Number = 0.0
    """The plane is dot(p, normal) + offset = 0."""
    material: str
    """The name of a table under [materials]."""

    @model_validator(mode="after")
    def _nonzero(self) -> Plane:
        if not any(self.normal):
            raise ValueError("normal must not be the zero vector")
        return self


class Box(Strict):
    shape: Literal["box"]
    center: Vec3 = [0.0, 0.0, 0.0]
    size: Annotated[list[Positive], Field(min_length=3, max_length=3)]
    """Half extents along x, y and z."""
    material: str
    """The name of a table under [materials]."""


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
    subsurface_g: Annotated[float, Field(strict=True, ge=-1.0, le=1.0)] = 0.5
    """Asymmetry g of the interior's phase function: > 0 scatters forward (glows when back-lit)."""

    @model_validator(mode="after")
    def _pattern(self) -> Material:
        if self.pattern != "none" and self.pattern_albedo is None:
            raise ValueError(f"pattern '{self.pattern}' needs pattern_albedo, a second colour")
        return self


class DirectionalLight(Strict):
    type: Literal["directional"]
    direction: Vec3
    """Toward the light."""
    color: Color = [1.0, 1.0, 1.0]
    """Linear RGB."""
    intensity: NonNegative = 1.0
    """Multiplies the colour."""
    shadow: bool = True
    """Whether it casts shadows (the `shadow` slot)."""
    shadow_distance: Positive = 5.0
    """How far a shadow ray looks for an occluder."""
    penumbra: Annotated[list[Positive], Field(min_length=3, max_length=3)] | None = None
    """Per-channel exponents applied to the shadow, e.g. [1.0, 1.2, 1.5]: penumbrae turn cool."""

    @model_validator(mode="after")
    def _nonzero(self) -> DirectionalLight:
        if not any(self.direction):
            raise ValueError("direction must not be the zero vector")
        return self


class PointLight(Strict):
    type: Literal["point"]
    position: Vec3
    """Where the light is."""
    color: Color = [1.0, 1.0, 1.0]
    intensity: NonNegative = 1.0
    range: Positive = 10.0
    """Where the attenuation reaches zero (for the attenuation variants that have a range)."""
    shadow: bool = True
    """Whether it casts shadows (the `shadow` slot)."""


class SkyLight(Strict):
    type: Literal["sky"]
    color: Color = [0.2, 0.5, 1.0]
    """Colour of the light from the sky above."""
    intensity: NonNegative = 1.0


class BackLight(Strict):
    type: Literal["back"]
    direction: Vec3 | None = None
    """Toward the light; by default the key light's direction mirrored and made horizontal."""
    color: Color = [0.15, 0.1, 0.08]
    intensity: NonNegative = 1.0


class BounceLight(Strict):
    type: Literal["bounce"]
    direction: Vec3 | None = None
    """Toward the light; by default the key light's direction mirrored and made horizontal."""
    color: Color = [0.40, 0.28, 0.20]
    intensity: NonNegative = 1.0


class EnvironmentLight(Strict):
    """Diffuse light from the scene's environment, by the `irradiance` slot's variant."""

    type: Literal["environment"]
    intensity: NonNegative = 1.0


Light = Annotated[
    DirectionalLight | PointLight | SkyLight | BackLight | BounceLight | EnvironmentLight,
    Field(discriminator="type"),
]
Camera = Annotated[OrbitCamera | LookAtCamera, Field(discriminator="type")]
SceneObject = Annotated[Sphere | Plane | Box, Field(discriminator="shape")]


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


class Effects(Strict):
    ao: bool = True
    """Ambient occlusion (the `ao` slot)."""


class Post(Strict):
    tonemap: Literal["none", "reinhard", "aces"] = "reinhard"
    """The tone map applied before output."""
    output: Literal["gamma22", "srgb"] = "gamma22"
    """The transfer function to the display."""


class Quality(Strict):
    tier: Literal["fast", "balanced", "reference"] = "balanced"
    """The quality tier: which variant fills each slot."""
    variants: dict[str, str] = {}
    """Slot -> variant, overriding the tier, e.g. { shadow = "hard" }."""


class Scene(Strict):
    name: str = "scene"
    """Shown in the shader's header."""
    description: str = ""
    camera: Camera = OrbitCamera(type="orbit")
    """An orbit or a look-at camera."""
    objects: Annotated[list[SceneObject], Field(min_length=1)]
    """The shapes, as [[objects]] tables with a shape key."""
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
    quality: Quality = Quality()

    def used_materials(self) -> list[str]:
        """Names of the materials objects use, in order of first use; unused ones emit nothing."""
        return list(dict.fromkeys(obj.material for obj in self.objects))

    @model_validator(mode="after")
    def _references(self) -> Scene:
        for i, obj in enumerate(self.objects):
            if obj.material not in self.materials:
                known = ", ".join(sorted(self.materials)) or "none defined"
                raise ValueError(
                    f"objects[{i}].material: '{obj.material}' is not a material "
                    f"(materials: {known})"
                )
        return self


def default_scene_path() -> Path:
    return Path(str(resources.files("glint.snippets") / "scenes" / "default.toml"))


def load_scene(path: str | Path | None = None) -> Scene:
    """Read and validate a scene file; None means the embedded default scene."""
    path = Path(path) if path is not None else default_scene_path()
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"{path}: no such scene file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"{path}: cannot read the scene: {exc}") from None
    return parse_scene(text, str(path))


def parse_scene(text: str, filename: str = "<scene>") -> Scene:
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{filename}: not valid TOML: {exc}") from None
    return scene_from_dict(data, filename)


def scene_from_dict(data: Mapping[str, Any], filename: str = "<scene>") -> Scene:
    """A scene from the tables of a scene file (a dict), validated, with one message naming
    the first problem's key."""
    try:
        return Scene.model_validate(dict(data))
    except ValidationError as exc:
        first = exc.errors()[0]
        more = len(exc.errors()) - 1
        suffix = f" (and {more} more problem{'s' if more > 1 else ''})" if more else ""
        raise InputError(f"{filename}: {describe_error(first)}{suffix}") from None


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
    return f"{loc}: {message[0].lower()}{message[1:]} (got {value!r})"


_TAGS: dict[str, type[BaseModel]] = {
    "orbit": OrbitCamera,
    "lookat": LookAtCamera,
    "sphere": Sphere,
    "plane": Plane,
    "box": Box,
    "directional": DirectionalLight,
    "point": PointLight,
    "sky": SkyLight,
    "back": BackLight,
    "bounce": BounceLight,
    "environment": EnvironmentLight,
}
_SECTIONS = (Environment, Medium, Background, Effects, Post, Quality)
_MATERIALS = "materials"  # marks the table whose keys are material names


def _walk(loc: tuple[Any, ...]) -> tuple[str, Any]:
    """('lights', 0, 'directional', 'color', 1) -> ('lights[0].color[1]', model of the last key).

    Union tags that pydantic puts in the location are not keys of the file and are dropped.
    """
    path = ""
    model: Any = Scene
    for item in loc:
        if isinstance(item, int):
            path += f"[{item}]"
            continue
        fields = getattr(model, "model_fields", {})
        if model is _MATERIALS:
            model = Material
        elif item not in fields and item in _TAGS:
            model = _TAGS[item]
            continue
        else:
            model = _section(fields[item].annotation, item) if item in fields else None
        path += f".{item}" if path else str(item)
    return path, model


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
