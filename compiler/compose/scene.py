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
    model_config = ConfigDict(extra="forbid", strict=True)


class OrbitCamera(Strict):
    type: Literal["orbit"]
    target: Vec3 = [0.0, 0.0, 0.0]
    radius: Positive = 3.0
    height: Number = 1.5
    speed: Number = 0.3
    focal: Positive = 1.5


class LookAtCamera(Strict):
    type: Literal["lookat"]
    position: Vec3 = [0.0, 1.0, 4.0]
    target: Vec3 = [0.0, 0.0, 0.0]
    focal: Positive = 1.5

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


class Plane(Strict):
    shape: Literal["plane"]
    normal: Vec3 = [0.0, 1.0, 0.0]
    offset: Number = 0.0  # the plane is dot(p, normal) + offset = 0
    material: str

    @model_validator(mode="after")
    def _nonzero(self) -> Plane:
        if not any(self.normal):
            raise ValueError("normal must not be the zero vector")
        return self


class Box(Strict):
    shape: Literal["box"]
    center: Vec3 = [0.0, 0.0, 0.0]
    size: Annotated[list[Positive], Field(min_length=3, max_length=3)]  # half extents
    material: str


class Material(Strict):
    albedo: Color
    roughness: Unit = 0.5
    metallic: Unit = 0.0
    pattern: Literal["none", "checker"] = "none"
    pattern_albedo: Color | None = None  # the second colour of a pattern
    # Oren-Nayar's σ, the slope deviation of the diffuse microfacets in radians (0 is Lambert);
    # the rough-diffuse variants read it. None: the specular roughness stands in for it.
    diffuse_roughness: Unit | None = None
    # Light that passes through the body and scatters toward the eye (translucency), per
    # channel: the interior's scattering colour. None: the material is opaque.
    subsurface: Color | None = None
    # Asymmetry g of the interior's phase function: > 0 scatters forward (glows when back-lit).
    subsurface_g: Annotated[float, Field(strict=True, ge=-1.0, le=1.0)] = 0.5

    @model_validator(mode="after")
    def _pattern(self) -> Material:
        if self.pattern != "none" and self.pattern_albedo is None:
            raise ValueError(f"pattern '{self.pattern}' needs pattern_albedo, a second colour")
        return self


class DirectionalLight(Strict):
    type: Literal["directional"]
    direction: Vec3  # toward the light
    color: Color = [1.0, 1.0, 1.0]
    intensity: NonNegative = 1.0
    shadow: bool = True
    shadow_distance: Positive = 5.0
    # Per-channel exponents applied to the shadow, e.g. [1.0, 1.2, 1.5]: penumbrae turn cool.
    penumbra: Annotated[list[Positive], Field(min_length=3, max_length=3)] | None = None

    @model_validator(mode="after")
    def _nonzero(self) -> DirectionalLight:
        if not any(self.direction):
            raise ValueError("direction must not be the zero vector")
        return self


class PointLight(Strict):
    type: Literal["point"]
    position: Vec3
    color: Color = [1.0, 1.0, 1.0]
    intensity: NonNegative = 1.0
    range: Positive = 10.0  # where the attenuation reaches zero (if the variant has a range)
    shadow: bool = True


class SkyLight(Strict):
    type: Literal["sky"]
    color: Color = [0.2, 0.5, 1.0]
    intensity: NonNegative = 1.0


class BackLight(Strict):
    type: Literal["back"]
    # Toward the light; by default the key light's direction mirrored and made horizontal.
    direction: Vec3 | None = None
    color: Color = [0.15, 0.1, 0.08]
    intensity: NonNegative = 1.0


class BounceLight(Strict):
    type: Literal["bounce"]
    # Toward the light; by default the key light's direction mirrored and made horizontal.
    direction: Vec3 | None = None
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
    bottom: Color = [0.8, 0.85, 0.9]
    reflection: bool = True


class Medium(Strict):
    """A homogeneous participating medium between the eye and the surfaces: fog, or water
    below a level. Beer-Lambert extinction with the medium's own glow (the `media` slot)."""

    # σ per unit distance (natural log), per channel; by default the seed's water, which
    # takes red first and blue last.
    extinction: Color = [2.0794415, 2.4953298, 3.7429947]
    # What a long path through the medium converges to: its colour under the ambient light.
    inscatter: Color = [0.02, 0.12, 0.16]
    # Water: the medium fills y < level. None: it fills all of space (fog).
    level: Number | None = None


class Background(Strict):
    sun: bool = True  # draw a glow and disc around the key light


class Effects(Strict):
    ao: bool = True


class Post(Strict):
    tonemap: Literal["none", "reinhard", "aces"] = "reinhard"
    output: Literal["gamma22", "srgb"] = "gamma22"


class Quality(Strict):
    tier: Literal["fast", "balanced", "reference"] = "balanced"
    variants: dict[str, str] = {}  # slot -> variant, overriding the tier


class Scene(Strict):
    name: str = "scene"
    description: str = ""
    camera: Camera = OrbitCamera(type="orbit")
    objects: Annotated[list[SceneObject], Field(min_length=1)]
    materials: dict[str, Material]
    lights: list[Light] = []
    environment: Environment | None = Environment()
    medium: Medium | None = None
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
