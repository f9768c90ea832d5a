"""Image statistics, atomic PNG output and FLIP comparison."""

from __future__ import annotations

import os
import stat

import numpy as np
import pytest

from glint.compiler.errors import EnvironmentProblem, InputError
from glint.compiler.render.images import (
    BLOCK_PIXELS,
    OUTLIER_FLOOR,
    flip_error,
    flip_map,
    flip_summary,
    image_stats,
    load_png,
    luminance,
    outlier_mask,
    outlier_share,
    png_bytes,
    png_pixels,
    save_png,
    to_display,
)


def gradient(width: int = 48, height: int = 32) -> np.ndarray:
    """A smooth RGBA test picture with values on the 8-bit grid."""
    y, x = np.mgrid[0:height, 0:width].astype(np.float32)
    rgb = np.stack([x / (width - 1), y / (height - 1), 0.5 + 0 * x], axis=2)
    rgba = np.concatenate([rgb, np.ones_like(rgb[:, :, :1])], axis=2)
    return (np.round(rgba * 255) / 255).astype(np.float32)


def test_stats_of_a_gradient() -> None:
    stats = image_stats(gradient())
    assert (stats["width"], stats["height"], stats["nan"], stats["inf"]) == (48, 32, 0, 0)
    assert stats["finite_min"] == 0.0 and stats["finite_max"] == 1.0
    assert stats["mean"] == pytest.approx([0.5, 0.5, 0.5], abs=0.01)
    assert stats["std"][2] == 0.0
    assert stats["black_fraction"] == 0.0 and stats["white_fraction"] == 0.0


def test_stats_count_broken_and_blank_pixels() -> None:
    img = np.zeros((4, 4, 4), dtype=np.float32)
    img[0, 0, 0] = np.nan
    img[0, 1, 3] = np.nan  # NaN in alpha counts too
    img[1, 0, 2] = np.inf
    img[3, :, :3] = 1.0
    stats = image_stats(img)
    assert (stats["nan"], stats["inf"]) == (2, 1)
    assert stats["black_fraction"] == pytest.approx(10 / 16)
    assert stats["white_fraction"] == pytest.approx(4 / 16)
    assert stats["finite_max"] == 1.0


def test_a_channel_with_no_finite_value_has_no_mean() -> None:
    img = np.zeros((2, 3, 4), dtype=np.float32)
    img[:, :, 0] = np.nan
    img[:, :, 1] = np.inf
    stats = image_stats(img)
    assert stats["mean"] == [None, None, 0.0] and stats["std"] == [None, None, 0.0]
    assert stats["finite_min"] == stats["finite_max"] == 0.0


def test_stats_of_a_large_image_are_numpy_s_over_the_whole() -> None:
    """Taken in blocks of rows, the figures are those of numpy over the whole image."""
    rng = np.random.default_rng(7)
    img = rng.normal(0.5, 0.5, (3 * BLOCK_PIXELS // 500 + 7, 500, 4)).astype(np.float32)
    img[3, 4, 0] = np.nan
    img[-1, -1, 2] = -np.inf
    stats = image_stats(img)
    rgb = img[:, :, :3].astype(np.float64)
    masked = np.ma.masked_invalid(rgb)
    assert stats["mean"] == pytest.approx(list(masked.mean(axis=(0, 1))), rel=1e-12)
    assert stats["std"] == pytest.approx(list(masked.std(axis=(0, 1))), rel=1e-9)
    assert stats["finite_min"] == float(masked.min()) and stats["finite_max"] == float(masked.max())
    assert (stats["nan"], stats["inf"]) == (1, 1)
    # The PNG, written in blocks, is the whole image in display space.
    display = (to_display(img) * 255.0).round().astype(np.uint8)
    assert np.array_equal(png_pixels(png_bytes(img)), display / np.float32(255.0))
    assert tuple(display[3, 4]) == (255, 0, 255)  # NaN is magenta


def test_stats_and_png_of_a_large_image_take_little_memory() -> None:
    """Statistics and PNG output of a 1024x1024 float frame (16 MB) allocate what a few blocks
    take and the PNG's 8-bit pixels (3 MB) and its bytes, not copies of the frame (measured
    with tracemalloc: 6.5 MB and 7.3 MB; 109 MB and 40 MB before they went by blocks)."""
    import tracemalloc

    img = np.random.default_rng(3).random((1024, 1024, 4), dtype=np.float32)
    tracemalloc.start()
    try:
        image_stats(img)
        _, stats_peak = tracemalloc.get_traced_memory()
        tracemalloc.reset_peak()
        png_bytes(img)
        _, png_peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert stats_peak < 16 << 20, stats_peak
    assert png_peak < 16 << 20, png_peak


def test_png_round_trip(tmp_path: os.PathLike[str]) -> None:
    img = gradient()
    img[0, 0, :3] = [2.0, -1.0, 0.5]  # out of range: clamped
    img[0, 1, 1] = np.nan  # shown as magenta
    path = os.path.join(tmp_path, "out.png")
    save_png(img, path)
    back = load_png(path)
    assert back.shape == (32, 48, 3)
    np.testing.assert_array_equal(back[1:], img[1:, :, :3])
    np.testing.assert_allclose(back[0, 0], [1.0, 0.0, 128 / 255], rtol=1e-6)
    np.testing.assert_array_equal(back[0, 1], [1.0, 0.0, 1.0])
    assert os.listdir(tmp_path) == ["out.png"]  # no temporary file left behind


def test_unwritable_path_is_an_environment_problem(tmp_path: os.PathLike[str]) -> None:
    missing = os.path.join(tmp_path, "no", "such", "dir", "out.png")
    with pytest.raises(EnvironmentProblem, match="choose a writable path") as raised:
        save_png(gradient(), missing)
    assert raised.value.exit_code == 2
    assert not os.path.exists(os.path.dirname(missing))


@pytest.mark.skipif(os.geteuid() == 0, reason="root can write to a read-only directory")
def test_read_only_directory_leaves_nothing(tmp_path: os.PathLike[str]) -> None:
    locked = os.path.join(tmp_path, "locked")
    os.mkdir(locked)
    os.chmod(locked, stat.S_IRUSR | stat.S_IXUSR)
    try:
        with pytest.raises(EnvironmentProblem):
            save_png(gradient(), os.path.join(locked, "out.png"))
        assert os.listdir(locked) == []
    finally:
        os.chmod(locked, stat.S_IRWXU)


def test_failed_replace_leaves_no_temporary_file(tmp_path: os.PathLike[str]) -> None:
    # The target is a directory, so the final rename fails after the PNG was written.
    target = os.path.join(tmp_path, "taken")
    os.mkdir(target)
    with pytest.raises(EnvironmentProblem, match="cannot write"):
        save_png(gradient(), target)
    assert os.listdir(tmp_path) == ["taken"]


def test_flip_error_of_identical_images_is_zero() -> None:
    assert flip_error(gradient(), gradient()) == 0.0


def test_flip_error_sees_a_difference() -> None:
    other = gradient()
    other[8:24, 12:36, :3] = 1.0 - other[8:24, 12:36, :3]
    error = flip_error(gradient(), other)
    assert 0.0 < error <= 1.0
    # A PNG that was written and read back compares equal to the image it came from.
    assert flip_error(other, np.round(other * 255) / 255) == 0.0


def test_flip_error_rejects_different_sizes() -> None:
    with pytest.raises(InputError, match="different sizes"):
        flip_error(gradient(48, 32), gradient(32, 48))


def test_flip_map_is_per_pixel_and_its_mean_is_flip_error() -> None:
    other = gradient()
    other[8:24, 12:36, :3] = 1.0 - other[8:24, 12:36, :3]
    error = flip_map(gradient(), other)
    assert error.shape == (32, 48)
    assert float(error.mean()) == pytest.approx(flip_error(gradient(), other), abs=1e-6)
    assert error[0, 0] == 0.0 and error[16, 24] > 0.1  # far from the change / inside it


def test_flip_summary_pools_the_maps_and_takes_a_pixel_value_as_p99() -> None:
    # 990 pixels at 0 and 10 at 1: 99 % do not exceed 0. One more at 1 and p99 is 1.
    quiet = np.zeros(1000, np.float32)
    quiet[:10] = 1.0
    assert flip_summary([quiet.reshape(20, 50)]) == (pytest.approx(0.01), 0.0)
    loud = quiet.copy()
    loud[10] = 1.0
    assert flip_summary([loud.reshape(20, 50)])[1] == 1.0
    # Two views pooled: 101 zeros, then 0.01 ... 0.99; the 198th of the 200 values is 0.97
    # (the ramp's own p99 is 0.98, the zeros' 0: neither their mean nor the larger).
    ramp = np.arange(100, dtype=np.float32).reshape(10, 10) / 100.0
    mean, p99 = flip_summary([ramp, np.zeros((10, 10), np.float32)])
    assert mean == pytest.approx(0.495 / 2) and p99 == pytest.approx(0.97)


def grey(level: float, height: int = 10, width: int = 20) -> np.ndarray:
    return np.full((height, width, 3), level, dtype=np.float32)


def test_luminance_decodes_the_display_gamma_and_weighs_rec709() -> None:
    assert luminance(grey(0.5))[0, 0] == pytest.approx((128 / 255) ** 2.2)  # 8-bit grid
    red = np.zeros((1, 1, 3), np.float32)
    red[..., 0] = 1.0
    assert luminance(red)[0, 0] == pytest.approx(0.2126)


def test_a_known_number_of_darkened_pixels_is_that_share_of_outliers() -> None:
    reference = grey(0.6)
    test = reference.copy()
    test.reshape(-1, 3)[:7] = 0.6 * 0.5 ** (1 / 2.2) - 0.01  # just under half the luminance
    test.reshape(-1, 3)[7:12] = 0.6 * 0.5 ** (1 / 2.2) + 0.01  # just above: not outliers
    test.reshape(-1, 3)[12] = 1.0  # (1 / 0.6) ** 2.2 = 3.1 times brighter
    assert outlier_mask(reference, test).sum() == 8
    assert outlier_share(reference, test) == pytest.approx(8 / 200)
    assert outlier_share(reference, reference) == 0.0


def test_near_black_pixels_are_not_outliers() -> None:
    black = grey(0.0)
    # Levels 0 against 3/255: infinitely brighter, but both under the floor.
    assert luminance(grey(3 / 255))[0, 0] < OUTLIER_FLOOR
    assert outlier_share(black, grey(3 / 255)) == 0.0
    # 4/255 is above the floor: against black it is an outlier, against 3/255 (one step) not.
    assert outlier_share(black, grey(4 / 255)) == 1.0
    assert outlier_share(grey(3 / 255), grey(4 / 255)) == 0.0
    # One 8-bit step is never an outlier once the brighter pixel is above the floor.
    for level in range(3, 255):
        assert outlier_share(grey(level / 255), grey((level + 1) / 255)) == 0.0, level


def test_outliers_reject_different_sizes() -> None:
    with pytest.raises(InputError, match="different sizes"):
        outlier_share(gradient(48, 32), gradient(32, 48))
