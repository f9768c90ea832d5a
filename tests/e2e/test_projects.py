"""A ShaderToy project drawn pass by pass, frame after frame: glint's render of a Buffer A
feedback loop over a picture matches wgpu-shadertoy's after 60 frames, the buffer really feeds
the next frame, and `glint render PROJECT --frames N` writes that picture."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from runners import render_wgpu_project, wgpu_missing
from site_browser import MAKE_TEST

from glint.compiler.render.images import flip_error
from glint.compiler.render.runner import render_project
from glint.compiler.target.shadertoy_project import read_project

pytestmark = pytest.mark.render

PROJECT = Path(__file__).resolve().parents[1] / "corpus" / "projects" / "feedback"
SIZE = (240, 135)
FRAMES = 60
FLIP_LIMIT = 0.01


def _glint(path: Path, frames: int) -> np.ndarray:
    return render_project(read_project(path), *SIZE, time=0.0, frames=frames).image[..., :3]


def test_glint_draws_what_wgpu_shadertoy_draws() -> None:
    missing = wgpu_missing()
    if missing:
        pytest.skip(f"{missing}: {MAKE_TEST}")
    ours = _glint(PROJECT, FRAMES)
    theirs = render_wgpu_project(read_project(PROJECT), *SIZE, 0.0, FRAMES)
    error = flip_error(ours, theirs)
    print(f"feedback project, {FRAMES} frames: mean FLIP {error:.5f} against wgpu-shadertoy")
    assert error <= FLIP_LIMIT


def test_the_buffer_feeds_the_next_frame() -> None:
    """The dot circles the centre at 3 rad/s: after one frame only the dot is lit; after 60 its
    trail covers an arc, brightest at its head, and the JSON export draws the same."""
    one, many = _glint(PROJECT, 1), _glint(PROJECT, FRAMES)
    again = _glint(PROJECT, 1)  # the same frame twice is the same picture
    assert np.abs(again - one).max() == 0.0
    lit_one = (one.sum(axis=2) > 2.0).sum()
    lit_many = (many.sum(axis=2) > 2.0).sum()
    assert lit_many > 5 * lit_one > 0
    np.testing.assert_allclose(_glint(PROJECT / "shader.json", FRAMES), many, atol=1e-6)


def test_render_runs_a_project_from_the_command_line(tmp_path: Path) -> None:
    out = tmp_path / "trail.png"
    command = [
        sys.executable, "-m", "glint.compiler.cli", "render", str(PROJECT / "shader.json"),
        "--frames", str(FRAMES), "--size", f"{SIZE[0]}x{SIZE[1]}", "-o", str(out),
    ]  # fmt: skip
    done = subprocess.run(command, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert f"{FRAMES} frames" in done.stdout
    written = np.asarray(Image.open(out), np.float32) / 255.0
    expected = np.clip(_glint(PROJECT, FRAMES), 0.0, 1.0)
    assert flip_error(expected, written) < 0.01
    broken = tmp_path / "broken.json"
    broken.write_text('{"Shader": {"renderpass": [{"type": "image"}]}}')
    done = subprocess.run([*command[:4], str(broken), "-o", str(tmp_path / "x.png")],
                          capture_output=True, text=True)  # fmt: skip
    assert done.returncode == 1 and "code: missing" in done.stderr
    assert "Traceback" not in done.stderr and not (tmp_path / "x.png").exists()
