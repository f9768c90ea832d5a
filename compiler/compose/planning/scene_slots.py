"""Which slots a scene exercises, and why: the planner's reading of the scene's own code.

The scene's generated units (scene_code.py) call what its content needs, each call with its
reason: a shadow-casting light makes `shade` call `shadow`, a point light `pointLight`, and so
on. Following those calls through the catalog (a light snippet calls `lightResponse`, which
calls `fresnel`, `diffuse` and `specular`; the Cook-Torrance lobe calls `distribution` and
`visibility`) gives every slot the shader needs; the rest stay out, each with the reason it is
out. The resolver follows the same calls (and the same rule of which snippet provides what,
resolver.providers), so it takes exactly these slots; a test checks it for every example scene.
"""

from __future__ import annotations

from dataclasses import dataclass

from glint.compiler.catalog.loader import Catalog
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.compose.linking.resolver import providers
from glint.compiler.compose.units import Unit
from glint.compiler.scene.model import Scene


@dataclass(frozen=True)
class SlotUse:
    used: bool
    why: str


# Why a slot is out when nothing in the scene reaches it.
_OUT = {
    "D": "no light is shaded through the BRDF",
    "F": "no BRDF light and no environment reflection",
    "V": "no light is shaded through the BRDF",
    "diffuse": "no light is shaded through the BRDF",
    "specular": "no light is shaded through the BRDF",
    "attenuation": "no point or spot light",
    "area": "no area light (sphere, disc or rect)",
    "shadow": "no light casts a shadow",
    "specocc": "no environment reflection",
    "env": "nothing samples the environment",
    "ibl": "no environment reflection",
    "irradiance": "no environment light",
    "sss": "no translucent material lit by a directional light",
    "phase": "no translucent material lit by a directional light",
    "media": "no [medium]",
}


def translucent_materials(scene: Scene) -> list[str]:
    return [m for m in scene.used_materials() if scene.materials[m].subsurface is not None]


def slot_uses(
    scene: Scene, catalog: Catalog, choices: dict[str, str], units: list[Unit]
) -> dict[str, SlotUse]:
    """Every one-variant slot: in (and why) or out (and why), from what the scene's generated
    `units` call, given the variant of each slot (the variants decide what else is reached:
    Cook-Torrance calls D and V, Phong does not)."""
    reached: dict[str, str] = {}

    def follow(symbol: str, root: str, caller: str | None = None) -> None:
        slot = _slot_of(symbol, catalog, choices)
        if slot is not None:
            if slot in reached:
                return
            reached[slot] = f"{caller} calls it; {root}" if caller else root
            snippet = catalog.get(choices[slot])
        else:
            library, _ = providers(symbol, catalog, choices)
            if not library:
                return  # a scene symbol (map) or a constant
            snippet = library[0]
        for requirement in snippet.requires:
            follow(requirement, root, snippet.id)

    # mainImage first: what it calls reaches the background before the lights reach the sky
    ordered = sorted(units, key=lambda unit: unit.id != "scene.main")
    for unit in ordered:
        for symbol, root in unit.why:
            follow(symbol, root)
    for unit in ordered:  # then what the scene's code calls whatever its content
        for symbol in unit.requires:
            follow(symbol, f"the scene's code calls it ({unit.id})")
    uses = {}
    for name, slot in SLOTS.items():
        if slot.many:
            continue
        if name in reached:
            uses[name] = SlotUse(True, reached[name])
        else:
            uses[name] = SlotUse(False, _out_reason(name, scene))
    return uses


def _slot_of(symbol: str, catalog: Catalog, choices: dict[str, str]) -> str | None:
    """The one-variant slot a requirement names or whose chosen variant provides it."""
    if symbol in SLOTS and not SLOTS[symbol].many:
        return symbol
    _, chosen = providers(symbol, catalog, choices)
    return chosen[0].slot if chosen else None


def _out_reason(slot: str, scene: Scene) -> str:
    if slot == "ao":
        if not scene.effects.ao:
            return "effects.ao = false"
        return "no fill light and no environment reflection for AO to darken"
    if slot in ("ibl", "specocc") and scene.environment is None:
        return "the scene has no environment"
    if slot in ("sss", "phase") and translucent_materials(scene):
        return "translucent materials, but no directional light to shine through them"
    return _OUT.get(slot, "not reached from the scene's code")
