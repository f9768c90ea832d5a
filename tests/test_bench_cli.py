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
    data = json.loads((tmp_path / "a" / "bench.json").read_text())
    assert {v["id"] for v in data["variants"]} == {
        "F.dielectric", "F.schlick", "F.schlick_f90", "F.schlick_fast"
    }  # fmt: skip
    assert {t["tier"] for t in data["tiers"]} == {"fast", "balanced", "reference", "template"}
    assert data["machine"]["renderer"]
    markdown = (tmp_path / "a" / "bench.md").read_text()
    assert "### F" in markdown and "| F.dielectric | F_dielectric |" in markdown
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
