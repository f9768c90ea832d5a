"""`--budget`: the most accurate variants whose measured cost per pixel fits a budget.

The cost of a shader per pixel is estimated as the sum, over the slots in use, of how often a
pixel calls the slot (once per BRDF light for D, once per shadow-casting light for the shadow)
times the variant's measured time per call (`snippets/measurements.json`, written by
`glint bench --update`). Only variants measured against the same reference as the tier's own
choice compete, so a budget trades accuracy, never the model: it may swap a soft shadow for one
with fewer steps, never GGX for Beckmann. Slots fixed by the scene or the command line count
against the budget as they are.

Choosing one variant per slot under a total cost is a multiple-choice knapsack; the classic
greedy answer is used: start from each slot's cheapest variant on its cost/error front and buy,
while the budget lasts, the upgrade that removes the most error per nanosecond. Errors of
different slots are made comparable by dividing by the largest error on the slot's front.
"""

from __future__ import annotations

from dataclasses import dataclass

from glint.compiler.catalog.measurements import Measurements, VariantCost
from glint.compiler.compose.planning.scene_slots import SlotUse
from glint.compiler.errors import InputError
from glint.compiler.scene.model import DirectionalLight, EnvironmentLight, PointLight, Scene


@dataclass(frozen=True)
class Pick:
    variant: VariantCost
    why: str


def calls_per_pixel(scene: Scene, uses: dict[str, SlotUse]) -> dict[str, int]:
    """How many times a lit pixel calls each slot in use (an estimate: a loop in the scene code
    or a miss of the ray changes it)."""
    directional = sum(isinstance(light, DirectionalLight) for light in scene.lights)
    point = sum(isinstance(light, PointLight) for light in scene.lights)
    casters = sum(
        isinstance(light, DirectionalLight | PointLight) and light.shadow for light in scene.lights
    )
    environment_lights = sum(isinstance(light, EnvironmentLight) for light in scene.lights)
    reflection = int(uses["ibl"].used)
    brdf = directional + point
    calls = {
        "D": brdf, "V": brdf, "diffuse": brdf, "specular": brdf, "F": brdf + reflection,
        "attenuation": point, "shadow": casters, "irradiance": environment_lights,
        "env": 1 + reflection, "sss": directional, "phase": directional,
    }  # fmt: skip
    return {slot: calls.get(slot, 1) for slot, use in uses.items() if use.used}


def front(options: list[VariantCost]) -> list[VariantCost]:
    """Cheapest first, each more accurate than every cheaper one (ties: the first by id)."""
    ordered = sorted(options, key=lambda v: (v.gpu_ns, v.rms, v.id))
    kept: list[VariantCost] = []
    for option in ordered:
        if not kept or option.rms < kept[-1].rms:  # type: ignore[operator]
            kept.append(option)
    return kept


def within_budget(
    candidates: dict[str, list[VariantCost]],
    calls: dict[str, int],
    fixed_ns: float,
    budget_ns: float,
) -> dict[str, Pick]:
    """One variant per slot of `candidates`, the most accurate the budget allows."""
    fronts = {slot: front(options) for slot, options in sorted(candidates.items())}
    level = dict.fromkeys(fronts, 0)

    def cost(slot: str, i: int) -> float:
        return calls[slot] * fronts[slot][i].gpu_ns

    def error(slot: str, i: int) -> float:
        worst = fronts[slot][0].rms or 0.0
        return (fronts[slot][i].rms or 0.0) / worst if worst > 0 else 0.0

    total = fixed_ns + sum(cost(slot, 0) for slot in fronts)
    if total > budget_ns:
        raise InputError(
            f"--budget {budget_ns:g} ns per pixel is below the cheapest combination of measured "
            f"variants, {total:.3g} ns; raise the budget or choose a tier"
        )
    while True:
        best: tuple[float, str] | None = None
        for slot, i in level.items():
            if i + 1 == len(fronts[slot]):
                continue
            extra = cost(slot, i + 1) - cost(slot, i)
            if total + extra > budget_ns:
                continue
            gain = (error(slot, i) - error(slot, i + 1)) / max(extra, 1e-9)
            if best is None or gain > best[0]:
                best = (gain, slot)
        if best is None:
            break
        slot = best[1]
        total += cost(slot, level[slot] + 1) - cost(slot, level[slot])
        level[slot] += 1
    picks = {}
    for slot, i in level.items():
        chosen = fronts[slot][i]
        why = (
            f"--budget {budget_ns:g} ns/pixel: rms {chosen.rms:.3g} for {chosen.gpu_ns:.3g} ns/call"
        )
        if i + 1 < len(fronts[slot]):
            better = fronts[slot][i + 1]
            why += f" ({better.id} is more accurate but does not fit)"
        picks[slot] = Pick(chosen, why)
    return picks


def candidates_for(
    slot: str, tier_choice: str, measurements: Measurements
) -> list[VariantCost] | None:
    """Measured variants of `slot` that share the reference of the tier's choice; None when
    the tier's choice has no measured error (the budget leaves that slot to the tier)."""
    own = measurements.variants.get(tier_choice)
    if own is None or own.reference is None or own.rms is None:
        return None
    return [
        v
        for v in measurements.variants.values()
        if v.slot == slot and v.reference == own.reference and v.rms is not None
    ]


def estimated_cost(
    choices: dict[str, str], calls: dict[str, int], measurements: Measurements
) -> float:
    """ns per pixel of the chosen variants (those measured)."""
    return sum(
        calls.get(slot, 1) * measurements.variants[variant].gpu_ns
        for slot, variant in choices.items()
        if variant in measurements.variants
    )
