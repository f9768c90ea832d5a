"""The lint corpus: real-world-style ShaderToy shaders that are correct (glslang accepts
every one; they measure how rare findings on good code are), and typical mistakes that
glslang rejects or that are legal but wrong (each file's first line says which)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from glint.compiler.target.glslang import validate

ROOT = Path(__file__).resolve().parents[2]
CORPUS = sorted((ROOT / "tests" / "corpus" / "lint").glob("*.glsl"))
MISTAKES = sorted((ROOT / "tests" / "corpus" / "lint_mistakes").glob("*.glsl"))

needs_glslang = pytest.mark.skipif(
    shutil.which("glslangValidator") is None, reason="glslangValidator not installed"
)


def _expectation(path: Path) -> str:
    """`invalid` (glslang rejects it) or `valid, findings` (legal, but a lint should object)."""
    first = path.read_text(encoding="utf-8").split("\n", 1)[0]
    assert first.startswith("// expect: "), f"{path.name}: first line must say what to expect"
    expected = first.removeprefix("// expect: ").strip()
    assert expected in ("invalid", "valid, findings"), expected
    return expected


def test_corpus_size_and_lengths() -> None:
    assert 12 <= len(CORPUS) <= 20
    for path in CORPUS:
        lines = path.read_text(encoding="utf-8").count("\n")
        assert 100 <= lines <= 400, (path.name, lines)


def test_mistakes_cover_both_kinds() -> None:
    kinds = [_expectation(p) for p in MISTAKES]
    assert "invalid" in kinds and "valid, findings" in kinds


@needs_glslang
@pytest.mark.parametrize("path", CORPUS, ids=lambda p: p.name)
def test_corpus_shader_validates(path: Path) -> None:
    diagnostics = validate(path.read_text(encoding="utf-8"), path.name)
    assert diagnostics == [], "\n".join(map(str, diagnostics))


@needs_glslang
@pytest.mark.parametrize("path", MISTAKES, ids=lambda p: p.name)
def test_mistake_validates_as_intended(path: Path) -> None:
    errors = [
        d for d in validate(path.read_text(encoding="utf-8"), path.name) if d.severity == "error"
    ]
    if _expectation(path) == "invalid":
        assert errors, f"{path.name} should not compile"
    else:
        assert errors == [], "\n".join(map(str, errors))
