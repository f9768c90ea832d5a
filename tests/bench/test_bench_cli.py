"""`glint bench` end to end, small: what it prints and writes, and that the static part of its
output does not change from one run to the next."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from PIL import Image

from glint.compiler.bench import report
from glint.compiler.bench.report import BenchResult, static_part
from glint.compiler.bench.scenes import TierMeasure
from glint.compiler.bench.variants import VariantMeasure
from glint.compiler.catalog.measurements import load_measurements
from glint.compiler.cli import main

pytestmark = pytest.mark.render

SMALL = ["--slots", "F", "--scenes", "default", "--size", "48x27", "--repeats", "2"]


def run(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    code = main(["bench", *args])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_bench_prints_the_trade_and_writes_json_markdown_and_charts(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    code, out, _ = run(capsys, *SMALL, "--out", str(tmp_path / "a"))
    assert code == 0
    assert "| default | balanced |" in out and "| default | template |" in out
    assert "goal balanced vs template:" in out and "goal reference vs template:" in out
    assert "| FLIP p99 | outliers |" in out and "outliers" in out.split("goal fast vs template:")[1]
    data = json.loads((tmp_path / "a" / "bench.json").read_text())
    assert {v["id"] for v in data["variants"]} == {
        "F.dielectric", "F.schlick", "F.schlick_f90", "F.schlick_fast"
    }  # fmt: skip
    assert {t["tier"] for t in data["tiers"]} == {"fast", "balanced", "reference", "template"}
    for tier in data["tiers"]:
        assert 0.0 <= tier["flip_p99"] <= 1.0 and 0.0 <= tier["outliers"] <= 1.0
    assert data["machine"]["renderer"]
    markdown = (tmp_path / "a" / "bench.md").read_text()
    assert "### F" in markdown and "| F.dielectric | F_dielectric |" in markdown
    assert "| default | reference | " in markdown and "| 0.0000 | 0.0000 | 0.000% |" in markdown
    for chart in ("variants.png", "tiers.png"):
        with Image.open(tmp_path / "a" / chart) as image:
            assert image.size[0] > 200 and image.size[1] > 200

    _, _, _ = run(capsys, *SMALL, "--out", str(tmp_path / "b"))
    first = json.loads((tmp_path / "a" / "bench.json").read_text())
    second = json.loads((tmp_path / "b" / "bench.json").read_text())
    assert _static(first) == _static(second)


def _static(data: dict) -> dict:
    variants = [VariantMeasure(**v) for v in data["variants"]]
    tiers = [TierMeasure(**t) for t in data["tiers"]]
    return static_part(BenchResult(machine={}, variants=variants, tiers=tiers))


def test_update_writes_the_measurements_the_planner_reads(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    target = tmp_path / "measurements.json"
    monkeypatch.setattr(report, "measurements_path", lambda: target)
    code, _, err = run(capsys, "--slots", "F", "--update", "--out", str(tmp_path))
    assert code == 2 and "--update writes every variant's measurements" in err
    assert not target.exists()
    # The whole variant part is too slow for a test; --update's writer on a small result:
    variant = VariantMeasure("F.schlick", "F", "F_dielectric", "value", 0.1, 0.01, 0.2, None, 9,
                             120, 3.5, True)  # fmt: skip
    report.write_measurements(
        BenchResult(machine={"renderer": "x", "cpu": True}, variants=[variant])
    )
    loaded = load_measurements(target)
    assert loaded.machine == {"renderer": "x", "cpu": True}
    assert loaded.variants["F.schlick"].gpu_ns == 3.5 and loaded.variants["F.schlick"].rms == 0.01
    assert "do not edit by hand" in target.read_text()


def test_bad_bench_arguments_are_named(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, _, err = run(capsys, "--slots", "nope", "--no-scenes", "--out", str(tmp_path))
    assert code == 2 and "--slots: unknown slot 'nope'" in err
    code, _, err = run(capsys, "--repeats", "1", "--out", str(tmp_path))
    assert code == 2 and "--repeats must be at least 2" in err


def test_the_tiers_chart_labels_every_point(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every tier's point carries its name (and, on the every-scene panel, its scene's)."""
    import matplotlib.axes

    labels: list[str] = []
    annotate = matplotlib.axes.Axes.annotate

    def spy(self: matplotlib.axes.Axes, text: str, *args: object, **kwargs: object) -> object:
        labels.append(text)
        return annotate(self, text, *args, **kwargs)

    monkeypatch.setattr(matplotlib.axes.Axes, "annotate", spy)
    tiers = [
        TierMeasure("default", "fast", 4.0, 0.01, 0.8, 1, 0.6, None, 0.05, 0.0),
        TierMeasure("default", "reference", 5.0, 0.0, 1.0, 1, 0.75, None, 0.0, 0.0),
        TierMeasure("default", "template", 6.7, 0.08, 1.3, 1, 1.0, None, 0.3, 0.01),
        TierMeasure("pool", "fast", 3.0, 0.05, 0.7, 1, None, None, 0.2, 0.001),
        TierMeasure("pool", "reference", 4.3, 0.0, 1.0, 1, None, None, 0.0, 0.0),
    ]
    result = BenchResult(machine={"cpu": True}, tiers=tiers)
    report.write_charts(result, tmp_path)
    assert {"fast 0.60×", "reference 0.75×", "template 1.00×"} <= set(labels)
    assert {"default fast", "pool fast", "reference (every scene)"} <= set(labels)
    with Image.open(tmp_path / "tiers.png") as image:
        assert image.size[0] > 800
