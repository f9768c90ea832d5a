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


# The rule that must find each planted mistake that compiles (`valid, findings`).
PLANTED = {
    "acos_unclamped.glsl": "N003",
    "fresnel_with_ndotl.glsl": "L001",
    "missing_gamma.glsl": "L005",
    "reversed_smoothstep.glsl": "N009",
    "unclamped_dot_in_pow.glsl": "N001",
    "uninitialized_variable.glsl": "C103",
}


def test_every_planted_mistake_names_its_rule() -> None:
    valid = {p.name for p in MISTAKES if _expectation(p) == "valid, findings"}
    assert valid == set(PLANTED)


@pytest.mark.parametrize("name", sorted(PLANTED))
def test_planted_mistake_is_found_by_the_default_rules(name: str) -> None:
    """The default rules find each planted mistake on its own (`glint lint` without --select):
    a rule still opt-in (too few judged findings on the corpus to be on by default) is an
    expected failure until it is on, and is held to finding it when selected."""
    from glint.lint.options import Options
    from glint.lint.rules import all_rules
    from glint.lint.runner import lint_bytes

    code = PLANTED[name]
    data = (ROOT / "tests" / "corpus" / "lint_mistakes" / name).read_bytes()
    selected = {
        f.code for f in lint_bytes(data, name, Options(select=[code], glslang=False)).findings
    }
    assert code in selected, f"{name}: {code} does not find the planted mistake"
    if not all_rules()[code].default:
        pytest.xfail(f"{code} is opt-in: too few judged findings on the corpus to run by default")
    found = {f.code for f in lint_bytes(data, name, Options(glslang=False)).findings}
    assert code in found, f"{name}: the default rules miss it ({sorted(found)})"
