"""Pictures on ShaderToy channels as a material's albedo (albedo_texture, triplanar), bound
with `glint render --channel N=FILE` or glint.render(channels=...): rendered with real picture
files, and refused where a picture the scene reads is not bound."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

import glint
from glint.compiler.errors import InputError, UsageError

SIZE = (64, 48)


def _scene(material: dict[str, Any]) -> dict[str, Any]:
    return {
        "camera": {"type": "lookat", "position": [0.0, 3.0, 3.0], "target": [0.0, 0.0, 0.0]},
        "objects": [{"shape": "plane", "material": "floor"}],
        "materials": {"floor": {"albedo": [1.0, 1.0, 1.0], "roughness": 0.8, **material}},
        "lights": [{"type": "directional", "direction": [0.2, 1.0, 0.3], "intensity": 2.0}],
        "effects": {"ao": False},
    }


def _picture(path: Path, colours: list[tuple[int, int, int]]) -> Path:
    """A 64×64 picture of vertical stripes of the colours."""
    data = np.zeros((64, 64, 3), np.uint8)
    for i, colour in enumerate(colours):
        data[:, i * 64 // len(colours) : (i + 1) * 64 // len(colours)] = colour
    Image.fromarray(data).save(path)
    return path


def test_a_solid_picture_is_its_linear_colour_as_albedo(tmp_path: Path) -> None:
    """A picture of one sRGB colour c lights exactly as the albedo c^2.2 times the material's
    albedo: the picture is decoded to linear and multiplies the albedo."""
    colour = (200, 90, 40)
    picture = _picture(tmp_path / "one.png", [colour])
    textured = _scene({"albedo_texture": 2, "albedo": [0.5, 1.0, 1.0]})
    linear = [0.5 * (colour[0] / 255) ** 2.2, (colour[1] / 255) ** 2.2, (colour[2] / 255) ** 2.2]
    plain = _scene({"albedo": linear})
    a = glint.render(glint.compose(textured), size=SIZE, channels={2: picture}).pixels
    b = glint.render(glint.compose(plain), size=SIZE).pixels
    np.testing.assert_allclose(a, b, atol=2e-3)


def test_a_striped_picture_shows_its_stripes_on_the_floor(tmp_path: Path) -> None:
    """Red and blue stripes: the floor shows both, in about equal shares, and nothing of a
    channel left unbound (black)."""
    picture = _picture(tmp_path / "stripes.png", [(220, 20, 20), (20, 20, 220)])
    image = glint.render(
        _scene({"albedo_texture": 0, "texture_scale": 1.0}), size=SIZE, channels={0: picture}
    ).pixels
    red = (image[..., 0] > 2 * image[..., 2]).mean()
    blue = (image[..., 2] > 2 * image[..., 0]).mean()
    assert red > 0.25 and blue > 0.25, (red, blue)


def test_an_unbound_picture_is_refused_not_drawn_black(tmp_path: Path) -> None:
    scene = _scene({"albedo_texture": 1})
    with pytest.raises(UsageError, match="nothing is bound to iChannel1"):
        glint.render(glint.compose(scene), size=SIZE)
    with pytest.raises(InputError, match="cannot read the picture"):
        glint.render(glint.compose(scene), size=SIZE, channels={1: tmp_path / "none.png"})


def _floor_scene(folder: Path, extra: str = "") -> Path:
    """A scene file: a floor whose albedo is the picture on channel 0, lit from above."""
    scene = folder / "floor.toml"
    scene.write_text(
        '[camera]\ntype = "lookat"\nposition = [0, 3, 3]\n'
        '[[objects]]\nshape = "plane"\nmaterial = "floor"\n'
        "[materials.floor]\nalbedo = [1, 1, 1]\nalbedo_texture = 0\n"
        '[[lights]]\ntype = "directional"\ndirection = [0, 1, 0]\n' + extra
    )
    return scene


def test_render_binds_a_picture_from_the_command_line(tmp_path: Path) -> None:
    """The command a user types: the scene file, --channel 0=FILE; without it, exit 2 and a
    message that says what to give."""
    picture = _picture(tmp_path / "stone.png", [(120, 110, 100), (90, 80, 70)])
    scene = _floor_scene(tmp_path)
    out = tmp_path / "floor.png"
    glint_cli = [sys.executable, "-m", "glint.compiler.cli"]
    bound = subprocess.run(
        [*glint_cli, "render", str(scene), "--channel", f"0={picture}", "-o", str(out),
         "--size", "32x24"], capture_output=True, text=True,
    )  # fmt: skip
    assert bound.returncode == 0, bound.stderr
    assert np.asarray(Image.open(out)).mean() > 20
    unbound = subprocess.run(
        [*glint_cli, "render", str(scene), "-o", str(tmp_path / "x.png")],
        capture_output=True, text=True,
    )  # fmt: skip
    assert unbound.returncode == 2
    assert "--channel 0=FILE" in unbound.stderr and "Traceback" not in unbound.stderr


def test_a_geometry_file_may_read_a_bound_channel_only(tmp_path: Path) -> None:
    (tmp_path / "field.glsl").write_text(
        "float sceneDistance(vec3 p) {\n"
        "    return length(p) - 1.0 - 0.01 * texture(iChannel0, p.xz).r;\n}\n"
    )
    scene = {
        "objects": [],
        "geometry": {"file": "field.glsl", "material": "rock", "lipschitz": 1.5},
        "materials": {"rock": {"albedo": [0.5, 0.5, 0.5]}},
    }
    from glint.compiler.scene.model import scene_from_dict

    where = str(tmp_path / "scene.toml")
    with pytest.raises(InputError, match="reads iChannel0, which no material"):
        glint.compose(scene_from_dict(scene, where))
    scene["materials"]["rock"]["albedo_texture"] = 0
    assert "texture(iChannel0" in glint.compose(scene_from_dict(scene, where)).text


def test_a_scene_names_its_pictures_and_render_binds_them(tmp_path: Path) -> None:
    """[channels] 0 = "stone.png" beside the scene: `glint render scene.toml` binds it (the
    picture equals what --channel gives), and the composed shader names the file to bind."""
    _picture(tmp_path / "stone.png", [(120, 110, 100), (60, 50, 40)])
    _picture(tmp_path / "other.png", [(20, 200, 20)])
    scene = _floor_scene(tmp_path, '[channels]\n0 = "stone.png"\n')
    by_scene = glint.render(scene, size=(32, 24)).pixels
    by_argument = glint.render(scene, size=(32, 24), channels={0: tmp_path / "stone.png"}).pixels
    replaced = glint.render(scene, size=(32, 24), channels={0: tmp_path / "other.png"}).pixels
    np.testing.assert_array_equal(by_scene, by_argument)
    change = replaced - by_scene  # the floor turns green where the other picture lies on it
    assert (change[..., 1] - change[..., 0]).mean() > 0.05
    assert "iChannel0: bind a picture to it (stone.png: the albedo of floor)" in (
        glint.compose(scene).text
    )
