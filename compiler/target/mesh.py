"""The mesh targets: a vertex and a fragment shader per program, with the names of three.js'
RawShaderMaterial, in GLSL ES 3.00 (`mesh-webgl2`) or GLSL 3.30 (`mesh-desktop`).

three.js gives a RawShaderMaterial `modelMatrix`, `viewMatrix`, `projectionMatrix` and
`cameraPosition` under these names, and the attributes `position` and `normal`. Its own
`normalMatrix` is in view space; glint's is in world space (the inverse transpose of
modelMatrix's upper 3x3), because glint lights in world space: set it as a uniform of your own.
"""

from __future__ import annotations

MESH_TARGETS = ("mesh-webgl2", "mesh-desktop")
STAGES = ("vert", "frag")
STAGE_NAMES = {"vert": "vertex", "frag": "fragment"}

ATTRIBUTES: tuple[tuple[str, str], ...] = (("vec3", "position"), ("vec3", "normal"))
UNIFORMS: tuple[tuple[str, str, str], ...] = (
    ("mat4", "modelMatrix", "object to world"),
    ("mat4", "viewMatrix", "world to camera"),
    ("mat4", "projectionMatrix", "camera to clip space"),
    ("mat3", "normalMatrix", "world space: inverse transpose of modelMatrix's 3x3"),
    ("vec3", "cameraPosition", "the eye, in world space"),
)


def version_lines(target: str) -> str:
    """What opens every stage of `target`: #version, and the precisions ES needs."""
    if target == "mesh-webgl2":
        return "#version 300 es\nprecision highp float;\nprecision highp int;\n"
    if target == "mesh-desktop":
        return "#version 330\n"
    raise ValueError(f"unknown mesh target {target!r}")


def background_target(target: str) -> str:
    """The full-screen target the background program is emitted for (ShaderToy's uniforms)."""
    return "webgl2" if target == "mesh-webgl2" else "desktop"
