"""Parameter baking, the stage after planning: the values of snippet parameters that the scene
sets (camera, environment, medium, background) and those computed from it (the nine
spherical-harmonic coefficients of the environment for `irradiance.sh9`; a pixel-cone march's
tolerance for the camera's focal length and its far limit for the camera's distance; an area
light's shadow rays by tier), and last the scene's own [quality.params], checked against each
parameter's type and range. The emitter writes them as #defines; snippets' defaults cover the
rest."""

from __future__ import annotations

import math

from glint.compiler.catalog.loader import Param, glsl_value, load_catalog
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.planning.spherical_harmonics import (
    project_sh9,
    sh9_params,
    snippet_environment,
)
from glint.compiler.errors import InputError
from glint.compiler.scene.model import LookAtCamera, OrbitCamera, Scene


def bake(scene: Scene, plan: Plan) -> dict[str, str]:
    """#define name -> GLSL value, for the plan's snippets."""
    params = scene_params(scene)
    lit_by_environment = any(light.type == "environment" for light in scene.lights)
    if plan.choices.get("irradiance") == "irradiance.sh9" and lit_by_environment:
        params |= _sh9_params(plan.choices["env"], params)
    params |= _march_pixel(scene, plan)
    params |= _march_far(scene, plan)
    if plan.choices.get("area") is not None:
        params |= _area_shadow_rays(plan)
    params |= given_params(scene, plan)
    return params


# Shadow rays per side toward an area light, by tier: one ray (the centre's shadow) at fast,
# 2 × 2 spread over the light at the others (its penumbra grows with its size).
AREA_SHADOW_RAYS = {"fast": 1}


def _area_shadow_rays(plan: Plan) -> dict[str, str]:
    rays = AREA_SHADOW_RAYS.get(plan.tier)
    return {} if rays is None else {"AREA_SHADOW_RAYS": str(rays)}


def given_params(scene: Scene, plan: Plan) -> dict[str, str]:
    """[quality.params]: values of parameters of the snippets the plan takes (its one-variant
    slots' and the libraries'), checked against each one's type and range."""
    given = scene.quality.params
    if not given:
        return {}
    catalog = load_catalog()
    chosen = [catalog.get(snippet_id) for snippet_id in plan.choices.values()]
    libraries = [s for s in catalog.snippets.values() if SLOTS[s.slot].many]
    known: dict[str, Param] = {}
    for snippet in [*chosen, *libraries]:
        for name, param in snippet.params.items():
            known.setdefault(name, param)
    out: dict[str, str] = {}
    for name, value in given.items():
        param = known.get(name)
        if param is None:
            names = ", ".join(sorted(known))
            raise InputError(
                f"quality.params.{name}: not a parameter of the snippets this scene uses at "
                f"the {plan.tier} tier; theirs: {names}"
            )
        out[name] = _checked(f"quality.params.{name}", param, value)
    return out


def _checked(key: str, param: Param, value: float | int | list[float]) -> str:
    """The GLSL value of a given parameter, or an error naming what the parameter takes."""
    if param.type == "vec3":
        if not isinstance(value, list):
            raise InputError(f"{key}: a vec3 parameter; give three numbers, e.g. [1.0, 0.5, 0.0]")
        return glsl_value([float(v) for v in value], "vec3")
    if isinstance(value, list):
        raise InputError(f"{key}: a {param.type} parameter; give one number, not a list")
    if param.type == "int" and not isinstance(value, int):
        raise InputError(f"{key}: an int parameter (a count); give a whole number, not {value!r}")
    if param.range is not None and not param.range[0] <= value <= param.range[1]:
        low, high = param.range
        raise InputError(f"{key}: {value!r} is outside its range, {low:g} to {high:g}")
    return glsl_value(int(value) if param.type == "int" else float(value), param.type)


# The focal length a pixel-cone march's MARCH_PIXEL default is for: there it is about half a
# pixel at 360 lines (raymarch.cone).
DEFAULT_FOCAL = 1.5


def _march_pixel(scene: Scene, plan: Plan) -> dict[str, str]:
    """MARCH_PIXEL for the scene's lens: the march stops within MARCH_PIXEL · t of a surface,
    an angle, and a pixel's angle shrinks as the focal length grows. Left at its default, a
    long lens (focal 5) let the march stop 2 pixels off the surface: silhouettes grew a dark
    rim and a concave dimple's rim caught rays meant for its floor (hairlines). Scaled by
    DEFAULT_FOCAL / focal it stays the same share of a pixel."""
    march = plan.choices.get("raymarch")
    param = load_catalog().get(march).params.get("MARCH_PIXEL") if march else None
    if param is None or scene.camera is None:
        return {}
    pixel = float(param.default) * DEFAULT_FOCAL / scene.camera.focal
    return {"MARCH_PIXEL": glsl_value(pixel, "float")}


# How far past the camera's target a march goes, in multiples of the eye's distance to it: the
# scene around the target, and the ground behind it, stay in reach.
FAR_REACH = 3.0


def _march_far(scene: Scene, plan: Plan) -> dict[str, str]:
    """MARCH_FAR for the camera's distance: the default (50) cut off the whole scene for a camera
    80 units from its target, and the picture was the background without a word. At least the
    default; FAR_REACH times the farthest the eye gets from what it looks at."""
    march = plan.choices.get("raymarch")
    param = load_catalog().get(march).params.get("MARCH_FAR") if march else None
    if param is None:
        return {}
    far = FAR_REACH * max(_eye_distances(scene))
    if far <= float(param.default):
        return {}
    high = param.range[1] if param.range is not None else far
    return {"MARCH_FAR": glsl_value(min(far, high), "float")}


def _eye_distances(scene: Scene) -> list[float]:
    """How far the eye is from the point it looks at (for each key of a path)."""
    camera = scene.camera
    if isinstance(camera, OrbitCamera):
        return [math.hypot(camera.radius, camera.height)]
    if isinstance(camera, LookAtCamera):
        return [math.dist(camera.position, camera.target)]
    return [math.dist(key.position, key.target) for key in camera.keys]


def _sh9_params(env_id: str, params: dict[str, str]) -> dict[str, str]:
    """SH_C0..SH_C8 of the scene's environment: the env snippet, with the scene's parameter
    values, run on the CPU and projected onto nine spherical harmonics."""
    coefficients = project_sh9(snippet_environment(env_id, params))
    return {name: glsl_value(row, "vec3") for name, row in sh9_params(coefficients).items()}


def scene_params(scene: Scene) -> dict[str, str]:
    """Values of snippet parameters that the scene sets; snippets' defaults cover the rest."""
    params: dict[str, str] = {}
    camera = scene.camera
    if isinstance(camera, OrbitCamera):
        params["CAMERA_TARGET"] = glsl_value(camera.target, "vec3")
        params["CAMERA_RADIUS"] = glsl_value(camera.radius, "float")
        params["CAMERA_HEIGHT"] = glsl_value(camera.height, "float")
        params["CAMERA_SPEED"] = glsl_value(camera.speed, "float")
        params["CAMERA_FOCAL"] = glsl_value(camera.focal, "float")
        if camera.start:
            params["CAMERA_START"] = glsl_value(math.radians(camera.start), "float")
    elif isinstance(camera, LookAtCamera):
        params["CAMERA_POSITION"] = glsl_value(camera.position, "vec3")
        params["CAMERA_TARGET"] = glsl_value(camera.target, "vec3")
        params["CAMERA_FOCAL"] = glsl_value(camera.focal, "float")
    else:  # a path: its keys are the scene's code (camera_path.py)
        params["CAMERA_FOCAL"] = glsl_value(camera.focal, "float")
    if camera.roll:
        turn = (camera.roll + 180.0) % 360.0 - 180.0  # the same roll, within ±180°
        params["CAMERA_ROLL"] = glsl_value(math.radians(turn), "float")
    if scene.background.color is not None:
        params["BACKGROUND_COLOR"] = glsl_value(scene.background.color, "vec3")
    if scene.environment is not None:
        params["ENV_TOP"] = glsl_value(scene.environment.top, "vec3")
        params["ENV_BOTTOM"] = glsl_value(scene.environment.bottom, "vec3")
    if scene.medium is not None:
        params["MEDIUM_EXTINCTION"] = glsl_value(scene.medium.extinction, "vec3")
        params["MEDIUM_INSCATTER"] = glsl_value(scene.medium.inscatter, "vec3")
    return params
