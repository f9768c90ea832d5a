"""Scene to shader: generate the scene's own code, plan, bake, resolve, prune, emit."""

from __future__ import annotations

import re
from collections.abc import Collection, Mapping
from dataclasses import replace
from importlib.metadata import version as package_version

from glint.compiler.catalog.loader import Catalog, Snippet, load_catalog
from glint.compiler.compose.codegen.scene_code import MIRROR_UNIT, generate
from glint.compiler.compose.linking.emitter import Composition, emit, parameter_unit
from glint.compiler.compose.linking.reachability import ROOTS, prune_unreachable
from glint.compiler.compose.linking.resolver import resolve
from glint.compiler.compose.linking.uniform_params import (
    UniformParam,
    as_uniforms,
    candidates,
    constant_uses,
    defined_params,
    manifest_comment,
)
from glint.compiler.compose.planning.bake import bake
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.planning.planner import plan
from glint.compiler.compose.units import CONSTANTS, Unit
from glint.compiler.errors import InputError, UsageError
from glint.compiler.scene.model import Scene

DERIVATIVES = re.compile(r"\b(dFdx|dFdy|fwidth)\s*\(")


def uses_derivatives(snippet: Snippet) -> bool:
    """Whether the snippet takes screen-space derivatives (which need uniform control flow)."""
    return DERIVATIVES.search(snippet.body) is not None


def glint_version() -> str:
    return package_version("glint")


def compose_scene(
    scene: Scene,
    target: str = "shadertoy",
    tier: str | None = None,
    variants: dict[str, str] | None = None,
    budget: float | None = None,
    params_as_uniforms: bool = False,
) -> Composition:
    """Compose a scene; `budget` (ns per pixel) picks the quality variants from measurements;
    `params_as_uniforms` (webgl2 only) makes the ranged parameters uniforms a page can set."""
    if scene.is_mesh:
        raise InputError(
            f"objects: the scene's objects are meshes, which a {target} fragment shader cannot "
            "draw: compose it with --target mesh-webgl2 or mesh-desktop (a vertex and a "
            "fragment shader per material)"
        )
    catalog = load_catalog()
    tier = tier or scene.quality.tier
    code = generate(scene, tier=tier)
    the_plan = plan(scene, catalog, tier, variants, budget, code.units)
    the_plan = replace(the_plan, params=bake(scene, the_plan))
    if uses_derivatives(catalog.get(the_plan.choices["normal"])):
        if any(unit.id == MIRROR_UNIT for unit in code.units):
            raise InputError(
                f"effects.reflections: the normal variant {the_plan.choices['normal']} takes "
                "screen-space derivatives, which a mirror ray's hit has none of; choose "
                "another normal variant (--variant normal=central_differences), or turn "
                "reflections off"
            )
        # the same calls, written so that the normal is taken in uniform control flow
        code = generate(scene, normal_in_uniform_flow=True, tier=tier)
    units = assemble(code.units, catalog, the_plan, code.defines)
    return emit_shader(scene.name, the_plan, units, target, params_as_uniforms, catalog, code.knobs)


def assemble(
    units: list[Unit],
    catalog: Catalog,
    the_plan: Plan,
    defines: dict[str, str],
    roots: frozenset[str] = ROOTS,
) -> list[Unit]:
    """The generated units with the snippets they reach, the #define block first, less what
    `roots` never reach."""
    # The #define block gives the light names snippets may require (SUN_DIR) and the parameters
    # of the snippets the resolver took; it goes first.
    units = resolve(units, catalog, the_plan.choices, constants=defines)
    units = [parameter_unit(units, catalog, the_plan, defines), *units]
    # Units come whole; drop what is never reached, parameters included, now that the block
    # is written.
    return prune_unreachable(units, roots)


def emit_shader(
    scene_name: str,
    the_plan: Plan,
    units: list[Unit],
    target: str,
    params_as_uniforms: bool = False,
    catalog: Catalog | None = None,
    knobs: Mapping[str, UniformParam] | None = None,
) -> Composition:
    """Emit composed units for `target`: the last step of composing, also used to emit one
    composition for a second target without planning it again (the site's live canvases)."""
    if params_as_uniforms and target != "webgl2":
        # ShaderToy's Image tab cannot declare uniforms, and only the site's WebGL2 canvas sets them
        raise UsageError(f"--params-as-uniforms needs --target webgl2, not {target}")
    uniforms: list[UniformParam] = []
    if params_as_uniforms:
        catalog = catalog or load_catalog()
        units, uniforms = _params_as_uniforms(
            scene_name, the_plan, units, catalog, target, knobs or {}
        )
    text = emit(scene_name, the_plan, units, target, glint_version())
    return Composition(text=text, units=units, plan=the_plan, uniforms=uniforms)


def _params_as_uniforms(
    scene_name: str,
    the_plan: Plan,
    units: list[Unit],
    catalog: Catalog,
    target: str,
    knobs: Mapping[str, UniformParam],
) -> tuple[list[Unit], list[UniformParam]]:
    """The units with the ranged parameters the pruned block still defines turned into
    uniforms, except those the shader needs as constants; and those uniforms, in block order.
    `knobs` are the scene's own values a page may set (scene_code: light intensities, material
    roughness and metallic, exposure)."""
    index = next((i for i, unit in enumerate(units) if unit.id == CONSTANTS), None)
    if index is None:
        return units, []
    block = units[index].body
    ranged = {**candidates(units, catalog, the_plan), **knobs}
    params = [ranged[name] for name in defined_params(block, ranged)]
    by_name = {p.name: p for p in params}

    def shader_with(names: Collection[str]) -> str:
        body = as_uniforms(block, [by_name[name] for name in names])
        trial = [*units[:index], replace(units[index], body=body), *units[index + 1 :]]
        return emit(scene_name, the_plan, trial, target, "")

    # Keep as #define what the shader needs as a constant (found by parsing it, not listed).
    constant = constant_uses(by_name, shader_with)
    params = [p for p in params if p.name not in constant]
    body = as_uniforms(block, params) + manifest_comment(params)
    return [*units[:index], replace(units[index], body=body), *units[index + 1 :]], params
