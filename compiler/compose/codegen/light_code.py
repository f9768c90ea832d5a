"""The lights' part of the scene's code: a #define per light's value and the term of `shade` that
adds it, each with the reason its call is there (a shadow-casting light makes `shade` call
`shadow`); mesh programs light with the same terms.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from glint.compiler.catalog.loader import glsl_float, glsl_value
from glint.compiler.compose.codegen.knobs import UniformParam
from glint.compiler.errors import InputError
from glint.compiler.scene.model import (
    AREA_LIGHTS,
    BackLight,
    BounceLight,
    DirectionalLight,
    DiscLight,
    EnvironmentLight,
    PointLight,
    RectLight,
    Scene,
    SkyLight,
    SphereLight,
    SpotLight,
)


def _vec3(v: list[float]) -> str:
    return glsl_value(v, "vec3")


@dataclass
class LightCode:
    defines: dict[str, str]  # name -> GLSL expression
    calls: list[str]  # one term of `shade` per light
    requires: list[str]  # the functions those terms call
    directional: list[str]  # the identifier of each directional light (SUN, LIGHT1, ...)
    why: list[tuple[str, str]]  # (function called, the light that makes `shade` call it)
    labels: list[str]  # `lights[i] (type)` of each light, in the scene's order
    knobs: dict[str, UniformParam] = field(default_factory=dict)  # each light's intensity


# Where a shadow ray starts: the shading point lifted by the march's tolerance at the hit, which
# mainImage writes to a global (scene_code._hit_lift_unit).
HIT_LIFT = "hitLift"
LIFTED = f"s.P + s.N * {HIT_LIFT}"


def light_code(scene: Scene) -> LightCode:
    """Constants for each light and the line of `shade` that adds it."""
    defines: dict[str, str] = {}
    calls: list[str] = []
    requires: list[str] = []
    directional: list[str] = []
    why: list[tuple[str, str]] = []
    labels = [f"lights[{i}] ({light.type})" for i, light in enumerate(scene.lights)]
    counts: dict[str, int] = {}
    knobs: dict[str, UniformParam] = {}

    def name(base: str) -> str:
        n = counts.get(base, 0)
        counts[base] = n + 1
        return base if n == 0 else f"{base}{n}"

    def fill_direction(i: int, ident: str, direction: list[float] | None) -> None:
        if direction is not None:
            defines[f"{ident}_DIR"] = f"normalize({_vec3(direction)})"
        elif "SUN" in counts:
            # Opposite the sun, horizontal: light bounced back from behind the viewer's side.
            defines[f"{ident}_DIR"] = "normalize(vec3(-SUN_DIR.x, 0.0, -SUN_DIR.z))"
        else:
            raise InputError(
                f"lights[{i}].direction: a {scene.lights[i].type} light needs a direction when "
                "the scene has no directional light before it"
            )

    def colour(ident: str, color: list[float], intensity: float) -> None:
        # the intensity apart from the colour: a knob a page can turn, and one a reader of the
        # ShaderToy code finds by name
        defines[f"{ident}_INTENSITY"] = glsl_float(intensity)
        defines[f"{ident}_COLOR"] = f"({_vec3(color)} * {ident}_INTENSITY)"
        knobs[f"{ident}_INTENSITY"] = _intensity_knob(f"{ident}_INTENSITY", intensity)

    def positioned_visibility(ident: str, shadow: bool) -> str:
        """A point or spot light's visibility: a shadow ray that stops at the light."""
        if not shadow:
            return "vec3(1.0)"
        requires.extend(["shadow", HIT_LIFT])
        toward = f"normalize({ident}_POS - s.P)"
        return f"vec3(shadow({LIFTED}, {toward}, 0.02, distance({ident}_POS, s.P)))"

    def shaded_through_brdf(i: int, function: str, shadow: bool) -> None:
        why.append((function, f"{labels[i]} is shaded through the BRDF"))
        if shadow:
            why.append(("shadow", f"{labels[i]} casts shadows"))

    for i, light in enumerate(scene.lights):
        if isinstance(light, DirectionalLight):
            ident = name("SUN") if "SUN" not in counts else name("LIGHT")
            directional.append(ident)
            defines[f"{ident}_DIR"] = f"normalize({_vec3(light.direction)})"
            knobs[f"{ident}_DIR"] = _direction_knob(f"{ident}_DIR", light.direction)
            colour(ident, light.color, light.intensity)
            visibility = "vec3(1.0)"
            if light.shadow:
                dist = glsl_float(light.shadow_distance)
                cast = f"vec3(shadow({LIFTED}, {ident}_DIR, 0.02, {dist}))"
                visibility = cast
                requires += ["shadow", HIT_LIFT]
                if light.penumbra is not None:
                    defines[f"{ident}_PENUMBRA"] = _vec3(light.penumbra)
                    visibility = f"pow({cast}, {ident}_PENUMBRA)"
            calls.append(f"directionalLight(s, {ident}_DIR, {ident}_COLOR, {visibility})")
            requires.append("directionalLight")
            shaded_through_brdf(i, "directionalLight", light.shadow)
        elif isinstance(light, PointLight):
            ident = name("POINT")
            defines[f"{ident}_POS"] = _vec3(light.position)
            colour(ident, light.color, light.intensity)
            defines[f"{ident}_RANGE"] = glsl_float(light.range)
            visibility = positioned_visibility(ident, light.shadow)
            calls.append(f"pointLight(s, {ident}_POS, {ident}_COLOR, {ident}_RANGE, {visibility})")
            requires.append("pointLight")
            shaded_through_brdf(i, "pointLight", light.shadow)
        elif isinstance(light, SpotLight):
            ident = name("SPOT")
            assert light.direction is not None  # the model turns a target into a direction
            defines[f"{ident}_POS"] = _vec3(light.position)
            defines[f"{ident}_DIR"] = f"normalize({_vec3(light.direction)})"
            cones = [math.cos(math.radians(a)) for a in (light.outer, light.inner)]
            defines[f"{ident}_CONE"] = glsl_value(cones, "vec2")
            colour(ident, light.color, light.intensity)
            defines[f"{ident}_RANGE"] = glsl_float(light.range)
            visibility = positioned_visibility(ident, light.shadow)
            calls.append(
                f"spotLight(s, {ident}_POS, {ident}_DIR, {ident}_CONE, {ident}_COLOR, "
                f"{ident}_RANGE, {visibility})"
            )
            requires.append("spotLight")
            shaded_through_brdf(i, "spotLight", light.shadow)
        elif isinstance(light, AREA_LIGHTS):
            ident = name("AREA")
            shape, right, up, area = area_frame(light)
            defines[f"{ident}_POS"] = _vec3(light.position)
            defines[f"{ident}_RIGHT"] = _vec3(right)
            defines[f"{ident}_UP"] = _vec3(up)
            colour(ident, light.color, light.intensity)
            # the intensity is the light's seen from afar; its surface's radiance is that
            # spread over its area (projected, for a sphere)
            defines[f"{ident}_RADIANCE"] = f"({ident}_COLOR / {glsl_float(area)})"
            args = f"{ident}_POS, {ident}_RIGHT, {ident}_UP, {shape}"
            why.append(("areaLight", f"{labels[i]} is an area light"))
            visibility = ""
            if light.shadow:
                visibility = f" * areaShadow({LIFTED}, {args})"
                requires += ["areaShadow", HIT_LIFT]
                why.append(("areaShadow", f"{labels[i]} casts shadows"))
            calls.append(f"areaLight(s, {args}, {ident}_RADIANCE){visibility}")
            requires += ["areaLight", shape]
        elif isinstance(light, SkyLight):
            ident = name("SKY")
            colour(ident, light.color, light.intensity)
            calls.append(f"skyLight(s, {ident}_COLOR, occlusion)")
            requires.append("skyLight")
            why.append(("skyLight", f"{labels[i]} fills the shading"))
        elif isinstance(light, BackLight | BounceLight):
            ident = name(light.type.upper())
            fill_direction(i, ident, light.direction)
            colour(ident, light.color, light.intensity)
            function = f"{light.type}Light"
            calls.append(f"{function}(s, {ident}_DIR, {ident}_COLOR, occlusion)")
            requires.append(function)
            why.append((function, f"{labels[i]} fills the shading"))
        elif isinstance(light, EnvironmentLight):
            ident = name("ENV_LIGHT")
            defines[f"{ident}_SCALE"] = glsl_float(light.intensity)
            knobs[f"{ident}_SCALE"] = _intensity_knob(f"{ident}_SCALE", light.intensity)
            calls.append(f"irradianceLight(s, {ident}_SCALE, occlusion)")
            requires.append("irradianceLight")
            why.append(("irradianceLight", f"{labels[i]} lights with the environment's irradiance"))
    return LightCode(defines, calls, requires, directional, why, labels, knobs)


def area_frame(
    light: SphereLight | DiscLight | RectLight,
) -> tuple[str, list[float], list[float], float]:
    """An area light as areaLight takes it: its shape's constant, the vectors `right` and `up`
    (right × up is the way a disc or rectangle shines; a sphere reads only right's length),
    and the area its intensity is spread over (a sphere's seen from afar, πr²)."""
    if isinstance(light, SphereLight):
        r = light.radius
        return "AREA_SPHERE", [r, 0.0, 0.0], [0.0, r, 0.0], math.pi * r * r
    facing = _unit(light.direction)
    hint = light.up if isinstance(light, RectLight) and light.up is not None else None
    if hint is None:
        hint = [0.0, 0.0, 1.0] if abs(facing[1]) > 0.999 else [0.0, 1.0, 0.0]
    right = _unit(_cross(hint, facing))
    up = _cross(facing, right)  # right × up = facing
    if isinstance(light, DiscLight):
        r = light.radius
        return "AREA_DISC", _scaled(right, r), _scaled(up, r), math.pi * r * r
    width, height = light.size
    return "AREA_RECT", _scaled(right, width / 2), _scaled(up, height / 2), width * height


def _unit(v: list[float]) -> list[float]:
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v]


def _cross(a: list[float], b: list[float]) -> list[float]:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _scaled(v: list[float], k: float) -> list[float]:
    return [round(c * k, 7) + 0.0 for c in v]


def _intensity_knob(name: str, value: float) -> UniformParam:
    """A light's intensity as a knob: a log slider over four decades around 1 (0.01 to 100),
    wider where the scene's own value lies outside."""

    low = min(0.01, value) if value > 0 else 0.0
    return UniformParam(name, "float", value, low, max(100.0, value))


def _direction_knob(name: str, direction: list[float]) -> UniformParam:
    """A directional light's direction (toward the light) as a knob: a unit vector the page
    sets by azimuth and elevation."""
    length = math.sqrt(sum(c * c for c in direction))
    unit = [round(c / length, 6) for c in direction]
    return UniformParam(name, "vec3", unit, -1.0, 1.0, control="direction")
