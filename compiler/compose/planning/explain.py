"""`glint compose --explain`: for each slot, whether it is in the shader and why, and which
variant fills it and why; then the material paths the scene turns on."""

from __future__ import annotations

from glint.compiler.catalog.measurements import load_measurements
from glint.compiler.compose.planning.budget import calls_per_pixel, estimated_cost
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.errors import InputError
from glint.compiler.scene.model import Scene


def explain(scene: Scene, plan: Plan) -> str:
    lines = [f"scene '{scene.name}', tier {plan.tier}", "", "slots:"]
    width = max(len(slot) for slot in plan.uses)
    for slot, use in plan.uses.items():
        name = slot.ljust(width)
        if use.used:
            lines.append(f"  in   {name}  {plan.choices[slot]}: {plan.reasons[slot]}")
            lines.append(f"       {' ' * width}  in because {use.why}")
        else:
            lines.append(f"  out  {name}  {use.why}")
    lines += ["", "material paths:"]
    lines += [f"  {path}" for path in material_paths(scene)]
    cost = estimate(scene, plan)
    if cost:
        lines += ["", cost]
    return "\n".join(lines) + "\n"


def estimate(scene: Scene, plan: Plan) -> str | None:
    """The measured cost per lit pixel of the variants chosen, if there are measurements."""
    try:
        measurements = load_measurements()
    except InputError:
        return None
    calls = calls_per_pixel(scene, plan.uses)
    total = estimated_cost(plan.choices, calls, measurements)
    renderer = measurements.machine.get("renderer", "?")
    return f"estimated cost: {total:.3g} ns per lit pixel (glint bench --update on {renderer})"


def material_paths(scene: Scene) -> list[str]:
    """The optional parts of a Surface, in or out with the materials that ask for them."""
    used = scene.used_materials()
    metals = [m for m in used if scene.materials[m].metallic > 0.0]
    rough = [m for m in used if scene.materials[m].diffuse_roughness is not None]
    translucent = [m for m in used if scene.materials[m].subsurface is not None]
    return [
        _path("metallic (core.metallic)", metals, "metallic > 0"),
        _path("diffuse roughness", rough, "diffuse_roughness"),
        _path("translucency (subsurfaceAt)", translucent, "subsurface"),
    ]


def _path(label: str, materials: list[str], key: str) -> str:
    if not materials:
        return f"out  {label}: no material has {key}"
    names = ", ".join(repr(m) for m in materials)
    return f"in   {label}: {names} ({key})"
