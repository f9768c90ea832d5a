"""The emitter: resolved units to one self-contained shader source for a target.

The ShaderToy target is exactly what pastes into the Image tab: a header naming the snippets,
the parameter block, then every unit once, each behind a `// source: FILE:LINE` marker that lets
`glint validate` map an error back to the snippet it came from (a unit that pruning cut into
pieces carries a marker of its own before each later piece). Nothing varies between runs: the
same scene gives the same bytes.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from glint.compiler.catalog.loader import Catalog, glsl_value
from glint.compiler.compose.linking.uniform_params import UniformParam
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.units import CONSTANTS, GENERATED, Unit, generated
from glint.compiler.scene.values import comment_text
from glint.compiler.target import shadertoy
from glint.compiler.target.sourcemap import source_marker

TARGETS = shadertoy.TARGETS


@dataclass
class Composition:
    text: str
    units: list[Unit]
    plan: Plan
    # the parameters the page sets as uniforms (--params-as-uniforms; empty without it)
    uniforms: list[UniformParam] = field(default_factory=list)


def parameter_unit(units: list[Unit], catalog: Catalog, plan: Plan, lights: dict[str, str]) -> Unit:
    """The scene's constants and the parameters of the resolved `units`, as the unit that goes
    first (the resolver took its names as given)."""
    block = parameter_block(units, catalog, plan, lights)
    return generated(CONSTANTS, list(lights), [], block, rank=-1)


def parameter_block(units: list[Unit], catalog: Catalog, plan: Plan, lights: dict[str, str]) -> str:
    """`#define` lines for the scene's lights and every parameter of the units taken."""
    lines = ["// Scene constants (light directions point toward the light)."]
    lines += [f"#define {name} {value}" for name, value in lights.items()]
    knobs = {
        name: plan.params.get(name, glsl_value(param.default, param.type))
        for name, param in catalog.params_of(u.id for u in units).items()
    }
    if knobs:
        lines.append("// Parameters of the snippets below.")
        lines += [f"#define {name} {value}" for name, value in knobs.items()]
    return "\n".join(lines) + "\n"


IMAGE_TAB = "Paste into the Image tab of https://www.shadertoy.com/new as it is."


def header(
    scene_name: str,
    plan: Plan,
    units: list[Unit],
    target: str,
    version: str,
    where: str = "",
    what: str = "",
) -> str:
    """The comment that opens a shader; `where` says where a ShaderToy one is pasted, `what`
    (if given) what the shader is."""
    snippets = [u for u in units if u.origin != GENERATED]
    width = max((len(comment_text(u.id)) for u in snippets), default=0)
    if not what:
        what = (
            where or IMAGE_TAB if target == "shadertoy" else f"A complete {target} fragment shader."
        )
    # the scene's strings (its name, a material's in `what`, a file's in a unit's id) go into
    # the comment only through comment_text: no line break or `*/` can end it early
    lines = [
        f"// glint {version} - scene '{comment_text(scene_name)}', tier {plan.tier}, "
        f"target {target}",
        f"// {comment_text(what)}",
        "// Snippets, in order:",
    ]
    lines += [
        f"//   {comment_text(u.id).ljust(width)}  {comment_text(u.summary)}" for u in snippets
    ]
    return "\n".join(lines) + "\n"


def emit(
    scene_name: str,
    plan: Plan,
    units: list[Unit],
    target: str,
    version: str,
    where: str = "",
) -> str:
    parts = [header(scene_name, plan, units, target, version, where), *unit_blocks(units)]
    text = "\n".join(parts)
    return shadertoy.wrap_for(target, text)


def unit_blocks(units: list[Unit]) -> list[str]:
    """Each unit's code behind the marker that maps its lines to its file."""
    blocks = []
    for unit in units:
        body = unit.body.strip("\n")
        line = unit.line + _leading_blank_lines(unit.body)
        blocks.append(f"{source_marker(unit.origin, line)}\n{body}\n")
    return blocks


def _leading_blank_lines(body: str) -> int:
    return len(body) - len(body.lstrip("\n"))
