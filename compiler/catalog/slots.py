"""The slots of a lighting shader and the contract each one keeps.

A slot is a role in the shader (the normal distribution, the shadow, the tone map). Every
variant of a slot defines the slot's entry function with exactly the slot's prototype, so any
variant replaces any other without touching its callers. Slots marked `many` are libraries
(SDF primitives, light types, patterns) from which a scene takes as many snippets as it needs;
the others hold exactly one variant per shader.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Slot:
    name: str
    summary: str
    entry: str | None = None  # the function every variant defines; None for library slots
    prototype: str | None = None  # its exact GLSL prototype
    many: bool = False  # a library: several snippets of this slot may be used at once


SLOTS: dict[str, Slot] = {
    s.name: s
    for s in (
        Slot("core", "shared constants and structs", many=True),
        Slot("sdf", "signed distance primitives", many=True),
        Slot("trace", "closed-form ray queries of primitives: hit, clearance, normal", many=True),
        Slot("pattern", "procedural albedo patterns", many=True),
        Slot("light", "light types, each a function of the surface", many=True),
        Slot(
            "D",
            "normal distribution function",
            "distribution",
            "float distribution(float NoH, float a)",
        ),
        Slot("F", "Fresnel reflectance", "fresnel", "vec3 fresnel(vec3 f0, float cosTheta)"),
        Slot(
            "V",
            "visibility: the geometry term over 4·NoL·NoV",
            "visibility",
            "float visibility(Dots d, float a)",
        ),
        # The two lobes return reflectance times their own cosine factor (BRDF · N·L), so
        # that wrapped and stylised models, which reshape the cosine, fill the same slot.
        Slot(
            "diffuse",
            "diffuse lobe: BRDF times its cosine factor",
            "diffuse",
            "vec3 diffuse(Surface s, Dots d)",
        ),
        Slot(
            "specular",
            "specular lobe, given the Fresnel term: BRDF times its cosine factor",
            "specular",
            "vec3 specular(Surface s, Dots d, vec3 F)",
        ),
        Slot(
            "attenuation",
            "distance falloff of a point light with a range",
            "attenuation",
            "float attenuation(float dist, float range)",
        ),
        # One entry for the three shapes (sphere, disc, rectangle): `shape` is a constant at
        # every call, so a compiler folds the branches of the two shapes a call does not use.
        Slot(
            "area",
            "light from a sphere, disc or rectangle of uniform radiance",
            "areaLight",
            "vec3 areaLight(Surface s, vec3 center, vec3 right, vec3 up, int shape, vec3 radiance)",
        ),
        Slot(
            "ao",
            "ambient occlusion of the SDF scene",
            "ambientOcclusion",
            "float ambientOcclusion(vec3 p, vec3 n)",
        ),
        Slot(
            "specocc",
            "specular occlusion derived from ambient occlusion",
            "specularOcclusion",
            "float specularOcclusion(float NoV, float ao, float a)",
        ),
        Slot(
            "shadow",
            "shadow ray through the SDF scene",
            "shadow",
            "float shadow(vec3 ro, vec3 rd, float tmin, float tmax)",
        ),
        Slot(
            "env",
            "environment radiance seen along a direction",
            "environment",
            "vec3 environment(vec3 dir)",
        ),
        Slot(
            "ibl",
            "image-based (environment) specular lighting",
            "environmentLight",
            "vec3 environmentLight(Surface s, float ao)",
        ),
        Slot(
            "irradiance",
            "diffuse light from the environment: cosine-weighted irradiance over π",
            "irradiance",
            "vec3 irradiance(vec3 n)",
        ),
        Slot(
            "sss",
            "light transmitted through thin parts of the SDF toward L",
            "subsurface",
            "float subsurface(vec3 p, vec3 L)",
        ),
        Slot(
            "phase",
            "phase function of a scattering medium",
            "phase",
            "float phase(float cosTheta, float g)",
        ),
        Slot(
            "media",
            "radiance after a distance through a participating medium (extinction, in-scatter)",
            "medium",
            "vec3 medium(vec3 color, float dist)",
        ),
        Slot("normal", "surface normal of the SDF", "calcNormal", "vec3 calcNormal(vec3 p)"),
        Slot(
            "raymarch",
            "ray/scene intersection",
            "raymarch",
            "float raymarch(vec3 ro, vec3 rd)",
        ),
        Slot(
            "camera",
            "primary ray for a pixel",
            "cameraRay",
            "void cameraRay(vec2 fragCoord, out vec3 ro, out vec3 rd)",
        ),
        Slot(
            "background",
            "colour of rays that hit nothing",
            "background",
            "vec3 background(vec3 rd)",
        ),
        Slot("tonemap", "HDR to display range", "tonemap", "vec3 tonemap(vec3 color)"),
        Slot(
            "output",
            "linear to display transfer function",
            "outputTransfer",
            "vec3 outputTransfer(vec3 color)",
        ),
    )
}

# Symbols the composer generates from the scene itself; snippets may require them. The
# functions with their prototypes, the constants with their type and meaning.
SCENE_FUNCTIONS: dict[str, str] = {
    "map": "float map(vec3 p)",
    "materialAt": "int materialAt(vec3 p)",
    # Only for a scene whose every object is an analytic primitive (an unplaced sphere, box or
    # plane): the closed-form queries of compose/codegen/trace_code.py.
    "traceScene": "float traceScene(vec3 ro, vec3 rd, float tmax)",
    "sceneClearance": "float sceneClearance(vec3 ro, vec3 rd, float tmax, float reach)",
    "sceneNormal": "vec3 sceneNormal(vec3 p)",
    # The part (start, end) of a ray where surfaces can be (compose/codegen/bounds.py).
    "sceneSpan": "vec2 sceneSpan(vec3 ro, vec3 rd)",
    # A path camera's keyframes as a curve (compose/codegen/camera_path.py).
    "cameraPath": "void cameraPath(float t, out vec3 eye, out vec3 target)",
}
SCENE_CONSTANTS: dict[str, str] = {
    "SUN_DIR": "vec3 direction toward the scene's key (sun) light",
    "SUN_COLOR": "vec3 radiance of the key light",
}
SCENE_SYMBOLS: dict[str, str] = SCENE_FUNCTIONS | SCENE_CONSTANTS


def slot_of_entry(name: str) -> Slot | None:
    """The slot whose entry function is `name`, if any."""
    for slot in SLOTS.values():
        if slot.entry == name:
            return slot
    return None
