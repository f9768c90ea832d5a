"""The composed default scene is the template's scene: composed with the template's models, it
renders like an independent, monolithic rewrite of the lighting-model skill's template
(compiler/bench/template.glsl), with no NaN/Inf."""

from __future__ import annotations

import numpy as np
import pytest

from glint import compose
from glint.compiler.bench.scenes import TEMPLATE_MODELS, template_source
from glint.compiler.render import flip_error, image_stats, render

pytestmark = pytest.mark.render

# Mean FLIP between the two renders. They compute the same model with the same float
# operations, so anything beyond rounding noise means the composed scene drifted. Measured on
# llvmpipe: 0.0 for the composed scene; 0.004 for the sphere at roughness 0.45 instead of 0.35,
# 0.005 for hard instead of soft shadows, 0.08 without the back light.
FLIP_TOLERANCE = 0.001
# A mean hides small local changes, so also bound the pixels that visibly differ.
PIXEL_STEP = 2.0 / 255.0
MAX_DIFFERING_FRACTION = 0.001
SIZE = (320, 180)


@pytest.fixture(scope="module")
def composed() -> str:
    text = compose(tier="balanced", variants=TEMPLATE_MODELS).text
    # The catalog's sphere tracing takes 512 steps where the template stops at 128 (and then
    # shows sky below a grazing horizon); with the template's budget it is the template's march.
    assert text.count("#define MARCH_STEPS 512\n") == 1
    return text.replace("#define MARCH_STEPS 512\n", "#define MARCH_STEPS 128\n")


@pytest.mark.parametrize("time", [0.0, 1.0, 7.5])
def test_composed_default_matches_the_template(composed: str, time: float) -> None:
    ours = render(composed, *SIZE, time=time)
    reference = render(template_source(), *SIZE, time=time)
    stats = image_stats(ours)
    assert stats["nan"] == 0 and stats["inf"] == 0
    # Not a blank frame: sky, sphere and ground give real contrast.
    assert stats["black_fraction"] < 0.01 and max(stats["std"]) > 0.05
    error = flip_error(reference, ours)
    assert error <= FLIP_TOLERANCE, f"mean FLIP {error:.4f} at iTime {time}"
    differing = (np.abs(ours[..., :3] - reference[..., :3]).max(axis=2) > PIXEL_STEP).mean()
    assert differing <= MAX_DIFFERING_FRACTION, f"{differing:.2%} of pixels differ"


def test_the_red_sphere_is_in_the_middle(composed: str) -> None:
    """The picture has the template's content where the template puts it."""
    img = render(composed, *SIZE, time=0.0)
    h, w = img.shape[:2]
    centre = img[h // 2 - 5 : h // 2 + 5, w // 2 - 5 : w // 2 + 5, :3].mean(axis=(0, 1))
    assert centre[0] > centre[1] + 0.1 and centre[0] > centre[2] + 0.1  # red sphere
    sky = img[2:8, :, :3].mean(axis=(0, 1))
    assert sky[2] >= sky[0] and sky.min() > 0.5  # pale blue sky at the top
    ground = img[-8:-2, :, :3]
    assert ground.std() > 0.03  # checker contrast at the bottom


def test_different_times_differ(composed: str) -> None:
    """The camera orbits with iTime."""
    a = render(composed, 160, 90, time=0.0)
    b = render(composed, 160, 90, time=3.0)
    assert np.abs(a - b).mean() > 0.01
