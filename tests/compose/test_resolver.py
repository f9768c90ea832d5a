"""The resolver: every reachable unit once, dependencies first; clear errors otherwise."""

from __future__ import annotations

import pytest

from glint.compiler.catalog.loader import Catalog, load_catalog, parse_snippet
from glint.compiler.catalog.slots import SCENE_FUNCTIONS
from glint.compiler.compose.linking.resolver import resolve
from glint.compiler.compose.units import generated
from glint.compiler.errors import InputError


def snippet(slot: str, variant: str, provides: list[str], requires: list[str], body: str = ""):
    front = (
        "/* ---\n"
        f'id = "{slot}.{variant}"\nslot = "{slot}"\nsummary = "test"\n'
        f"provides = {provides!r}\nrequires = {requires!r}\nsources = []\n"
        "--- */\n"
    ).replace("'", '"')
    return parse_snippet(front + body, f"snippets/{slot}/{variant}.glsl")


def catalog_of(*snippets) -> Catalog:
    return Catalog({s.id: s for s in snippets})


def ids(units) -> list[str]:
    return [u.id for u in units]


def test_dependencies_come_first_and_each_unit_once() -> None:
    cat = catalog_of(
        snippet("core", "constants", ["PI"], []),
        snippet("D", "ggx", ["distribution"], ["PI"]),
        snippet("V", "smith", ["visibility"], ["PI"]),
        snippet("specular", "ct", ["specular"], ["D", "V", "PI"]),
    )
    root = generated("scene.main", ["mainImage"], ["specular", "distribution"], "")
    choices = {"D": "D.ggx", "V": "V.smith", "specular": "specular.ct"}
    order = ids(resolve([root], cat, choices))
    assert sorted(order) == sorted(set(order))
    assert order.index("core.constants") < order.index("D.ggx") < order.index("specular.ct")
    assert order.index("V.smith") < order.index("specular.ct") < order.index("scene.main")


def test_only_reachable_units_are_taken() -> None:
    cat = catalog_of(
        snippet("core", "constants", ["PI"], []),
        snippet("sdf", "box", ["sdBox"], []),
        snippet("tonemap", "reinhard", ["tonemap"], []),
    )
    root = generated("scene.main", ["mainImage"], ["tonemap"], "")
    assert ids(resolve([root], cat, {"tonemap": "tonemap.reinhard"})) == [
        "tonemap.reinhard",
        "scene.main",
    ]


def test_chosen_variant_fills_a_slot() -> None:
    cat = catalog_of(
        snippet("shadow", "soft", ["shadow"], []),
        snippet("shadow", "hard", ["shadow"], []),
    )
    root = generated("scene.shade", ["shade"], ["shadow"], "")
    assert "shadow.hard" in ids(resolve([root], cat, {"shadow": "shadow.hard"}))
    assert "shadow.soft" in ids(resolve([root], cat, {"shadow": "shadow.soft"}))


def test_missing_provider_names_the_requirer() -> None:
    cat = catalog_of(snippet("D", "ggx", ["distribution"], ["PI"]))
    root = generated("scene.main", ["mainImage"], ["distribution"], "")
    with pytest.raises(InputError, match="D.ggx requires 'PI', which no unit provides"):
        resolve([root], cat, {"D": "D.ggx"})


def test_unchosen_slot_variant_is_named() -> None:
    cat = catalog_of(snippet("ao", "sdf5", ["ambientOcclusion"], []))
    root = generated("scene.shade", ["shade"], ["ambientOcclusion"], "")
    with pytest.raises(InputError, match="provided by ao.sdf5, which the plan did not choose"):
        resolve([root], cat, {})


def test_two_providers_of_one_symbol() -> None:
    cat = catalog_of(
        snippet("core", "a", ["PI"], []),
        snippet("core", "b", ["PI"], []),
    )
    root = generated("scene.main", ["mainImage"], ["PI"], "")
    with pytest.raises(InputError, match="'PI' required by scene.main is provided by both"):
        resolve([root], cat, {})


def test_a_unit_clashing_with_a_generated_one() -> None:
    cat = catalog_of(snippet("core", "a", ["map", "helper"], []))
    roots = [
        generated("scene.map", ["map"], [], ""),
        generated("scene.main", ["mainImage"], ["helper"], ""),
    ]
    with pytest.raises(InputError, match="'map' is provided by both scene.map and core.a"):
        resolve(roots, cat, {})


def test_cycle_names_the_units() -> None:
    cat = catalog_of(
        snippet("core", "a", ["A"], ["B"]),
        snippet("core", "b", ["B"], ["C"]),
        snippet("core", "c", ["C"], ["A"]),
    )
    root = generated("scene.main", ["mainImage"], ["A"], "")
    with pytest.raises(InputError, match="dependency cycle: core.a -> core.b -> core.c -> core.a"):
        resolve([root], cat, {})


def test_slot_requirement_without_a_choice() -> None:
    cat = catalog_of(snippet("specular", "ct", ["specular"], ["D"]))
    root = generated("scene.main", ["mainImage"], ["specular"], "")
    with pytest.raises(InputError, match="specular.ct requires slot D, but the plan has no"):
        resolve([root], cat, {"specular": "specular.ct"})


def test_real_catalog_resolves_every_requirement_of_every_snippet() -> None:
    """Each snippet's requirements resolve with the balanced choices (no dangling names)."""
    from glint.compiler.compose.planning.planner import tier_table

    catalog = load_catalog()
    choices = {slot: f"{slot}.{v}" for slot, v in tier_table()["balanced"].items()}
    choices |= {
        "camera": "camera.orbit",
        "background": "background.gradient",
        "tonemap": "tonemap.none",
        "output": "output.srgb",
    }
    scene_symbols = generated("scene.stub", [*SCENE_FUNCTIONS, "SUN_DIR", "SUN_COLOR"], [], "")
    for snip in catalog.snippets.values():
        choices_here = dict(choices)
        if snip.slot in choices_here:
            choices_here[snip.slot] = snip.id
        root = generated("scene.root", ["mainImage"], list(snip.provides), "")
        units = resolve([scene_symbols, root], catalog, choices_here)
        assert snip.id in ids(units)
