"""How much a slot's variant pictures differ from one another: the measure of whether a slot's
page shows what choosing a variant changes (issue 27).

For two pictures of the same size, the share of pixels where some channel differs by more than
3/255; for a slot, the median of that share over every pair of its variants' pictures. A slot
whose pictures all look the same scores near 0; the site's goal is at least 5 % for the surface
slots, shadows and AO. Measured on the built site's PNGs (what a reader sees), or on fresh
renders with

    python -m glint.compiler.site.variant_contrast [SLOT ...]
"""

from __future__ import annotations

import argparse
import itertools
import statistics
import sys
import tempfile
from collections.abc import Iterable, Mapping
from pathlib import Path

import numpy as np

from glint.compiler.render.images import png_pixels

THRESHOLD = 3 / 255  # a difference a reader can see on a good screen, side by side
GOAL = 0.05  # the median pairwise share the issue asks of D, F, V, specular, diffuse, shadow, AO
# and specular occlusion, which has a preview of its own (a polished corner)
MEASURED_SLOTS = ("D", "F", "V", "specular", "diffuse", "shadow", "ao", "specocc")


def differing_share(a: bytes, b: bytes) -> float:
    """The share of pixels of two PNGs of one size where a colour channel differs by more than
    THRESHOLD."""
    return _share(png_pixels(a), png_pixels(b))


def _share(pa: np.ndarray, pb: np.ndarray) -> float:
    pa, pb = pa[..., :3], pb[..., :3]
    if pa.shape != pb.shape:
        raise ValueError(f"pictures of different sizes: {pa.shape} and {pb.shape}")
    return float(np.mean(np.any(np.abs(pa - pb) > THRESHOLD, axis=-1)))


def pairwise_shares(pictures: Mapping[str, bytes]) -> dict[tuple[str, str], float]:
    """`differing_share` of every pair of the named PNGs (each decoded once)."""
    pixels = {name: png_pixels(png) for name, png in pictures.items()}
    return {(a, b): _share(pixels[a], pixels[b]) for a, b in itertools.combinations(pixels, 2)}


def slot_contrast(pictures: Iterable[bytes]) -> float | None:
    """The median share of differing pixels over every pair of the pictures (None for fewer
    than two)."""
    shares = pairwise_shares({str(i): png for i, png in enumerate(pictures)})
    return statistics.median(shares.values()) if shares else None


def contrasts(by_slot: Mapping[str, list[bytes]]) -> dict[str, float | None]:
    return {slot: slot_contrast(pngs) for slot, pngs in by_slot.items()}


def _rendered(slots: Iterable[str], cache_dir: Path) -> dict[str, list[bytes]]:
    """Each slot's variant pictures, rendered as the site renders them."""
    import glint

    from .pictures import variant_pictures

    catalog = glint.catalog()
    out: dict[str, list[bytes]] = {}
    for slot in slots:
        ids = sorted(i for i, s in catalog.items() if s.slot == slot)
        built = variant_pictures(ids, cache_dir)
        out[slot] = [built.files[p.path] for p in built.by_id.values() if p.path is not None]
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m glint.compiler.site.variant_contrast",
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("slots", nargs="*", default=list(MEASURED_SLOTS))
    parser.add_argument("--cache-dir", type=Path, default=None)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        pictures = _rendered(args.slots, args.cache_dir or Path(tmp))
    for slot, share in contrasts(pictures).items():
        shown = "—" if share is None else f"{share:.1%}"
        mark = ""
        if share is not None and slot in MEASURED_SLOTS:
            mark = "  ok" if share >= GOAL else f"  below {GOAL:.0%}"
        print(f"{slot:<10} {len(pictures[slot]):>2} pictures  median pairwise {shown}{mark}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
