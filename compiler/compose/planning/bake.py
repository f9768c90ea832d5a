"""Parameter baking, the stage after planning: the values of snippet parameters that the scene
sets (camera, environment, medium) and those computed from it (the nine spherical-harmonic
coefficients of the environment for `irradiance.sh9`; a pixel-cone march's tolerance for the
camera's focal length). The emitter writes them as #defines; snippets' defaults cover the
rest."""

from __future__ import annotations

from glint.compiler.catalog.loader import glsl_value, load_catalog
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.planning.spherical_harmonics import (
    project_sh9,
    sh9_params,
    snippet_environment,
)
from glint.compiler.scene.model import LookAtCamera, OrbitCamera, Scene


def bake(scene: Scene, plan: Plan) -> dict[str, str]:
    """#define name -> GLSL value, for the plan's snippets."""
    params = scene_params(scene)
    lit_by_environment = any(light.type == "environment" for light in scene.lights)
    if plan.choices.get("irradiance") == "irradiance.sh9" and lit_by_environment:
        params |= _sh9_params(plan.choices["env"], params)
    params |= _march_pixel(scene, plan)
    return params


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
    elif isinstance(camera, LookAtCamera):
        params["CAMERA_POSITION"] = glsl_value(camera.position, "vec3")
        params["CAMERA_TARGET"] = glsl_value(camera.target, "vec3")
        params["CAMERA_FOCAL"] = glsl_value(camera.focal, "float")
    if scene.environment is not None:
        params["ENV_TOP"] = glsl_value(scene.environment.top, "vec3")
        params["ENV_BOTTOM"] = glsl_value(scene.environment.bottom, "vec3")
    if scene.medium is not None:
        params["MEDIUM_EXTINCTION"] = glsl_value(scene.medium.extinction, "vec3")
        params["MEDIUM_INSCATTER"] = glsl_value(scene.medium.inscatter, "vec3")
    return params
