"""One snippet as a complete ShaderToy shader: the snippet, everything it requires, stand-ins
for what a scene would generate, and a `mainImage`. The catalog check compiles it; probes run it.
"""

from __future__ import annotations

import re

from glint.compiler.catalog.loader import Catalog, Snippet
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.catalog.tiers import tier_table
from glint.compiler.compose.codegen.trace_code import QUERIES, Analytic, trace_glsl
from glint.compiler.compose.linking.emitter import emit, parameter_unit
from glint.compiler.compose.linking.resolver import resolve
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.units import Unit, generated

# Stand-ins for what the composer generates from a scene, so that a snippet that needs the
# scene (`map`, the key light) compiles on its own: the default scene's sphere and ground.
SCENE_STUB = """float map(vec3 p) { return min(length(p) - 1.0, p.y + 1.0); }
int materialAt(vec3 p) { return 0; }
"""
# The same scene's closed-form queries, for the analytic variants (compose/codegen/trace_code.py).
TRACE_STUB = trace_glsl(
    [
        Analytic("sphere", size="1.0"),
        Analytic("plane", normal="vec3(0.0, 1.0, 0.0)", offset="1.0"),
    ]
)
# A bounded marcher's span where the stand-in scene gives none: the whole ray.
WHOLE_SPAN = "vec2 sceneSpan(vec3 ro, vec3 rd) { return vec2(0.0, 1e30); }\n"
# A path camera's keyframes where the stand-in scene has none: the look-at camera's default.
STILL_PATH = (
    "void cameraPath(float t, out vec3 eye, out vec3 target) "
    "{ eye = vec3(0.0, 1.0, 4.0); target = vec3(0.0); }\n"
)
SCENE_DEFINES = {"SUN_DIR": "normalize(vec3(0.6, 0.8, -0.5))", "SUN_COLOR": "vec3(2.0)"}
# Choices for the slots a scene's content decides, when a snippet needs one of them.
CONTENT_CHOICES = {
    "camera": "camera.orbit",
    "background": "background.gradient",
    "tonemap": "tonemap.none",
    "output": "output.gamma22",
}
EMPTY_MAIN = "void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(0.0); }\n"


def standalone_choices(snippet: Snippet) -> dict[str, str]:
    """Balanced-tier variants for every slot, with the snippet itself filling its own slot."""
    choices = {slot: f"{slot}.{v}" for slot, v in tier_table()["balanced"].items()}
    choices |= CONTENT_CHOICES
    if not SLOTS[snippet.slot].many:
        choices[snippet.slot] = snippet.id
    return choices


def standalone_source(
    snippet: Snippet, catalog: Catalog, main: str = EMPTY_MAIN, scene_stub: str = SCENE_STUB
) -> str:
    """The snippet and its dependencies (balanced-tier choices for other slots) with `main`.
    `scene_stub` stands in for the scene: it defines `map` and `materialAt`."""
    choices = standalone_choices(snippet)
    defined = set(_DEFINITION.findall(scene_stub))
    if any(name in QUERIES and name not in defined for name in snippet.requires):
        scene_stub += TRACE_STUB  # the default scene's queries, where the stub has none
    if "sceneSpan" in snippet.requires and "sceneSpan" not in defined:
        scene_stub += WHOLE_SPAN
    if "cameraPath" in snippet.requires and "cameraPath" not in defined:
        scene_stub += STILL_PATH
    scene = stub_unit(scene_stub, catalog)
    entry = generated("scene.main", ["mainImage"], list(snippet.provides), main)
    units = resolve([scene, entry], catalog, choices, constants=SCENE_DEFINES)
    plan = Plan(tier="balanced", choices=choices)
    units = [parameter_unit(units, catalog, plan, SCENE_DEFINES), *units]
    return emit(snippet.id, plan, units, "shadertoy", "standalone")


_DEFINITION = re.compile(r"^[A-Za-z_]\w*\s+([A-Za-z_]\w*)\s*\([^;{]*\)\s*\{", re.M)
_CALL = re.compile(r"\b([A-Za-z_]\w*)\s*\(")


def stub_unit(scene_stub: str, catalog: Catalog) -> Unit:
    """The stand-in scene as a unit: it provides the functions it defines and requires the
    catalog functions it calls (the closed-form queries call the `trace` snippets)."""
    provides = list(dict.fromkeys(_DEFINITION.findall(scene_stub)))
    called = {name for name in _CALL.findall(scene_stub) if name not in provides}
    requires = sorted(name for name in called if catalog.providers(name))
    return generated("scene.stub", provides, requires, scene_stub)
