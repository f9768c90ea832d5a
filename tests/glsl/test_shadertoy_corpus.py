"""The front end on real ShaderToy shaders: every Image-tab shader that glslangValidator accepts
must preprocess, parse and yield its symbols; no shader of the corpus may crash it.

The corpus lives beside the checkout, in ../shared/corpus (see its README); its shaders belong to
their authors and are not copied here. The tests skip when it is absent.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from glint.compiler.errors import InputError
from glint.compiler.glsl import parse, preprocess, symbols_of

CORPUS = Path(__file__).resolve().parents[3] / "shared" / "corpus"
SHADERS = CORPUS / "shadertoy"
LISTING = CORPUS / "glslang-valid.txt"
ABSENT = f"the ShaderToy corpus is not at {CORPUS} (../shared/corpus beside the checkout)"


def _params(names: list[str]) -> list[object]:
    if not names:
        return [pytest.param(None, marks=pytest.mark.skip(reason=ABSENT), id="corpus-absent")]
    return [pytest.param(SHADERS / name, id=name.removesuffix(".glsl")) for name in names]


def _valid() -> list[str]:
    return LISTING.read_text(encoding="utf-8").split() if LISTING.is_file() else []


def _invalid() -> list[str]:
    if not SHADERS.is_dir():
        return []
    valid = set(_valid())
    return sorted(p.name for p in SHADERS.glob("*.glsl") if p.name not in valid)


def front_end(path: Path) -> None:
    """Preprocess, parse and collect symbols, as `glint lint` does."""
    text = path.read_text(encoding="utf-8-sig")
    pre = preprocess(text, path.name)
    symbols_of(parse(pre.text, path.name), pre)


@pytest.mark.skipif(not LISTING.is_file(), reason=ABSENT)
def test_the_listing_names_existing_shaders() -> None:
    names = _valid()
    assert len(names) >= 400
    assert [n for n in names if not (SHADERS / n).is_file()] == []


@pytest.mark.parametrize("path", _params(_valid()))
def test_shader_glslang_accepts_parses(path: Path) -> None:
    try:
        front_end(path)
    except InputError as exc:
        pytest.fail(f"glslang accepts this shader, glint does not: {exc.message}")


@pytest.mark.parametrize("path", _params(_invalid()))
def test_shader_glslang_rejects_does_not_crash(path: Path) -> None:
    """These need a Common tab, buffers or textures that the corpus lacks; they may fail, but
    only with a positioned error."""
    try:
        front_end(path)
    except InputError as exc:
        assert exc.message.startswith(f"{path.name}:")
