"""--budget: the most accurate measured variants within a cost per pixel."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from glint.compiler.catalog.loader import load_catalog
from glint.compiler.catalog.measurements import VariantCost, load_measurements
from glint.compiler.cli import main
from glint.compiler.compose.planning import explain as explain_module
from glint.compiler.compose.planning import planner as planner_module
from glint.compiler.compose.planning.budget import calls_per_pixel, front, within_budget
from glint.compiler.compose.planning.planner import plan
from glint.compiler.errors import InputError
from glint.compiler.scene.model import load_scene

CATALOG = load_catalog()


def cost(id_: str, ns: float, rms: float, reference: str = "r") -> VariantCost:
    return VariantCost(id_, id_.split(".")[0], reference, rms, ns, 10, False)


def test_front_keeps_only_variants_more_accurate_than_every_cheaper_one() -> None:
    options = [cost("s.a", 1, 0.5), cost("s.b", 2, 0.6), cost("s.c", 3, 0.1), cost("s.d", 3, 0.2)]
    assert [v.id for v in front(options)] == ["s.a", "s.c"]


def test_within_budget_buys_the_most_error_per_nanosecond() -> None:
    candidates = {
        "A": [cost("A.cheap", 1, 1.0), cost("A.good", 3, 0.1)],
        "B": [cost("B.cheap", 1, 1.0), cost("B.good", 11, 0.0)],
    }
    calls = {"A": 1, "B": 1}
    # 2 ns buys nothing; 4 ns buys A's upgrade (0.9 for 2 ns) before B's (1.0 for 10 ns).
    assert {s: p.variant.id for s, p in within_budget(candidates, calls, 0, 2).items()} == {
        "A": "A.cheap",
        "B": "B.cheap",
    }
    picks = within_budget(candidates, calls, 0, 4)
    assert picks["A"].variant.id == "A.good" and picks["B"].variant.id == "B.cheap"
    assert "B.good is more accurate but does not fit" in picks["B"].why
    assert within_budget(candidates, calls, 0, 100)["B"].variant.id == "B.good"
    # A slot called twice per pixel costs twice as much.
    assert within_budget(candidates, {"A": 2, "B": 1}, 0, 4)["A"].variant.id == "A.cheap"


def test_a_budget_below_the_cheapest_combination_is_an_error() -> None:
    candidates = {"A": [cost("A.cheap", 5, 1.0)]}
    with pytest.raises(InputError, match="below the cheapest combination of measured variants, 8"):
        within_budget(candidates, {"A": 1}, 3, 7)


def test_calls_per_pixel_follow_the_lights() -> None:
    scene = load_scene("snippets/scenes/lamp.toml")
    the_plan = plan(scene, CATALOG)
    calls = calls_per_pixel(scene, the_plan.uses)
    assert calls["D"] == 2 and calls["attenuation"] == 2  # two point lights
    assert calls["shadow"] == 1  # one of them casts shadows
    assert "sss" not in calls  # not in use


def write(path: Path, variants: dict[str, tuple[str, float, float]]) -> Path:
    """A measurements file: variant id -> (reference, rms, ns per call)."""
    rows = {}
    for vid, (reference, rms, ns) in variants.items():
        rows[vid] = {"slot": vid.split(".")[0], "reference": reference, "rms": rms}
        rows[vid] |= {"max_abs": rms, "spirv": 1, "gpu_ns": ns, "pareto": True}
    path.write_text(json.dumps({"machine": {"renderer": "test"}, "variants": rows}))
    return path


@pytest.fixture
def measured(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Measurements in which shadow.soft_64 is the most accurate and dearest shadow."""
    path = write(
        tmp_path / "m.json",
        {
            "shadow.hard": ("disc", 0.30, 1.0),
            "shadow.soft_12": ("disc", 0.20, 2.0),
            "shadow.soft": ("disc", 0.10, 4.0),
            "shadow.soft_centered": ("disc", 0.07, 6.0),
            "shadow.soft_64": ("disc", 0.05, 10.0),
            "ao.sdf3": ("ao", 0.02, 1.0),
            "ao.sdf5": ("ao", 0.01, 2.0),
        },
    )
    for module in (planner_module, explain_module):
        monkeypatch.setattr(module, "load_measurements", lambda: load_measurements(path))
    return path


def test_budget_replaces_the_tier_with_the_best_that_fits(measured: Path) -> None:
    scene = load_scene(None)  # one shadow-casting sun, AO on
    rich = plan(scene, CATALOG, budget=1e6)
    assert rich.choices["shadow"] == "shadow.soft_64" and rich.choices["ao"] == "ao.sdf5"
    assert rich.reasons["shadow"].startswith("--budget 1e+06 ns/pixel")
    tight = plan(scene, CATALOG, budget=2.5)
    assert tight.choices["shadow"] == "shadow.hard" and tight.choices["ao"] == "ao.sdf3"
    # Unmeasured slots keep the tier's variant.
    assert tight.choices["D"] == "D.ggx" and tight.reasons["D"] == "balanced tier"


def test_an_override_is_kept_and_counts_against_the_budget(measured: Path) -> None:
    scene = load_scene(None)
    the_plan = plan(scene, CATALOG, variants={"shadow": "soft_64"}, budget=12)
    assert the_plan.choices["shadow"] == "shadow.soft_64"
    assert the_plan.choices["ao"] == "ao.sdf5"  # 10 + 2 fits
    assert plan(scene, CATALOG, variants={"shadow": "soft_64"}, budget=11.5).choices["ao"] == (
        "ao.sdf3"
    )
    with pytest.raises(InputError, match="below the cheapest"):
        plan(scene, CATALOG, variants={"shadow": "soft_64"}, budget=10.5)


def test_missing_or_broken_measurements_are_named(tmp_path: Path) -> None:
    with pytest.raises(InputError, match=r"run `glint bench --update`"):
        load_measurements(tmp_path / "none.json")
    broken = tmp_path / "broken.json"
    broken.write_text('{"machine": {}, "variants": {"D.ggx": {"slot": "D"}}}')
    with pytest.raises(InputError, match="unreadable measurements.*regenerate"):
        load_measurements(broken)


def test_budget_on_the_command_line(capsys: pytest.CaptureFixture[str], measured: Path) -> None:
    assert main(["compose", "--budget", "2.5", "--explain"]) == 0
    out = capsys.readouterr().out
    assert "in   shadow       shadow.hard: --budget 2.5 ns/pixel" in out
    # hard (1 ns) + sdf3 (1 ns): the measured slots in use; the rest are not in the file.
    assert "estimated cost: 2 ns per lit pixel (glint bench --update on test)" in out
    assert main(["compose", "--budget", "0.5"]) == 1
    assert "below the cheapest combination" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["compose", "--budget", "-3"])
    assert "expected a positive number of ns" in capsys.readouterr().err


def test_the_catalogs_measurements_cover_every_measurable_variant() -> None:
    from glint.compiler.bench.variants import measurable_ids

    measurements = load_measurements()
    assert set(measurements.variants) == set(measurable_ids(CATALOG))
    assert measurements.machine["renderer"]
    for variant in measurements.variants.values():
        assert variant.gpu_ns >= 0 and variant.spirv > 0
        assert variant.rms is None or variant.rms >= 0
