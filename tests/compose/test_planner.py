"""The planner derives the slots a scene exercises from its content: every slot it says is in
reaches the shader and none it says is out does, for the example scenes and for scenes built
from every combination of features; and each content rule is checked on its own."""

from __future__ import annotations

import itertools
import random
import re
from pathlib import Path
from typing import Any

import pytest
from mesh_scenes import MESH_EXAMPLES, example_params

from glint import compose_mesh
from glint.compiler.catalog.loader import load_catalog
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.catalog.tiers import TIERS, tier_table
from glint.compiler.cli import main
from glint.compiler.compose.pipeline import compose_scene
from glint.compiler.compose.planning.explain import explain
from glint.compiler.compose.planning.planner import plan
from glint.compiler.scene.model import Scene, load_scene

CATALOG = load_catalog()
# The raymarched examples here; the mesh ones (a plan per material) below.
EXAMPLES = example_params("a plan per material: test_mesh_programs_emit_their_planned_slots")


def emitted_slots(scene: Scene, tier: str = "balanced", **overrides: str) -> set[str]:
    shader = compose_scene(scene, tier=tier, variants=overrides or None)
    return {u.slot for u in shader.units if u.slot in SLOTS and not SLOTS[u.slot].many}


def planned_slots(scene: Scene, tier: str = "balanced", **overrides: str) -> set[str]:
    the_plan = plan(scene, CATALOG, tier, overrides or None)
    assert set(the_plan.choices) == {s for s, use in the_plan.uses.items() if use.used}
    return set(the_plan.choices)


def build(
    lights: list[dict[str, Any]] | None = None,
    material: dict[str, Any] | None = None,
    **sections: Any,
) -> Scene:
    """A sphere on a plane, with the given lights, sphere material and top-level sections."""
    data: dict[str, Any] = {
        "objects": [
            {"shape": "sphere", "radius": 1.0, "material": "a"},
            {"shape": "plane", "normal": [0, 1, 0], "offset": 1.0, "material": "b"},
        ],
        "materials": {
            "a": {"albedo": [0.8, 0.2, 0.2], **(material or {})},
            "b": {"albedo": [0.5] * 3},
        },
        "lights": lights or [],
    }
    return Scene.model_validate(data | sections)


SUN = {"type": "directional", "direction": [0.6, 0.8, -0.5]}
LAMP = {"type": "point", "position": [1.0, 1.0, 1.0]}


@pytest.mark.parametrize("tier", TIERS)
@pytest.mark.parametrize("path", EXAMPLES)
def test_planned_slots_are_the_emitted_slots_for_every_example(path: Path, tier: str) -> None:
    scene = load_scene(path)
    assert planned_slots(scene, tier) == emitted_slots(scene, tier)


@pytest.mark.parametrize("tier", TIERS)
@pytest.mark.parametrize("path", MESH_EXAMPLES, ids=lambda p: p.stem)
def test_mesh_programs_emit_their_planned_slots(path: Path, tier: str) -> None:
    """Each material's program holds, over its two stages, the slots its plan takes, with the
    variants its `models` name."""
    for program in compose_mesh(path, tier=tier).programs:
        units = program.vertex.units + program.fragment.units
        emitted = {u.id for u in units if u.slot in SLOTS and not SLOTS[u.slot].many}
        assert emitted == set(program.plan.choices.values()), program.material
        models = program.scene.materials[program.material].models
        assert {f"{slot}.{variant}" for slot, variant in models.items()} <= emitted


# Features that bring slots in or keep them out, each with its alternatives.
FEATURES: dict[str, list[dict[str, Any]]] = {
    "sun": [{}, {"sun": dict(SUN)}, {"sun": SUN | {"shadow": False}}],
    "lamp": [{}, {"lamp": dict(LAMP)}, {"lamp": LAMP | {"shadow": False}}],
    "fill": [{}, {"fill": {"type": "sky"}}, {"fill": {"type": "back", "direction": [1, 0, 0]}}],
    "envlight": [{}, {"envlight": {"type": "environment"}}],
    "environment": [{}, {"environment": {"reflection": False}}, {"environment": None}],
    "effects": [{}, {"effects": {"ao": False}}],
    "medium": [{}, {"medium": {}}, {"medium": {"level": 0.0}}],
    "material": [
        {},
        {"metallic": 1.0},
        {"subsurface": [0.5, 0.4, 0.3]},
        {"diffuse_roughness": 0.5},
    ],
}


def random_scenes(count: int) -> list[tuple[str, Scene]]:
    choices = list(itertools.product(*FEATURES.values()))
    picked = random.Random(5).sample(choices, count)
    scenes = []
    for combo in picked:
        merged: dict[str, Any] = {}
        for part in combo:
            merged |= part
        lights = [merged.pop(k) for k in ("sun", "lamp", "fill", "envlight") if k in merged]
        material = {
            k: merged.pop(k) for k in ("metallic", "subsurface", "diffuse_roughness") if k in merged
        }
        scenes.append((repr(combo), build(lights, material, **merged)))
    return scenes


@pytest.mark.parametrize("label,scene", random_scenes(40), ids=[str(i) for i in range(40)])
def test_planned_slots_are_the_emitted_slots_for_feature_combinations(
    label: str, scene: Scene
) -> None:
    for tier in TIERS:
        assert planned_slots(scene, tier) == emitted_slots(scene, tier), (label, tier)


def test_shadow_only_with_a_shadow_casting_light() -> None:
    lit = build([SUN | {"shadow": False}, LAMP | {"shadow": False}])
    the_plan = plan(lit, CATALOG)
    assert not the_plan.uses["shadow"].used
    assert the_plan.uses["shadow"].why == "no light casts a shadow"
    assert "shadow" in planned_slots(build([SUN | {"shadow": False}, LAMP]))


def test_attenuation_only_with_a_point_light() -> None:
    assert "attenuation" not in planned_slots(build([SUN]))
    the_plan = plan(build([SUN, LAMP]), CATALOG)
    assert the_plan.uses["attenuation"].used
    assert "lights[1] (point)" in the_plan.uses["attenuation"].why


def test_no_brdf_without_a_directional_or_point_light() -> None:
    sky = build([{"type": "sky"}])
    assert not {"D", "F", "V", "diffuse", "specular"} & planned_slots(sky)
    # F comes back with a reflection variant that is weighted by Fresnel.
    slots = planned_slots(sky, ibl="simple_reflection")
    assert "F" in slots and "ibl" in slots and "D" not in slots
    unreflected = build([{"type": "sky"}], environment={"reflection": False})
    assert "F" not in planned_slots(unreflected, ibl="simple_reflection")


def test_metallic_path_only_with_a_metallic_material() -> None:
    plain = compose_scene(build([SUN]))
    metal = compose_scene(build([SUN], {"metallic": 0.7}))
    assert "core.metallic" not in {u.id for u in plain.units}
    assert "applyMetallic(" not in plain.text and "s.f0, albedo" not in plain.text
    assert "core.metallic" in {u.id for u in metal.units}
    # the metallic is a named constant (a knob a page can turn), 0.7 here
    metallic = re.search(r"applyMetallic\(s, (MAT_\w+)_ALBEDO, (MAT_\w+_METALLIC)\);", metal.text)
    assert metallic is not None and f"#define {metallic.group(2)} 0.7\n" in metal.text
    assert f"#define {metallic.group(1)}_ALBEDO vec3(0.8, 0.2, 0.2)\n" in metal.text


def test_rough_diffuse_model_only_with_a_diffuse_roughness() -> None:
    for tier in TIERS:
        assert plan(build([SUN]), CATALOG, tier).choices["diffuse"] == "diffuse.lambert"
        rough = plan(build([SUN], {"diffuse_roughness": 0.4}), CATALOG, tier)
        assert rough.choices["diffuse"].startswith("diffuse.oren_nayar")
        assert "diffuse_roughness" in rough.reasons["diffuse"]
    # σ = 0 is Lambert: no rough model for it.
    assert (
        plan(build([SUN], {"diffuse_roughness": 0.0}), CATALOG).choices["diffuse"]
        == "diffuse.lambert"
    )
    # An explicit choice wins over the content's.
    chosen = plan(build([SUN], {"diffuse_roughness": 0.4}), CATALOG, variants={"diffuse": "burley"})
    assert chosen.choices["diffuse"] == "diffuse.burley"


def test_no_ao_when_it_is_off_and_no_specular_occlusion_without_it() -> None:
    off = plan(build([SUN, {"type": "sky"}], effects={"ao": False}), CATALOG)
    assert not off.uses["ao"].used and off.uses["ao"].why == "effects.ao = false"
    assert off.choices["specocc"] == "specocc.none"
    on = plan(build([SUN, {"type": "sky"}]), CATALOG)
    assert on.uses["ao"].used and on.choices["specocc"] == "specocc.power"


def test_no_environment_terms_without_an_environment() -> None:
    the_plan = plan(build([SUN], environment=None), CATALOG)
    assert not the_plan.uses["ibl"].used and not the_plan.uses["irradiance"].used
    assert the_plan.uses["ibl"].why == "the scene has no environment"


def test_translucency_needs_a_directional_light() -> None:
    lamp_only = build([LAMP], {"subsurface": [0.5, 0.4, 0.3]})
    the_plan = plan(lamp_only, CATALOG)
    assert not the_plan.uses["sss"].used
    assert "no directional light" in the_plan.uses["sss"].why
    assert "subsurfaceAt" not in compose_scene(lamp_only).text


def test_an_override_of_a_slot_not_in_use_brings_nothing_in() -> None:
    scene = build([SUN | {"shadow": False}])
    assert "shadow" not in planned_slots(scene, shadow="soft_64")
    assert "shadow.soft_64" not in compose_scene(scene, variants={"shadow": "soft_64"}).text


def test_explain_names_every_slot_with_its_reason() -> None:
    scene = build([SUN, {"type": "sky"}], {"metallic": 1.0}, effects={"ao": False})
    text = explain(scene, plan(scene, CATALOG))
    for slot, spec in SLOTS.items():
        if not spec.many:
            assert f"  {slot} " in text
    assert "out  ao           effects.ao = false" in text
    analytic = "balanced tier: every object is an analytic primitive"
    assert f"in   shadow       shadow.analytic: {analytic}" in text
    assert "in because lights[0] (directional) casts shadows" in text
    assert "in   metallic (core.metallic): 'a' (metallic > 0)" in text


def test_compose_explain_on_the_command_line(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    assert main(["compose", "--explain", "--tier", "fast"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("scene 'default', tier fast")
    assert "void mainImage" not in out  # the explanation instead of the shader
    target = tmp_path / "s.glsl"
    assert main(["compose", "--explain", "-o", str(target)]) == 0
    assert "void mainImage" in target.read_text()


def test_analytic_scenes_trace_in_closed_form_at_the_tiers_that_say_so() -> None:
    # A sphere on a plane: no march at fast and balanced, the marcher at reference.
    scene = build([SUN])
    tiers = tier_table()["analytic"]
    for tier in TIERS:
        choices = plan(scene, CATALOG, tier).choices
        for slot in ("raymarch", "normal", "shadow"):
            want = tiers.get(tier, {}).get(slot)
            if want is None:
                assert choices[slot] != f"{slot}.analytic"
            else:
                assert choices[slot] == f"{slot}.{want}"
    text = compose_scene(scene, tier="fast").text
    for entry in ("float raymarch(", "float shadow(", "vec3 calcNormal("):
        body = text[text.index(entry) :].split("\n}\n")[0]
        assert "map(" not in body, entry


def test_a_shape_without_a_closed_form_keeps_the_march() -> None:
    data = build([SUN]).model_dump()
    data["objects"].append({"shape": "torus", "material": "a", "position": [2.0, 0.0, 0.0]})
    scene = Scene.model_validate(data)
    choices = plan(scene, CATALOG, "fast").choices
    assert choices["raymarch"] != "raymarch.analytic" and choices["shadow"] != "shadow.analytic"
    # a turned box has no axis-aligned slabs either
    data["objects"][-1] = {"shape": "box", "size": [0.5, 0.5, 0.5], "rotation": [0.0, 30.0, 0.0],
                           "material": "a"}  # fmt: skip
    assert plan(Scene.model_validate(data), CATALOG, "fast").choices["normal"] != "normal.analytic"
