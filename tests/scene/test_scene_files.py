"""The files a scene names (its own TOML, a [geometry] GLSL file, a mesh file and what an OBJ
refers to) are read only when they are regular files of a bounded size, without blocking: a
device, a FIFO, a folder, a file too large or not UTF-8 is one message, exit status 1."""

from __future__ import annotations

import os
import subprocess
import sys
import threading
from pathlib import Path
from typing import Any

import pytest

from glint.compiler.errors import InputError
from glint.compiler.files import MiB, read_user_file
from glint.compiler.scene.model import load_scene


def _geometry_scene(tmp_path: Path, file: str) -> Path:
    scene = tmp_path / "scene.toml"
    scene.write_text(
        f'[geometry]\nfile = "{file}"\nmaterial = "m"\n[materials.m]\nalbedo = [1.0, 1.0, 1.0]\n'
    )
    return scene


def test_a_device_as_geometry_file_is_refused_before_reading(tmp_path: Path) -> None:
    with pytest.raises(InputError) as caught:
        load_scene(_geometry_scene(tmp_path, "/dev/zero"))
    message = caught.value.message
    assert "geometry.file: /dev/zero: not a regular file (a device, a FIFO or a socket)" in message


def _in_time(function: Any, seconds: float = 10.0) -> Any:
    """function() in a thread; fails the test (instead of hanging it) past `seconds`."""
    outcome: dict[str, Any] = {}

    def run() -> None:
        try:
            outcome["value"] = function()
        except BaseException as exc:  # noqa: BLE001 - handed to the test
            outcome["error"] = exc

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), f"still running after {seconds} s: it blocks"
    if "error" in outcome:
        raise outcome["error"]
    return outcome.get("value")


def test_a_fifo_as_scene_geometry_or_mesh_file_is_refused_without_blocking(
    tmp_path: Path,
) -> None:
    fifo = tmp_path / "pipe.glsl"
    os.mkfifo(fifo)
    with pytest.raises(InputError, match="pipe.glsl: not a regular file"):
        _in_time(lambda: load_scene(_geometry_scene(tmp_path, "pipe.glsl")))
    scene_fifo = tmp_path / "scene_pipe.toml"
    os.mkfifo(scene_fifo)
    with pytest.raises(InputError, match="scene_pipe.toml: not a regular file"):
        _in_time(lambda: load_scene(scene_fifo))
    mesh_fifo = tmp_path / "pipe.obj"
    os.mkfifo(mesh_fifo)
    scene = tmp_path / "mesh.toml"
    scene.write_text(
        '[[objects]]\nshape = "mesh"\nfile = "pipe.obj"\nmaterial = "m"\n'
        "[materials.m]\nalbedo = [1.0, 1.0, 1.0]\n"
    )
    with pytest.raises(InputError, match=r"objects\[0\].file: .*pipe.obj: not a regular file"):
        _in_time(lambda: load_scene(scene))


def test_an_obj_whose_material_library_is_a_fifo_loads_without_it(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "pipe.mtl")
    (tmp_path / "tri.obj").write_text("mtllib pipe.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    scene = tmp_path / "mesh.toml"
    scene.write_text(
        '[[objects]]\nshape = "mesh"\nfile = "tri.obj"\nmaterial = "m"\n'
        "[materials.m]\nalbedo = [1.0, 1.0, 1.0]\n"
    )
    loaded = _in_time(lambda: load_scene(scene))
    assert loaded.objects[0].arrays.indices.shape == (1, 3)


def test_a_file_over_the_limit_is_refused_with_the_limit(tmp_path: Path) -> None:
    big = tmp_path / "big.toml"
    big.write_bytes(b"# " + b"x" * (4 * MiB) + b"\n")
    with pytest.raises(InputError) as caught:
        load_scene(big)
    assert "big.toml: 4.0 MiB, larger than the 4 MiB glint reads for a scene TOML file" in (
        caught.value.message
    )
    with pytest.raises(InputError, match="larger than the 0.5 MiB"):
        read_user_file(big, MiB // 2)


def test_a_folder_a_missing_file_and_bad_utf8_are_one_message(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="is a folder, expected a scene TOML file"):
        load_scene(tmp_path)
    with pytest.raises(InputError, match="no such scene file"):
        load_scene(tmp_path / "absent.toml")
    (tmp_path / "latin1.toml").write_bytes(b'name = "caf\xe9"\n')
    with pytest.raises(InputError, match="not UTF-8 text"):
        load_scene(tmp_path / "latin1.toml")


def test_cli_dev_zero_geometry_exits_1_at_once(tmp_path: Path) -> None:
    scene = _geometry_scene(tmp_path, "/dev/zero")
    done = subprocess.run(
        [sys.executable, "-m", "glint.compiler.cli", "compose", str(scene)],
        capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert done.returncode == 1, done.stderr
    assert "not a regular file" in done.stderr and "Traceback" not in done.stderr
    assert done.stdout == ""
