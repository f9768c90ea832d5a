"""Agreement with glslang: our front end and glslangValidator accept and reject the same corpus.

Each corpus file is an Image-tab shader; it is wrapped in the exact ShaderToy prelude, so the
prelude itself (version, precision, uniforms, `out`, `main`) goes through our parser too.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from glint.compiler.errors import InputError
from glint.compiler.glsl.parser import parse_source
from glint.compiler.target.shadertoy import wrap

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
VALID = sorted((CORPUS / "valid").glob("*.glsl"))
INVALID = sorted((CORPUS / "invalid").glob("*.glsl"))
GLSLANG = shutil.which("glslangValidator")

needs_glslang = pytest.mark.skipif(GLSLANG is None, reason="glslangValidator is not installed")


def glslang_accepts(source: str, tmp_path: Path) -> tuple[bool, str]:
    shader = tmp_path / "shader.frag"
    shader.write_text(source, encoding="utf-8")
    assert GLSLANG is not None
    run = subprocess.run([GLSLANG, str(shader)], capture_output=True, text=True, timeout=60)
    return run.returncode == 0, run.stdout + run.stderr


def ours_accepts(source: str, name: str) -> tuple[bool, str]:
    try:
        parse_source(source, name)
    except InputError as exc:
        return False, exc.message
    return True, ""


def test_corpus_is_big_enough() -> None:
    assert len(VALID) >= 25
    assert len(INVALID) >= 10


@pytest.mark.parametrize("path", VALID, ids=lambda p: p.stem)
def test_valid_shader_parses_bare(path: Path) -> None:
    ok, why = ours_accepts(path.read_text(encoding="utf-8"), path.name)
    assert ok, why


@needs_glslang
@pytest.mark.parametrize("path", VALID, ids=lambda p: p.stem)
def test_valid_shader_accepted_by_both(path: Path, tmp_path: Path) -> None:
    source = wrap(path.read_text(encoding="utf-8"))
    ok, log = glslang_accepts(source, tmp_path)
    assert ok, f"glslang rejects a corpus shader that should be valid:\n{log}"
    ok, why = ours_accepts(source, path.name)
    assert ok, why


@needs_glslang
@pytest.mark.parametrize("path", INVALID, ids=lambda p: p.stem)
def test_invalid_shader_rejected_by_both(path: Path, tmp_path: Path) -> None:
    source = wrap(path.read_text(encoding="utf-8"))
    ok, _ = glslang_accepts(source, tmp_path)
    assert not ok, "glslang accepts a corpus shader that should be invalid"
    ok, _ = ours_accepts(source, path.name)
    assert not ok, "our front end accepts a shader glslang rejects"


@pytest.mark.parametrize("path", INVALID, ids=lambda p: p.stem)
def test_invalid_shader_error_is_positioned(path: Path) -> None:
    with pytest.raises(InputError) as info:
        parse_source(path.read_text(encoding="utf-8"), path.name)
    assert info.value.message.startswith(f"{path.name}:")
