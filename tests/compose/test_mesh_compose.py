"""Mesh composition: both targets, every shading mode, each stage validated by glslang; the
pruning holds per stage (a phong vertex shader has no lighting, a gouraud fragment shader no
BRDF); per-material programs and models; errors mapped to snippet lines."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from mesh_scenes import mesh_scene

import glint
from glint.compiler.target.glslang import validate_stage

# Slots whose code lights a point: none may reach a stage that does not light.
LIGHTING_SLOTS = {"D", "F", "V", "diffuse", "specular", "light", "ibl", "env", "specocc"}
# Slots that need a distance field: no mesh program has them.
FIELD_SLOTS = {"raymarch", "normal", "shadow", "ao", "sss", "phase", "camera"}


def _slots(units: list) -> set[str]:
    return {unit.slot for unit in units}


@pytest.mark.parametrize("target", ["mesh-webgl2", "mesh-desktop"])
@pytest.mark.parametrize("shading", ["gouraud", "phong", "flat"])
def test_every_stage_validates(target: str, shading: str) -> None:
    shader = glint.compose_mesh(mesh_scene(shading=shading), target=target)
    version = "#version 300 es\n" if target == "mesh-webgl2" else "#version 330\n"
    (program,) = shader.programs
    assert program.shading == shading
    assert program.vertex.text.startswith(version) and program.fragment.text.startswith(version)
    assert shader.validate() == []
    assert not FIELD_SLOTS & set(program.plan.choices), program.plan.choices
    assert "position" in program.vertex.text and "gl_Position" in program.vertex.text


def test_gouraud_lights_vertices_and_its_fragment_shader_has_no_brdf() -> None:
    (program,) = glint.compose_mesh(mesh_scene(shading="gouraud")).programs
    assert "vColor = shade(surfaceAt(" in program.vertex.text
    assert {"D", "F", "V", "diffuse", "specular"} <= _slots(program.vertex.units)
    assert not LIGHTING_SLOTS & _slots(program.fragment.units)
    for name in ("shade", "lightResponse", "distribution", "fresnel", "SUN_DIR"):
        assert not re.search(rf"\b{name}\b", program.fragment.text), name


def test_phong_vertex_shader_has_no_lighting() -> None:
    (program,) = glint.compose_mesh(mesh_scene(shading="phong")).programs
    assert not LIGHTING_SLOTS & _slots(program.vertex.units)
    for name in ("shade", "surfaceAt", "SUN_DIR", "Surface"):
        assert not re.search(rf"\b{name}\b", program.vertex.text), name
    assert "vNormal = normalMatrix * normal;" in program.vertex.text
    assert "shade(surfaceAt(P, N, V))" in program.fragment.text


def test_flat_shading_takes_the_face_normal_from_derivatives() -> None:
    (program,) = glint.compose_mesh(mesh_scene(shading="flat")).programs
    assert "cross(dFdx(P), dFdy(P))" in program.fragment.text
    # the vertex normal is not needed: neither the attribute nor the varying survive pruning
    assert "vNormal" not in program.vertex.text and "in vec3 normal;" not in program.vertex.text


def test_programs_per_material_with_their_own_models_and_modes(tmp_path: Path) -> None:
    scene = mesh_scene()
    scene["materials"] = {
        "toon": {"albedo": [0.2, 0.6, 0.2], "models": {"diffuse": "toon", "specular": "phong"}},
        "plain": {"albedo": [0.6, 0.6, 0.6], "shading": "gouraud"},
    }
    sphere = {"shape": "mesh", "builtin": "icosphere", "subdivisions": 2}
    scene["objects"] = [
        {**sphere, "material": "toon", "position": [-1.0, 0.0, 0.0]},
        {**sphere, "material": "plain", "position": [1.0, 0.0, 0.0]},
    ]
    shader = glint.compose_mesh(scene, target="mesh-webgl2")
    toon, plain = shader.programs
    assert (toon.material, toon.shading, plain.shading) == ("toon", "phong", "gouraud")
    assert toon.plan.choices["diffuse"] == "diffuse.toon"
    assert toon.plan.choices["specular"] == "specular.phong"
    assert plain.plan.choices["diffuse"] == "diffuse.lambert"
    assert "materials.toon.models" in toon.plan.reasons["diffuse"]
    assert shader.validate() == []
    names = sorted(path.name for path in shader.save(tmp_path / "spheres"))
    assert names == [
        "spheres.background.frag",
        "spheres.plain.frag",
        "spheres.plain.vert",
        "spheres.toon.frag",
        "spheres.toon.vert",
    ]


def test_unknown_model_names_the_key() -> None:
    scene = mesh_scene()
    scene["materials"]["red"] = {"albedo": [1.0, 0.0, 0.0], "models": {"diffuse": "cel"}}
    with pytest.raises(glint.InputError) as caught:
        glint.compose_mesh(scene)
    message = caught.value.message
    assert message.startswith("materials.red.models.diffuse: unknown variant 'cel'")
    assert "toon" in message


def test_explain_says_what_has_no_effect_on_meshes() -> None:
    scene = mesh_scene(effects={"ao": True})
    scene["lights"] = [{"type": "directional", "direction": [0.0, 1.0, 0.0], "shadow": True}]
    text = glint.compose_mesh(scene).explain()
    assert "program 'red' (phong shading)" in text
    assert "lights[0].shadow = true: no effect on meshes" in text
    assert "effects.ao = true: no effect on meshes" in text
    assert "out  raymarch     meshes are rasterized" in text


def test_vertex_stage_errors_map_to_the_snippet_line() -> None:
    (program,) = glint.compose_mesh(mesh_scene(shading="gouraud")).programs
    broken = program.vertex.text.replace("return a2 / (PI * d * d);", "return a2 / (PI * d * q);")
    assert broken != program.vertex.text
    diagnostics = validate_stage(broken, "<vert>", "vert")
    errors = [d for d in diagnostics if d.severity == "error"]
    assert errors and errors[0].file == "snippets/D/ggx.glsl"
    lines = Path("snippets/D/ggx.glsl").read_text().splitlines()
    assert "return a2 / (PI * d * d);" in lines[errors[0].line - 1]
