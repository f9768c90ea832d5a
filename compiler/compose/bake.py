"""Parameter baking, the stage after planning: the values of snippet parameters that the scene
sets (camera, environment, medium) and those computed from it (the nine spherical-harmonic
coefficients of the environment for `irradiance.sh9`). The emitter writes them as #defines;
snippets' defaults cover the rest."""

from __future__ import annotations

from glint.compiler.catalog.loader import glsl_value
from glint.compiler.compose.planner import Plan
from glint.compiler.compose.scene import LookAtCamera, OrbitCamera, Scene
from glint.compiler.compose.spherical_harmonics import project_sh9, sh9_params, snippet_environment


def bake(scene: Scene, plan: Plan) -> dict[str, str]:
    """#define name -> GLSL value, for the plan's snippets."""
    params = scene_params(scene)
    lit_by_environment = any(light.type == "environment" for light in scene.lights)
    if plan.choices.get("irradiance") == "irradiance.sh9" and lit_by_environment:
        params |= _sh9_params(plan.choices["env"], params)
    return params


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
