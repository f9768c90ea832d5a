"""Which slots a scene exercises, and why: the planner's reading of the scene's content.

The content (its lights, materials, environment, medium, effects) names what the shading code
calls: a shadow-casting light calls `shadow`, a point light `pointLight`, and so on. Following
those calls through the catalog (a light snippet calls `lightResponse`, which calls `fresnel`,
`diffuse` and `specular`; the Cook-Torrance lobe calls `distribution` and `visibility`) gives
every slot the shader needs; the rest stay out, each with the reason it is out. The resolver
then takes exactly these slots: a slot it reaches that the planner left out is an error, and a
test keeps the two in agreement for every example scene.
"""

from __future__ import annotations

from dataclasses import dataclass

from glint.compiler.catalog.loader import Catalog
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.compose.resolver import providers
from glint.compiler.compose.scene import (
    BackLight,
    BounceLight,
    DirectionalLight,
    EnvironmentLight,
    PointLight,
    Scene,
    SkyLight,
)


@dataclass(frozen=True)
class SlotUse:
    used: bool
    why: str


# Why a slot is out when nothing in the scene reaches it.
_OUT = {
    "D": "no directional or point light is shaded through the BRDF",
    "F": "no BRDF light and no environment reflection",
    "V": "no directional or point light is shaded through the BRDF",
    "diffuse": "no directional or point light is shaded through the BRDF",
    "specular": "no directional or point light is shaded through the BRDF",
    "attenuation": "no point light",
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


def _roots(scene: Scene) -> list[tuple[str, str]]:
    """(symbol the scene's own code calls, why) for every call that depends on content."""
    roots = [
        ("cameraRay", f"camera.type = {scene.camera.type!r}"),
        ("raymarch", "every pixel marches its ray to the first surface"),
        ("calcNormal", "shading needs the surface normal"),
        ("background", "rays that hit nothing show the background"),
        ("tonemap", f"post.tonemap = {scene.post.tonemap!r}"),
        ("outputTransfer", f"post.output = {scene.post.output!r}"),
    ]
    occluded: list[str] = []  # what AO would darken
    first_directional = None
    for i, light in enumerate(scene.lights):
        label = f"lights[{i}] ({light.type})"
        if isinstance(light, DirectionalLight | PointLight):
            function = "directionalLight" if isinstance(light, DirectionalLight) else "pointLight"
            roots.append((function, f"{label} is shaded through the BRDF"))
            if light.shadow:
                roots.append(("shadow", f"{label} casts shadows"))
            if isinstance(light, DirectionalLight) and first_directional is None:
                first_directional = label
        elif isinstance(light, SkyLight | BackLight | BounceLight):
            roots.append((f"{light.type}Light", f"{label} fills the shading"))
            occluded.append(label)
        elif isinstance(light, EnvironmentLight):
            roots.append(("irradianceLight", f"{label} lights with the environment's irradiance"))
            occluded.append(label)
    reflection = scene.environment is not None and scene.environment.reflection
    if reflection:
        roots.append(("environmentLight", "environment.reflection = true"))
        occluded.append("the environment reflection")
    if scene.effects.ao and occluded:
        roots.append(("ambientOcclusion", f"effects.ao darkens {', '.join(occluded)}"))
    translucent = translucent_materials(scene)
    if translucent and first_directional is not None:
        why = f"material {translucent[0]!r} has subsurface, lit by {first_directional}"
        roots += [("subsurface", why), ("phase", why)]
    if scene.medium is not None:
        kind = "water" if scene.medium.level is not None else "fog"
        roots.append(("medium", f"[medium] ({kind})"))
    return roots


def slot_uses(scene: Scene, catalog: Catalog, choices: dict[str, str]) -> dict[str, SlotUse]:
    """Every one-variant slot: in (and why) or out (and why), given the variant of each slot
    (the variants decide what else is reached: Cook-Torrance calls D and V, Phong does not)."""
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

    for symbol, root in _roots(scene):
        follow(symbol, root)
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
