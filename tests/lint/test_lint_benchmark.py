"""The benchmark runs end to end on a few files and prints its report: the five measures, the
ratios to glslangValidator one process per file, the goals and the peak memory. Its timings
are not tested (they depend on the machine and its load)."""

from __future__ import annotations

import io
import re
import shutil
from pathlib import Path

import pytest

from glint.lint import benchmark

ROOT = Path(__file__).resolve().parents[2]
HAS_GLSLANG = shutil.which("glslangValidator") is not None


@pytest.mark.skipif(not HAS_GLSLANG, reason="glslangValidator not installed")
def test_the_report_has_every_measure_and_goal(capsys: pytest.CaptureFixture[str]) -> None:
    files = sorted((ROOT / "tests" / "corpus" / "lint_mistakes").glob("*.glsl"))[:3]
    assert benchmark.main([str(f) for f in files] + ["--repeat", "1", "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("glint lint benchmark: 3 files, ")
    assert "median of 1 run;" in out and "glint --jobs 1" in out
    rows = {}
    for key, label in benchmark.ROWS:
        line = next(line for line in out.splitlines() if line.startswith(f"({key}) {label}"))
        seconds, per_file, ratio, memory = re.findall(
            r"(\d+\.\d+)s\s+(\d+\.\d+)ms\s+(\d+\.\d+)x\s+(\d+) MiB", line
        )[0]
        rows[key] = float(ratio)
        assert float(seconds) > 0 and int(memory) > 0
    assert rows["c"] == 1.0  # the baseline
    goals = [line for line in out.splitlines() if line.startswith("goal (")]
    assert [g.split()[1] for g in goals] == ["(a)", "(a)", "(b)", "(e)"]
    assert all(g.endswith((", met", ", not met")) for g in goals)
    assert re.search(r"findings: \(a\) \d+, \(b\) \d+", out)
    assert re.search(r"peak memory \(max RSS\): this process \d+ MiB, largest child \d+ MiB", out)


@pytest.mark.skipif(not HAS_GLSLANG, reason="glslangValidator not installed")
def test_run_returns_the_medians_and_leaves_no_cache(tmp_path: Path) -> None:
    (tmp_path / "a.glsl").write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n")
    (tmp_path / "b.glsl").write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(x); }\n")
    stream = io.StringIO()
    timings = benchmark.run(benchmark.shader_files([tmp_path]), repeat=2, out=stream)
    assert set(timings) == {"a", "b", "c", "d", "e"}
    assert all(seconds > 0 for seconds in timings.values())
    # b.glsl's undeclared x is glslang's error: found with glslang on, not without
    assert re.search(r"findings: \(a\) 0, \(b\) 1", stream.getvalue())
    assert not (tmp_path / ".glint_cache").exists()  # the benchmark's cache is its own


def test_directories_are_searched_for_shaders(tmp_path: Path) -> None:
    (tmp_path / "a.glsl").write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }")
    (tmp_path / "notes.txt").write_text("not a shader")
    assert benchmark.shader_files([tmp_path]) == [tmp_path / "a.glsl"]
