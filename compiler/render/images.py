"""Rendered images: statistics that show a render is sane, PNG output, and perceptual error.

Images are float32 arrays H x W x C (C = 3 or 4, row 0 at the top) straight from the float
framebuffer, so they may hold values outside [0, 1], NaN and Inf. Display space is what ShaderToy
shows and what a PNG stores: RGB clamped to [0, 1] and quantised to 8 bits, NaN shown as magenta.
"""

from __future__ import annotations

import io
import os
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
from PIL import Image

from glint.compiler.errors import InputError
from glint.compiler.files import write_atomic

# A pixel counts as black or white when every RGB channel is within one 8-bit step of the end.
BLACK_LEVEL = 1.0 / 255.0
WHITE_LEVEL = 254.0 / 255.0
NAN_COLOUR = np.array([1.0, 0.0, 1.0], dtype=np.float32)


def _rgb(img: np.ndarray) -> np.ndarray:
    """The RGB channels as float32; 8-bit input (a loaded PNG) is scaled to [0, 1]."""
    array = np.asarray(img)
    if array.ndim == 2:
        array = np.repeat(array[:, :, None], 3, axis=2)
    if array.ndim != 3 or array.shape[2] < 3:
        raise ValueError(f"expected an H x W x 3 or 4 image, got shape {array.shape}")
    if array.dtype == np.uint8:
        return array[:, :, :3].astype(np.float32) / 255.0
    return array[:, :, :3].astype(np.float32)


# Statistics and PNG output go through a large image in blocks of about this many pixels, so that
# their temporary arrays stay a few MB however large the image (limits.PIPELINE_BYTES_PER_PIXEL).
BLOCK_PIXELS = 1 << 16


def _row_blocks(array: np.ndarray) -> list[np.ndarray]:
    """Views of consecutive rows of `array`, each about BLOCK_PIXELS pixels."""
    height = array.shape[0]
    width = array.shape[1] if array.ndim > 1 else 1
    step = max(1, BLOCK_PIXELS // max(width, 1))
    return [array[top : top + step] for top in range(0, height, step)]


def image_stats(img: np.ndarray) -> dict[str, Any]:
    """Summarise an image so a test or a report can tell a real render from a blank or broken one.

    `nan`/`inf` count pixels with any such channel (alpha included); the other figures are over
    the finite RGB values, and are None when there are none (`mean` and `std` per channel:
    None for a channel with no finite value).
    """
    array = np.asarray(img, dtype=np.float32)
    if array.ndim == 3:
        _rgb(array[:1, :1])  # the shape check, before any work
    blocks = _row_blocks(array)
    nan = inf = black = white = 0
    counts = np.zeros(3, dtype=np.int64)
    sums = np.zeros(3, dtype=np.float64)
    low, high = np.inf, -np.inf
    for block in blocks:
        channels = block if block.ndim == 3 else block[:, :, None]
        nan += int(np.isnan(channels).any(axis=2).sum())
        inf += int(np.isinf(channels).any(axis=2).sum())
        rgb = _rgb(block)
        finite = np.isfinite(rgb)
        all_finite = finite.all(axis=2)
        black += int((all_finite & (rgb <= BLACK_LEVEL).all(axis=2)).sum())
        white += int((all_finite & (rgb >= WHITE_LEVEL).all(axis=2)).sum())
        counts += finite.sum(axis=(0, 1))
        values = np.where(finite, rgb, 0.0)
        # float64 sums: a constant channel's mean is then exactly its value, its std exactly 0.
        sums += values.sum(axis=(0, 1), dtype=np.float64)
        if finite.any():
            low = min(low, float(rgb[finite].min()))
            high = max(high, float(rgb[finite].max()))
    has = counts > 0
    means = np.where(has, sums / np.maximum(counts, 1), 0.0)
    squares = np.zeros(3, dtype=np.float64)
    for block in blocks:  # a second pass: deviations from the mean, as numpy's std takes them
        rgb = _rgb(block)
        deviation = np.where(np.isfinite(rgb), rgb.astype(np.float64) - means, 0.0)
        squares += (deviation * deviation).sum(axis=(0, 1))
    stds = np.sqrt(squares / np.maximum(counts, 1))
    height = array.shape[0]
    width = array.shape[1] if array.ndim > 1 else 0
    pixels = max(height * width, 1)
    return {
        "width": int(width),
        "height": int(height),
        "nan": nan,
        "inf": inf,
        "finite_min": low if has.any() else None,
        "finite_max": high if has.any() else None,
        "mean": [float(m) if h else None for m, h in zip(means, has, strict=True)],
        "std": [float(d) if h else None for d, h in zip(stds, has, strict=True)],
        "black_fraction": black / pixels,
        "white_fraction": white / pixels,
    }


def to_display(img: np.ndarray) -> np.ndarray:
    """RGB in display space as float32 in [0, 1], on the 8-bit grid that a PNG stores."""
    rgb = _rgb(img)
    broken = np.isnan(rgb).any(axis=2)
    rgb = np.clip(np.nan_to_num(rgb, nan=0.0), 0.0, 1.0)
    rgb[broken] = NAN_COLOUR
    return np.round(rgb * 255.0) / 255.0


def png_bytes(img: np.ndarray) -> bytes:
    """The image as an 8-bit RGB PNG (to_display: clamped to [0, 1], NaN shown magenta)."""
    array = np.asarray(img)
    if array.ndim == 3:
        _rgb(array[:1, :1])  # the shape check
    pixels = np.empty((*array.shape[:2], 3), dtype=np.uint8)
    row = 0
    for block in _row_blocks(array):  # to_display's float copies, a block at a time
        pixels[row : row + block.shape[0]] = (to_display(block) * 255.0).round().astype(np.uint8)
        row += block.shape[0]
    buffer = io.BytesIO()
    Image.fromarray(pixels, mode="RGB").save(buffer, format="PNG")
    return buffer.getvalue()


def save_png(img: np.ndarray, path: str) -> None:
    """Write the image as an 8-bit RGB PNG, atomically: readers see the old file or the new one."""
    write_atomic(path, png_bytes(img))


def load_png(path: str) -> np.ndarray:
    """Read a PNG as float32 RGB in [0, 1] (golden images are stored this way)."""
    try:
        with Image.open(path) as image:
            return _rgb_of(image)
    except OSError as exc:
        raise InputError(f"cannot read image {path}: {exc}") from exc


# The largest picture a channel takes (ShaderToy's own are at most 1024 on a side).
PICTURE_LIMIT = 4096


def channel_picture(path: str, key: str) -> np.ndarray:
    """A picture file (PNG, JPEG, ...) as a channel's data: float32 RGBA in [0, 1], its bottom
    row first, as ShaderToy binds a picture (flipped, so that v = 0 is the picture's bottom).
    `key` names the argument in messages."""
    try:
        with Image.open(path) as image:
            if max(image.size) > PICTURE_LIMIT:
                raise InputError(
                    f"{key}: {path} is {image.size[0]}x{image.size[1]}; a channel takes a "
                    f"picture of at most {PICTURE_LIMIT} on a side: scale it down"
                )
            rgba = np.asarray(image.convert("RGBA"), dtype=np.float32) / 255.0
    except (OSError, Image.DecompressionBombError) as exc:
        raise InputError(f"{key}: cannot read the picture {path}: {exc}") from None
    return np.ascontiguousarray(rgba[::-1])


def channel_pictures(files: Mapping[int, str | os.PathLike[str]]) -> list[np.ndarray | None]:
    """The pictures of `files` ({channel: file}) as render_full's channel data, None where a
    channel below the last one has no picture (it samples black)."""
    data: list[np.ndarray | None] = [None] * (max(files) + 1 if files else 0)
    for unit, path in files.items():
        data[unit] = channel_picture(os.fspath(path), f"channels[{unit}]")
    return data


def png_pixels(data: bytes) -> np.ndarray:
    """A PNG's bytes (png_bytes, a cached picture) as float32 RGB in [0, 1]."""
    with Image.open(io.BytesIO(data)) as image:
        return _rgb_of(image)


def _rgb_of(image: Image.Image) -> np.ndarray:
    return np.asarray(image.convert("RGB"), dtype=np.float32) / 255.0


def flip_error(reference: np.ndarray, test: np.ndarray) -> float:
    """Mean LDR FLIP error between two images as they are displayed (0 = identical)."""
    return _flip(reference, test, magma=False)[1]


def flip_map(reference: np.ndarray, test: np.ndarray) -> np.ndarray:
    """The per-pixel LDR FLIP error (H x W float32 in [0, 1]) between two images as they are
    displayed; its mean is flip_error's."""
    return _flip(reference, test, magma=False)[0][:, :, 0]


def flip_summary(maps: Sequence[np.ndarray]) -> tuple[float, float]:
    """The mean and the 99th percentile of the per-pixel FLIP of one or more maps (flip_map),
    their pixels pooled. The percentile is the least value that at least 99 % of the pixels do
    not exceed (numpy's "inverted_cdf"): a value that some pixel has, not an interpolation."""
    if not maps:
        raise ValueError("flip_summary needs at least one map")
    pixels = np.concatenate([np.asarray(m, np.float64).ravel() for m in maps])
    return float(pixels.mean()), float(np.quantile(pixels, 0.99, method="inverted_cdf"))


# Luminance of what the screen shows: the shaders write display values (their own tone map, then
# pow(col, 1 / 2.2)), so the display values (to_display) are decoded with the same gamma 2.2 and
# weighed with the Rec. 709 / sRGB primaries' luminance coefficients.
DISPLAY_GAMMA = 2.2
REC709 = np.array([0.2126, 0.7152, 0.0722], dtype=np.float64)
# "Half" or "twice" means nothing between two pixels that are both black on the screen: near black
# the 8-bit grid alone makes such ratios (levels 2 and 3 are 2.4x apart in luminance, 0 and 1
# infinitely). A pixel is therefore tested only where the brighter of the two is at least as
# bright as the 8-bit grey 4/255 (luminance 1e-4, invisible on a screen; the floor sits half a
# step below it, clear of rounding). From there on one 8-bit step is never an outlier:
# ((v + 1) / v) ** 2.2 < 2 for every level v >= 3.
OUTLIER_FLOOR = float((3.5 / 255.0) ** DISPLAY_GAMMA)
OUTLIER_RATIO = 2.0


def luminance(img: np.ndarray) -> np.ndarray:
    """Relative luminance (H x W float64, 0 to 1) of the image as displayed: to_display's RGB
    decoded with DISPLAY_GAMMA, then Rec. 709 weights."""
    return (to_display(img).astype(np.float64) ** DISPLAY_GAMMA) @ REC709


def outlier_mask(reference: np.ndarray, test: np.ndarray) -> np.ndarray:
    """Pixels whose displayed luminance is under half or over twice the reference's (H x W
    bool); pixels where both are at most OUTLIER_FLOOR are never outliers."""
    ref, tst = luminance(reference), luminance(test)
    if ref.shape != tst.shape:
        raise InputError(
            f"cannot compare images of different sizes: {ref.shape[1]}x{ref.shape[0]} "
            f"and {tst.shape[1]}x{tst.shape[0]}"
        )
    lit = np.maximum(ref, tst) > OUTLIER_FLOOR
    return lit & ((tst * OUTLIER_RATIO < ref) | (tst > OUTLIER_RATIO * ref))


def outlier_share(reference: np.ndarray, test: np.ndarray) -> float:
    """The share of pixels (0 to 1) that are outliers (outlier_mask) against the reference."""
    return float(outlier_mask(reference, test).mean())


def flip_image(reference: np.ndarray, test: np.ndarray) -> tuple[np.ndarray, float]:
    """The FLIP error map in the magma colours (RGB in [0, 1]) and its mean."""
    return _flip(reference, test, magma=True)


def _flip(reference: np.ndarray, test: np.ndarray, magma: bool) -> tuple[np.ndarray, float]:
    # Imported here: flip_evaluator is only needed when images are compared.
    import flip_evaluator

    ref, tst = to_display(reference), to_display(test)
    if ref.shape != tst.shape:
        raise InputError(
            f"cannot compare images of different sizes: {ref.shape[1]}x{ref.shape[0]} "
            f"and {tst.shape[1]}x{tst.shape[0]}"
        )
    error_map, mean, _ = flip_evaluator.evaluate(ref, tst, "LDR", applyMagma=magma)
    return np.asarray(error_map, np.float32), float(mean)
