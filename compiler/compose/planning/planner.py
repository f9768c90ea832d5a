"""The planner: which slots the scene exercises, which variant fills each, and why; and the
parameter values the scene sets.

Which slots are in follows from the scene's content (`scene_slots.py`): no shadow without a
shadow-casting light, no attenuation without a point light, and so on. Slots the content decides
(camera, background, tone map, output transfer) follow the scene; the quality slots follow the
tier table in `snippets/tiers.toml`, then what the content asks for (a rough-diffuse model for
materials with a diffuse roughness, no specular occlusion without AO), then the scene's
`[quality.variants]`, then the command line. Only slots in use get a variant, so the resolver
fails loudly if the generated code reaches a slot the planner did not expect.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

from glint.compiler.catalog.loader import Catalog
from glint.compiler.catalog.measurements import VariantCost, load_measurements
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.catalog.tiers import tier_table
from glint.compiler.compose.codegen.scene_code import generate
from glint.compiler.compose.codegen.trace_code import QUERIES, TRACE_UNIT
from glint.compiler.compose.planning.budget import (
    calls_per_pixel,
    candidates_for,
    estimated_cost,
    within_budget,
)
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.planning.scene_slots import slot_uses
from glint.compiler.compose.units import Unit
from glint.compiler.errors import InputError
from glint.compiler.scene.model import Scene


def plan(
    scene: Scene,
    catalog: Catalog,
    tier: str | None = None,
    variants: dict[str, str] | None = None,
    budget: float | None = None,
    units: list[Unit] | None = None,
    models: tuple[str, Mapping[str, str]] | None = None,
) -> Plan:
    """The plan of `scene` at `tier`; with `budget` (ns per pixel) the quality slots take the
    most accurate measured variants within it instead of the tier's (see budget.py). The slots
    in use are those the scene's generated `units` reach (generated here when not given).
    `models` (key, {slot: variant}): a mesh material's own models, which replace the rest."""
    tier = tier or scene.quality.tier
    if units is None:
        units = generate(scene, tier=tier).units
    tiers = tier_table()
    result = Plan(tier=tier)

    def choose(slot: str, variant: str, why: str) -> None:
        result.choices[slot] = f"{slot}.{variant}"
        result.reasons[slot] = why

    own = tiers.get(tier, {})
    for slot, variant in tiers["balanced"].items():
        choose(slot, variant, f"{tier} tier" if slot in own else f"{tier} tier (as balanced)")
    for slot, variant in own.items():
        choose(slot, variant, f"{tier} tier")
    choose("camera", scene.camera.type, f"camera.type = {scene.camera.type!r}")
    choose("tonemap", scene.post.tonemap, f"post.tonemap = {scene.post.tonemap!r}")
    choose("output", scene.post.output, f"post.output = {scene.post.output!r}")
    has_sun = any(light.type == "directional" for light in scene.lights)
    if scene.background.color is not None:
        choose("background", "color", "background.color is set")
    elif scene.background.sun and has_sun:
        choose("background", "gradient_sun", "background.sun with a directional light")
    else:
        choose("background", "gradient", "no sun to draw in the background")
    fixed = {"camera", "tonemap", "output", "background"}  # what the budget may not change
    if budget is None and any(unit.id == TRACE_UNIT for unit in units):
        # Every object is a sphere, box or plane: closed forms replace the marches (trace_code.py).
        # --budget picks among the measured marching variants instead.
        for slot, variant in tiers.get("analytic", {}).get(tier, {}).items():
            choose(slot, variant, f"{tier} tier: every object is an analytic primitive")
    rough = _rough_materials(scene)
    if rough:
        fixed.add("diffuse")
        why = f"material {rough[0]!r} has diffuse_roughness; the {tier} tier's rough diffuse"
        choose("diffuse", tiers["rough_diffuse"][tier], why)
    if not scene.effects.ao:
        fixed.add("specocc")
        choose("specocc", "none", "effects.ao = false: no occlusion to derive it from")
    for source, table in (
        ("quality.variants", scene.quality.variants),
        ("--variant", variants or {}),
        models or ("", {}),
    ):
        for slot, variant in table.items():
            _check_variant(catalog, source, slot, variant)
            choose(slot, variant, f"{source} {slot} = {variant!r}")
            fixed.add(slot)

    result.uses = slot_uses(scene, catalog, result.choices, units)
    if budget is not None:
        _spend(result, scene, catalog, fixed, budget, choose)
        result.uses = slot_uses(scene, catalog, result.choices, units)
    for slot, use in result.uses.items():
        if not use.used:
            result.choices.pop(slot, None)
            result.reasons.pop(slot, None)
    if "raymarch" in result.reasons and not scene.exact_distance:
        # said for the reader: raymarch.relaxed stays safe on a bound (its overlap test), with
        # more failed relaxed steps
        result.reasons["raymarch"] += (
            "; the scene's field is a bound, not an exact distance (a user field, an "
            "ellipsoid, a blend, a cut or a repetition)"
        )
    return result


def _spend(
    result: Plan,
    scene: Scene,
    catalog: Catalog,
    fixed: set[str],
    budget_ns: float,
    choose: Callable[[str, str, str], None],
) -> None:
    """Replace the tier's variants of the slots in use by the most accurate within the budget."""
    measurements = load_measurements()
    calls = calls_per_pixel(scene, result.uses)
    candidates: dict[str, list[VariantCost]] = {}
    for slot in calls:
        options = (
            None if slot in fixed else candidates_for(slot, result.choices[slot], measurements)
        )
        # the closed-form variants are the tiers' choice for analytic scenes, not the budget's
        options = [o for o in options or [] if not set(QUERIES) & set(catalog.get(o.id).requires)]
        options = options or None
        if options:
            candidates[slot] = options
    rest = {
        slot: v for slot, v in result.choices.items() if slot in calls and slot not in candidates
    }
    fixed_ns = estimated_cost(rest, calls, measurements)
    for slot, pick in within_budget(candidates, calls, fixed_ns, budget_ns).items():
        choose(slot, pick.variant.id.split(".", 1)[1], pick.why)


def _rough_materials(scene: Scene) -> list[str]:
    """Materials in use whose diffuse is rougher than Lambert's."""
    return [
        m for m in scene.used_materials() if (scene.materials[m].diffuse_roughness or 0.0) > 0.0
    ]


def _check_variant(catalog: Catalog, source: str, slot: str, variant: str) -> None:
    if slot not in SLOTS or SLOTS[slot].many:
        one_variant = [name for name, s in SLOTS.items() if not s.many]
        raise InputError(f"{source}.{slot}: unknown slot; slots: {', '.join(one_variant)}")
    variants = sorted(s.variant for s in catalog.in_slot(slot))
    if variant not in variants:
        raise InputError(
            f"{source}.{slot}: unknown variant {variant!r}; variants of {slot}: "
            + ", ".join(variants)
        )
