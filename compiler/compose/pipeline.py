"""Scene to shader: plan, generate the scene's own code, resolve, prune, emit."""

from __future__ import annotations

import re
from dataclasses import replace
from importlib.metadata import version as package_version
from pathlib import Path

from glint.compiler.catalog.loader import Snippet, load_catalog
from glint.compiler.compose.bake import bake
from glint.compiler.compose.emitter import Shader, emit, parameter_unit
from glint.compiler.compose.planner import plan
from glint.compiler.compose.reachability import prune_unreachable
from glint.compiler.compose.resolver import resolve
from glint.compiler.compose.scene import Scene, load_scene
from glint.compiler.compose.scene_code import generate

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
    overrides: dict[str, str] | None = None,
    budget: float | None = None,
) -> Shader:
    """Compose a scene; `budget` (ns per pixel) picks the quality variants from measurements."""
    catalog = load_catalog()
    code = generate(scene)
    the_plan = plan(scene, catalog, tier, overrides, budget, code.units)
    the_plan = replace(the_plan, params=bake(scene, the_plan))
    if uses_derivatives(catalog.get(the_plan.choices["normal"])):
        # the same calls, written so that the normal is taken in uniform control flow
        code = generate(scene, normal_in_uniform_flow=True)
    # The #define block gives the light names snippets may require (SUN_DIR) and the parameters
    # of the snippets the resolver took; it goes first.
    units = resolve(code.units, catalog, the_plan.choices, constants=code.defines)
    units = [parameter_unit(units, catalog, the_plan, code.defines), *units]
    # Units come whole; drop what mainImage never reaches, parameters included, now that the
    # block is written.
    units = prune_unreachable(units)
    text = emit(scene.name, the_plan, units, target, glint_version())
    return Shader(text=text, units=units, plan=the_plan)


def compose(
    scene_path: str | Path | None = None,
    target: str = "shadertoy",
    tier: str | None = None,
    overrides: dict[str, str] | None = None,
    budget: float | None = None,
) -> Shader:
    """Compose a scene file (None: the embedded default scene) into one shader."""
    return compose_scene(load_scene(scene_path), target, tier, overrides, budget)
