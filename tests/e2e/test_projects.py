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
from runners import render_wgpu_json, render_wgpu_project, wgpu_missing
from site_browser import MAKE_TEST

from glint.compiler.errors import InputError
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


@pytest.mark.parametrize("split", [False, True])
def test_a_composed_scene_as_shadertoy_json_loads_in_wgpu_shadertoy(
    tmp_path: Path, split: bool
) -> None:
    """`glint compose --format shadertoy-json` (with --split common: a Common pass and a short
    Image pass): wgpu-shadertoy's own Shadertoy.from_json loads it and draws what glint draws,
    and glint reads it back as the same picture."""
    missing = wgpu_missing()
    if missing:
        pytest.skip(f"{missing}: {MAKE_TEST}")
    out = tmp_path / "default.json"
    split_common = ["--split", "common"] if split else []
    command = [sys.executable, "-m", "glint.compiler.cli", "compose", "--format",
               "shadertoy-json", "-o", str(out), *split_common]  # fmt: skip
    done = subprocess.run(command, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    import glint

    ours = glint.render(glint.compose(None), size=SIZE, time=1.0).pixels
    back = render_project(read_project(out), *SIZE, time=1.0).image[..., :3]
    np.testing.assert_allclose(back, ours, atol=1e-5)
    theirs = render_wgpu_json(out, *SIZE, 1.0)
    error = flip_error(np.clip(ours, 0.0, 1.0), theirs)
    print(
        f"default scene as ShaderToy JSON (split {split}): mean FLIP {error:.5f} in wgpu-shadertoy"
    )
    assert error <= FLIP_LIMIT


def test_a_scenes_pictures_travel_as_texture_inputs(tmp_path: Path) -> None:
    """The studio's tiled floor: its JSON has a texture input naming tiles.png; with the
    picture beside the JSON, glint draws the JSON as it draws the scene. A target other than
    ShaderToy's is refused."""
    import json
    import shutil

    import glint

    studio = Path(__file__).resolve().parents[2] / "snippets" / "scenes" / "studio.toml"
    out = tmp_path / "studio.json"
    cli = [sys.executable, "-m", "glint.compiler.cli", "compose", str(studio)]
    done = subprocess.run([*cli, "--format", "shadertoy-json", "-o", str(out)],
                          capture_output=True, text=True)  # fmt: skip
    assert done.returncode == 0 and "tiles.png" in done.stderr, done.stderr
    image = json.loads(out.read_text())["Shader"]["renderpass"][0]
    assert image["inputs"][0]["src"] == "tiles.png" and image["inputs"][0]["channel"] == 0
    shutil.copy(studio.parent / "pictures" / "tiles.png", tmp_path)
    back = render_project(read_project(out), *SIZE, time=1.0).image[..., :3]
    ours = glint.render(studio, size=SIZE, time=1.0).pixels
    np.testing.assert_allclose(back, ours, atol=1e-5)
    refused = subprocess.run([*cli, "--format", "shadertoy-json", "--target", "webgl2"],
                             capture_output=True, text=True)  # fmt: skip
    assert refused.returncode == 2 and "drop --target webgl2" in refused.stderr


def test_a_cubemap_shows_each_face_the_right_way_up(tmp_path: Path) -> None:
    """Six solid faces as ShaderToy names them (sky.png, sky_1.png ... sky_5.png: +x, -x, +y,
    -y, +z, -z); looking along each axis shows its face, and on +x, whose top half is red,
    looking a little up shows red and a little down the dark bottom half (GL's cube map
    convention, with each face's file top row first, as WebGL uploads it)."""
    colours = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 0), (255, 0, 255), (0, 255, 255)]
    for index, colour in enumerate(colours):
        face = np.zeros((16, 16, 3), np.uint8)
        face[:] = colour
        if index == 0:
            face[8:] = (40, 40, 40)
        Image.fromarray(face).save(tmp_path / ("sky.png" if index == 0 else f"sky_{index}.png"))
    (tmp_path / "image.glsl").write_text(
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    int i = int(fragCoord.x / iResolution.x * 8.0);\n"
        "    vec3 d = i == 0 ? vec3(1, 0, 0) : i == 1 ? vec3(-1, 0, 0) : i == 2 ? vec3(0, 1, 0)\n"
        "           : i == 3 ? vec3(0, -1, 0) : i == 4 ? vec3(0, 0, 1) : i == 5 ? vec3(0, 0, -1)\n"
        "           : i == 6 ? vec3(1, 0.5, 0) : vec3(1, -0.5, 0);\n"
        "    fragColor = vec4(texture(iChannel0, d).rgb, 1.0);\n}\n"
    )
    (tmp_path / "channels.toml").write_text(
        '[image]\n0 = { file = "sky.png", type = "cubemap", filter = "nearest" }\n'
    )
    seen = render_project(read_project(tmp_path), 80, 4).image[2, 5::10, :3]
    dark = 40 / 255
    # column 0 looks straight along +x, onto the line between the face's halves: not checked
    expected = [*[tuple(c / 255 for c in colour) for colour in colours[1:]],
                (1, 0, 0), (dark, dark, dark)]  # fmt: skip
    np.testing.assert_allclose(seen[1:], np.asarray(expected), atol=1e-3)
    (tmp_path / "sky_3.png").unlink()
    with pytest.raises(InputError, match=r"missing: sky_3.png"):
        read_project(tmp_path)


def test_a_pass_that_reads_an_unbound_channel_is_refused(tmp_path: Path) -> None:
    """The Image reads iChannel2 with nothing bound there: refused, not drawn black; a channel
    named only in a comment or as iChannelResolution is not a read."""
    import shutil

    shutil.copytree(PROJECT, tmp_path / "tabs")
    image = tmp_path / "tabs" / "image.glsl"
    code = image.read_text()
    image.write_text(code.replace("vec3 trail =", "// iChannel3 is free\n    vec3 trail ="))
    render_project(read_project(tmp_path / "tabs"), 16, 9)  # a comment is not a read
    image.write_text(code.replace("vec3 trail = texture(iChannel0, uv).rgb;",
                                  "vec3 trail = texture(iChannel2, uv).rgb;"))  # fmt: skip
    with pytest.raises(InputError, match="Image reads iChannel2, which nothing is bound to"):
        render_project(read_project(tmp_path / "tabs"), 16, 9)
