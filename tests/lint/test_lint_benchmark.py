"""The benchmark runs end to end on a couple of files (its timings are not tested)."""

from __future__ import annotations

from pathlib import Path

import pytest

from glint.lint import benchmark

ROOT = Path(__file__).resolve().parents[2]


def test_benchmark_prints_the_table_and_the_ratio(capsys: pytest.CaptureFixture[str]) -> None:
    files = sorted((ROOT / "tests" / "corpus" / "valid").glob("*.glsl"))[:2]
    assert benchmark.main([str(f) for f in files] + ["--repeat", "1"]) == 0
    out = capsys.readouterr().out
    assert "2 files" in out
    assert "glint lint, all rules (glslang off)" in out
    assert "ratio glint/glslang: " in out


def test_directories_are_searched_for_shaders(tmp_path: Path) -> None:
    (tmp_path / "a.glsl").write_text("void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }")
    (tmp_path / "notes.txt").write_text("not a shader")
    assert benchmark.shader_files([tmp_path]) == [tmp_path / "a.glsl"]
