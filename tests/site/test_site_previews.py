"""The docs site shows each slot's variants in a scene made to show that slot (issue 27): their
pictures must differ where the variants do, by the measure of variant_contrast.py, rendered as
the site renders them."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import glint
from glint.compiler.render.images import png_pixels
from glint.compiler.site.pictures import PREVIEWS, scene_using, variant_pictures
from glint.compiler.site.slot_comparison import _how_much_they_differ
from glint.compiler.site.variant_contrast import GOAL, differing_share, slot_contrast

pytestmark = pytest.mark.render

# F is not held to the goal: three of its four variants are one function wherever f0 >= 0.02
# (every material; F.schlick_f90 departs only below), so their pictures are the same by
# design and the page says so (test below).
HELD = ("D", "V", "specular", "diffuse", "shadow", "ao", "specocc")


def _pictures(slot: str, cache: Path) -> dict[str, bytes]:
    ids = sorted(i for i, s in glint.catalog().items() if s.slot == slot)
    built = variant_pictures(ids, cache)
    return {i: built.files[p.path] for i, p in built.by_id.items() if p.path is not None}


@pytest.mark.parametrize("slot", HELD)
def test_a_slots_variant_pictures_differ_where_the_variants_do(slot: str, tmp_path: Path) -> None:
    scene = scene_using(slot)
    assert scene is not None and scene[1] == f"snippets/previews/{PREVIEWS[slot]}.toml"
    pictures = _pictures(slot, tmp_path)
    assert len(pictures) == sum(1 for s in glint.catalog().values() if s.slot == slot)
    share = slot_contrast(pictures.values())
    assert share is not None and share >= GOAL, f"{slot}: median pairwise {share:.1%}"


def test_the_page_names_the_variants_whose_pictures_are_the_same(tmp_path: Path) -> None:
    pictures = _pictures("F", tmp_path)
    schlick = [i for i in pictures if i.startswith("F.schlick")]
    assert len(schlick) == 3
    assert all(differing_share(pictures[schlick[0]], pictures[i]) == 0.0 for i in schlick)
    assert differing_share(pictures["F.dielectric"], pictures["F.schlick"]) > 0.0
    said = _how_much_they_differ(pictures)
    assert "`F.schlick`, `F.schlick_f90` and `F.schlick_fast` give the same picture" in said
    assert "F.dielectric" not in said.split("give the same")[0]
    assert f"a median {slot_contrast(pictures.values()):.1%} of the pixels differ" in said


def test_a_slots_curves_show_every_variant_and_the_reference(tmp_path: Path) -> None:
    """The D chart: every variant along the half-vector angle, the reference tier's variant on
    its float64 reference, and the difference the docs talk about (GGX's long tail) in the
    data; on the slot page under its own heading."""
    from glint.compiler.catalog.tiers import tier_table
    from glint.compiler.site.measured import Bench
    from glint.compiler.site.slot_comparison import reference_variant, slot_comparisons
    from glint.compiler.site.slot_curves import ANGLES, slot_curves

    ids = sorted(i for i, s in glint.catalog().items() if s.slot == "D")
    reference = reference_variant("D", tier_table())
    curves = slot_curves("D", ids, reference)
    assert curves is not None and curves.reference_variant == reference == "D.ggx"
    for _, values, exact in curves.panels:
        assert set(values) == set(ids)
        assert exact is not None
        assert np.allclose(values["D.ggx"], exact, rtol=1e-3, atol=1e-6)
        tail = ANGLES > 50
        assert values["D.ggx"][tail].min() > 10 * values["D.beckmann"][tail].max()
    built = variant_pictures(["D.ggx", "D.beckmann"], tmp_path)
    files = {p.path: built.files[p.path] for p in built.by_id.values() if p.path}
    section = slot_comparisons({"D": ids}, built.by_id, files, Bench(), tmp_path).sections["D"]
    assert (
        "## Curves\n\n![every D variant along the sweep](../../img/charts/D-curves.png)" in section
    )


def test_every_shape_intersection_light_and_pattern_card_has_a_picture(tmp_path: Path) -> None:
    """The catalog's library snippets that a scene takes by its content (a shape, an analytic
    intersection, a light, the checker) each get a small scene of their own that uses them;
    the core helpers, which every scene uses alike, stay without."""
    from glint.compiler.catalog.slots import SLOTS

    library = sorted(i for i, s in glint.catalog().items()
                     if SLOTS.get(s.slot) is None or SLOTS[s.slot].many)  # fmt: skip
    built = variant_pictures(library, tmp_path)
    without = sorted(i for i, p in built.by_id.items() if p.path is None)
    assert without == [i for i in library if i.startswith("core.")]
    for snippet_id, picture in built.by_id.items():
        if picture.path is None:
            continue
        assert picture.own_scene and snippet_id in picture.shader.split("Snippets, in order:")[1]
        pixels = np.asarray(png_pixels(built.files[picture.path]))
        assert pixels.std() > 0.05, snippet_id  # a scene, not a flat colour
    # a shape's picture shows that shape: the torus and the sphere differ
    torus, sphere = (built.files[built.by_id[i].path] for i in ("sdf.torus", "sdf.sphere"))
    assert differing_share(torus, sphere) > 0.05
