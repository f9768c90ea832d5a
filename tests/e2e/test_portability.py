"""Every example scene at every tier draws the same picture in three ShaderToy runners: glint's
own (moderngl on Mesa's llvmpipe, `glint render`), WebGL2 in Debian's Chromium (SwiftShader) and
wgpu-shadertoy (GLSL through naga on Mesa's lavapipe Vulkan driver). Each runner's image is
compared with glint's by mean FLIP, which must stay at or under 0.01.

All the shaders are drawn in one browser page and in one wgpu-shadertoy process (tests/runners.py);
the moderngl images are drawn once each and shared by both comparisons.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import pytest
from PIL import Image
from runners import Pictures, RunnerFailure, render_webgl2, render_wgpu, wgpu_missing
from site_browser import MAKE_TEST

from glint.compiler.bench.scenes import example_scenes
from glint.compiler.compose.pipeline import compose_scene
from glint.compiler.render.images import flip_error
from glint.compiler.render.runner import render_full
from glint.compiler.scene.model import default_scene_path, load_scene

if TYPE_CHECKING:
    from playwright.sync_api import Browser

pytestmark = pytest.mark.render

TIERS = ("fast", "balanced", "reference")
SCENES = example_scenes()  # the raymarched ones: ShaderToy shaders, what these runners run
CASES = [(scene, tier) for scene in SCENES for tier in TIERS]
# Mesh examples are rasterized programs (a vertex and a fragment shader per material), not a
# ShaderToy Image tab: none of the three runners takes them. Listed so the report shows it.
MESH_SCENES = sorted(
    path.stem
    for path in default_scene_path().parent.glob("*.toml")
    if path.stem not in SCENES and load_scene(path).is_mesh
)
MESH_SKIP = "a mesh scene: rasterized programs, not a ShaderToy shader these runners run"
WIDTH, HEIGHT = 240, 135
TIME = 1.0
FLIP_LIMIT = 0.01
RUNNER_NAMES = {
    "webgl2": "WebGL2 in Chromium (SwiftShader)",
    "wgpu": "wgpu-shadertoy (naga, lavapipe)",
}

Images = dict[tuple[str, str], np.ndarray | RunnerFailure]


@pytest.fixture(scope="module")
def shaders() -> dict[tuple[str, str], tuple[str, str]]:
    """Each scene and tier's shader: the ShaderToy Image tab and the complete webgl2 shader."""
    folder = default_scene_path().parent
    composed = {}
    for scene_name, tier in CASES:
        scene = load_scene(folder / f"{scene_name}.toml")
        image_tab = compose_scene(scene, tier=tier).text
        webgl2 = compose_scene(scene, target="webgl2", tier=tier).text
        composed[scene_name, tier] = (image_tab, webgl2)
    return composed


@pytest.fixture(scope="module")
def pictures() -> dict[str, Pictures]:
    """Each scene's pictures ([channels] of the channels its materials read), as the files hold
    them: RGBA8, top row first. Every runner binds them as ShaderToy binds a picture."""
    folder = default_scene_path().parent
    out = {}
    for scene_name in SCENES:
        scene = load_scene(folder / f"{scene_name}.toml")
        out[scene_name] = {
            unit: np.asarray(Image.open(path).convert("RGBA"))
            for unit, path in sorted(scene.bound_pictures().items())
        }
    return out


def _glint_images(
    shaders: dict[tuple[str, str], tuple[str, str]],
    pictures: dict[str, Pictures],
    sampling: str,
    only_with_pictures: bool = False,
) -> Images:
    """glint's own render of each Image tab (moderngl, EGL), its pictures sampled `sampling`."""
    images: Images = {}
    for case, (image_tab, _) in shaders.items():
        channels = pictures[case[0]]
        if only_with_pictures and not channels:
            continue
        data: list[np.ndarray | None] = [None] * (max(channels) + 1 if channels else 0)
        for unit, picture in channels.items():
            data[unit] = np.ascontiguousarray(picture[::-1], np.float32) / 255.0
        images[case] = render_full(
            image_tab, WIDTH, HEIGHT, time=TIME, channels=data, pictures=sampling
        ).image
    return images


@pytest.fixture(scope="module")
def moderngl_images(
    shaders: dict[tuple[str, str], tuple[str, str]], pictures: dict[str, Pictures]
) -> Images:
    """glint's own render of each Image tab, pictures mipmapped as ShaderToy samples them: the
    reference of the comparisons."""
    return _glint_images(shaders, pictures, "mipmap")


@pytest.fixture(scope="module")
def moderngl_unmipmapped_images(
    shaders: dict[tuple[str, str], tuple[str, str]], pictures: dict[str, Pictures]
) -> Images:
    """The scenes with pictures again, sampled without mipmaps: wgpu-shadertoy 0.2 has no
    mipmapped channel (its filter is linear or nearest), so against it glint samples the same
    way; the difference that remains is the runners'."""
    return _glint_images(shaders, pictures, "linear", only_with_pictures=True)


@pytest.fixture(scope="module")
def webgl2_images(
    browser: Browser,
    shaders: dict[tuple[str, str], tuple[str, str]],
    pictures: dict[str, Pictures],
) -> Images:
    images = render_webgl2(
        browser, [webgl2 for _, webgl2 in shaders.values()], WIDTH, HEIGHT, TIME,
        pictures=[pictures[scene] for scene, _ in shaders],
    )  # fmt: skip
    return dict(zip(shaders, images, strict=True))


@pytest.fixture(scope="module")
def wgpu_images(
    shaders: dict[tuple[str, str], tuple[str, str]], pictures: dict[str, Pictures]
) -> Images:
    missing = wgpu_missing()
    if missing:
        pytest.skip(f"{missing}: {MAKE_TEST}")
    images = render_wgpu(
        [image_tab for image_tab, _ in shaders.values()], WIDTH, HEIGHT, TIME,
        pictures=[pictures[scene] for scene, _ in shaders],
    )  # fmt: skip
    return dict(zip(shaders, images, strict=True))


def _mean_rgb(image: np.ndarray) -> list[float]:
    return [round(float(v), 3) for v in image[:, :, :3].mean(axis=(0, 1))]


@pytest.mark.parametrize(
    "runner", [pytest.param("webgl2", marks=pytest.mark.browser), pytest.param("wgpu")]
)
@pytest.mark.parametrize(
    ("scene", "tier"),
    [
        *(pytest.param(s, t, id=f"{s}-{t}") for s, t in CASES),
        *(
            pytest.param(s, "-", id=s, marks=pytest.mark.skip(reason=MESH_SKIP))
            for s in MESH_SCENES
        ),
    ],
)
def test_runner_draws_what_glint_draws(
    request: pytest.FixtureRequest,
    moderngl_images: Images,
    runner: str,
    scene: str,
    tier: str,
) -> None:
    seen = request.getfixturevalue(f"{runner}_images")[scene, tier]
    where = f"scene {scene!r}, tier {tier}, {RUNNER_NAMES[runner]}"
    if isinstance(seen, RunnerFailure):
        pytest.fail(f"{where}: the runner could not draw the shader: {seen}")
    reference = moderngl_images[scene, tier]
    if runner == "wgpu" and (scene, tier) in (
        unmipmapped := request.getfixturevalue("moderngl_unmipmapped_images")
    ):
        reference = unmipmapped[scene, tier]
    error = flip_error(reference, seen)
    print(f"{scene} {tier} {runner}: mean FLIP {error:.5f} against moderngl")
    assert error <= FLIP_LIMIT, (
        f"{where}: mean FLIP {error:.4f} against glint render (moderngl, llvmpipe) at "
        f"{WIDTH}x{HEIGHT}, iTime {TIME}; the limit is {FLIP_LIMIT}. Mean RGB: moderngl "
        f"{_mean_rgb(reference)}, {runner} {_mean_rgb(seen)}"
    )
