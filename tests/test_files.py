"""Reading the files a user names and writing outputs whole (compiler/files.py)."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from glint.compiler.errors import InputError
from glint.compiler.files import read_text_file, write_atomic


def test_an_output_gets_the_mode_a_new_file_gets(tmp_path: Path) -> None:
    old = os.umask(0o022)
    try:
        write_atomic(tmp_path / "shader.glsl", b"void mainImage() {}\n")
    finally:
        os.umask(old)
    mode = stat.S_IMODE((tmp_path / "shader.glsl").stat().st_mode)
    assert mode == 0o644  # not mkstemp's 0600: others may read what glint wrote
    assert [p.name for p in tmp_path.iterdir()] == ["shader.glsl"]  # no temporary left


@pytest.mark.parametrize(
    ("make", "says"),
    [
        (lambda p: p, "no such file"),
        (lambda p: (p.mkdir(), p)[1], "is a folder"),
        (lambda p: (p.write_bytes(b"\xff\xfe\x00bad"), p)[1], "not UTF-8 text"),
    ],
)
def test_reading_a_bad_file_says_why(tmp_path: Path, make, says: str) -> None:  # type: ignore[no-untyped-def]
    path = make(tmp_path / "x.glsl")
    with pytest.raises(InputError, match=says):
        read_text_file(path)


def test_a_file_replaced_keeps_its_mode(tmp_path: Path) -> None:
    target = tmp_path / "shader.glsl"
    target.write_text("old\n")
    target.chmod(0o640)
    write_atomic(target, b"new\n")
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    assert target.read_text() == "new\n"
