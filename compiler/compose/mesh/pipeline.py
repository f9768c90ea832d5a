"""Mesh scene to shaders: one program (a vertex and a fragment shader) per material, and a
background program for the pixels no mesh covers.

Each material's program is planned on its own (its shading mode and its `models` decide what
each stage calls, and a program holds one variant per slot), then each stage is resolved,
given its parameter block, pruned from its `main` and emitted behind `#version`, with the
`// source:` markers that map glslang's messages to snippet lines. The background program is
the raymarched scenes' sky with their camera, a full-screen shader with ShaderToy's uniforms.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

from glint.compiler.catalog.loader import Catalog, load_catalog
from glint.compiler.compose.linking.emitter import Composition, header, unit_blocks
from glint.compiler.compose.mesh.code import background_unit, ignored, lit_scene, mesh_code
from glint.compiler.compose.pipeline import assemble, emit_shader, glint_version
from glint.compiler.compose.planning.bake import bake
from glint.compiler.compose.planning.explain import explain
from glint.compiler.compose.planning.plan import Plan
from glint.compiler.compose.planning.planner import plan
from glint.compiler.compose.planning.scene_slots import SlotUse
from glint.compiler.compose.units import Unit
from glint.compiler.errors import InputError, UsageError
from glint.compiler.scene.model import Scene
from glint.compiler.target.glslang import Diagnostic, validate, validate_stage
from glint.compiler.target.mesh import (
    MESH_TARGETS,
    STAGE_NAMES,
    background_target,
    version_lines,
)

MAIN = frozenset({"main"})
# Slots a mesh program never reaches, and why (the planner would say "not reached").
_NOT_IN_MESH_PROGRAMS = {
    "normal": "the mesh gives the normal (per vertex, or the face's from derivatives)",
    "raymarch": "meshes are rasterized, not marched",
    "camera": "the camera is the view and projection matrices",
    "background": "drawn by the background program, before the meshes",
}


@dataclass
class MeshStage:
    text: str  # the complete shader
    units: list[Unit]  # what it holds, in order


@dataclass
class MeshProgram:
    material: str
    shading: str  # gouraud, phong or flat
    plan: Plan
    scene: Scene  # the scene as this program sees it (mesh_code.lit_scene)
    vertex: MeshStage
    fragment: MeshStage


@dataclass
class MeshComposition:
    scene: Scene
    target: str
    programs: list[MeshProgram]
    background: Composition  # a complete fragment shader for a full-screen triangle
    ignored: list[str]  # what the scene asks for that has no effect on meshes

    def files(self, base: str | Path) -> dict[Path, str]:
        """The shaders by file name: BASE.vert and BASE.frag for one material, else
        BASE.MATERIAL.vert and BASE.MATERIAL.frag; and BASE.background.frag. BASE is the
        given path less its suffix (sphere.glsl -> sphere.vert)."""
        path = Path(base)
        stem = path.with_suffix("") if path.suffix in (".glsl", ".vert", ".frag") else path
        out: dict[Path, str] = {}
        for program in self.programs:
            name = stem.name if len(self.programs) == 1 else f"{stem.name}.{program.material}"
            out[stem.with_name(f"{name}.vert")] = program.vertex.text
            out[stem.with_name(f"{name}.frag")] = program.fragment.text
        out[stem.with_name(f"{stem.name}.background.frag")] = self.background.text
        return out

    def validate(self) -> list[Diagnostic]:
        """glslangValidator's diagnostics for every stage (at snippet file and line)."""
        found: list[Diagnostic] = []
        name = self.scene.name
        for program in self.programs:
            for stage in ("vert", "frag"):
                text = program.vertex.text if stage == "vert" else program.fragment.text
                found += validate_stage(text, f"<{name}.{program.material}.{stage}>", stage)
        found += validate(self.background.text, f"<{name}.background.frag>", "desktop")
        return found

    def explain(self) -> str:
        """Each program's slots in or out and why, and what has no effect on meshes."""
        parts = []
        for program in self.programs:
            title = f"program '{program.material}' ({program.shading} shading)"
            parts.append(f"{title}\n{explain(program.scene, program.plan)}")
        notes = self.ignored or ["nothing"]
        parts.append("no effect on meshes:\n" + "".join(f"  {note}\n" for note in notes))
        return "\n".join(parts)


def compose_mesh_scene(
    scene: Scene,
    target: str,
    tier: str | None = None,
    variants: dict[str, str] | None = None,
) -> MeshComposition:
    """The programs of a mesh scene for `target` (mesh-webgl2 or mesh-desktop)."""
    if target not in MESH_TARGETS:
        raise UsageError(f"unknown mesh target {target!r}; expected one of {MESH_TARGETS}")
    if not scene.is_mesh:
        raise InputError(
            f'--target {target} is for mesh scenes (objects with shape = "mesh"); this scene '
            "has none: compose it with --target shadertoy, webgl2 or desktop"
        )
    catalog = load_catalog()
    version = glint_version()
    programs = [
        _program(scene, material, target, tier, variants, catalog, version)
        for material in scene.used_materials()
    ]
    background = _background(scene, target, tier, variants, catalog)
    return MeshComposition(scene, target, programs, background, ignored(scene))


def _program(
    scene: Scene,
    material: str,
    target: str,
    tier: str | None,
    variants: dict[str, str] | None,
    catalog: Catalog,
    version: str,
) -> MeshProgram:
    lit = lit_scene(scene, material)
    code = mesh_code(lit, material)
    models = lit.materials[material].models
    key = (f"materials.{material}.models", models) if models else None
    the_plan = plan(lit, catalog, tier, variants, None, code.vertex + code.fragment, key)
    the_plan = replace(the_plan, params=bake(lit, the_plan))
    the_plan.uses.update({slot: SlotUse(False, why) for slot, why in _NOT_IN_MESH_PROGRAMS.items()})
    shading = lit.shading_of(material)
    stages = []
    for stage, units in (("vert", code.vertex), ("frag", code.fragment)):
        units = assemble(units, catalog, the_plan, code.defines, MAIN)
        what = (
            f"The {STAGE_NAMES[stage]} shader of material '{material}' ({shading} shading); "
            "three.js RawShaderMaterial names, normalMatrix in world space."
        )
        head = header(scene.name, the_plan, units, target, version, what=what)
        text = version_lines(target) + "\n".join([head, *unit_blocks(units)])
        stages.append(MeshStage(text, units))
    return MeshProgram(material, shading, the_plan, lit, stages[0], stages[1])


def _background(
    scene: Scene,
    target: str,
    tier: str | None,
    variants: dict[str, str] | None,
    catalog: Catalog,
) -> Composition:
    """The sky behind the meshes: cameraRay and background, as a full-screen shader."""
    lit = lit_scene(scene)
    defines = mesh_code(lit, scene.used_materials()[0]).defines  # SUN_DIR for the sun disc
    units = [background_unit(scene)]
    the_plan = plan(lit, catalog, tier, variants, None, units)
    the_plan = replace(the_plan, params=bake(lit, the_plan))
    units = assemble(units, catalog, the_plan, defines)
    return emit_shader(scene.name, the_plan, units, background_target(target), catalog=catalog)
