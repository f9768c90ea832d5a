"""What a slot's page shows of its variants side by side: each variant's picture with its FLIP
error image against the variant the reference tier takes for the slot, the slot's cost/error
chart with its front marked, its rows of the bench table, and one live canvas with a selector
of the variants (live_canvas.py).

Every variant of a slot is shown in the same scene (pictures.scene_using), so their pictures
compare pixel for pixel. The chart is drawn with matplotlib from the bench report and cached
by a hash of the data it shows, like the pictures.
"""

from __future__ import annotations

import hashlib
import json
import logging
import statistics
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath
from typing import Any

import numpy as np

import glint
from glint.compiler.catalog.tiers import tier_choice, tier_table
from glint.compiler.files import write_atomic
from glint.compiler.markdown import (
    md_code,
    md_text,
    path_url,
    safe_image,
    safe_link,
    table,
    url_part,
)
from glint.compiler.render.images import flip_image, png_bytes, png_pixels

from .live_canvas import slot_compare_section, slot_live_section
from .measured import Bench, figure_png, pyplot, time_per_call
from .pictures import Picture

FLIP_DIR = PurePosixPath("img") / "flip"
CHART_DIR = PurePosixPath("img") / "charts"
log = logging.getLogger(__name__)
CHART_VERSION = "1"  # bump when the chart's look changes


@dataclass
class SlotComparisons:
    """Per slot, the Markdown section of its page; the images it shows, by path."""

    sections: dict[str, str] = field(default_factory=dict)
    files: dict[PurePosixPath, bytes] = field(default_factory=dict)


def reference_variant(slot: str, tiers: Mapping[str, Mapping[str, str]]) -> str | None:
    """The variant the reference tier takes for `slot` (balanced's where it names none)."""
    chosen = tier_choice(tiers, "reference", slot)
    return f"{slot}.{chosen}" if chosen else None


def slot_comparisons(
    slots: Mapping[str, list[str]],
    pictures: Mapping[str, Picture],
    picture_files: Mapping[PurePosixPath, bytes],
    bench: Bench,
    cache_dir: Path | None,
) -> SlotComparisons:
    """The sections of the slots' pages: `slots` maps each slot to its variant ids."""
    tiers = tier_table()
    result = SlotComparisons()
    for slot, ids in slots.items():
        reference = reference_variant(slot, tiers)
        parts = [
            _flip_table(ids, reference, pictures, picture_files, result),
            slot_live_section(slot, ids, pictures, reference),
            slot_compare_section(slot, ids, pictures, reference),
        ]
        if any(i in pictures for i in ids):  # drawn where the build draws the slot's pictures
            parts.append(_curves(slot, ids, reference, cache_dir, result))
        rows = [bench.variants[i] for i in ids if i in bench.variants]
        if rows:
            parts.append(_bench_section(slot, rows, bench.machine, cache_dir, result))
        if any(parts):
            result.sections[slot] = "".join(parts)
    return result


def _flip_table(
    ids: list[str],
    reference: str | None,
    pictures: Mapping[str, Picture],
    files: Mapping[PurePosixPath, bytes],
    result: SlotComparisons,
) -> str:
    """Each variant's picture and its FLIP image against the reference variant's picture."""
    ref_picture = pictures.get(reference) if reference else None
    if ref_picture is None or ref_picture.path is None or ref_picture.path not in files:
        return ""
    truth = png_pixels(files[ref_picture.path])
    rows = []
    for snippet_id in ids:
        picture = pictures.get(snippet_id)
        if picture is None or picture.path is None or picture.path not in files:
            continue
        shown = _image(snippet_id, picture.path)
        if snippet_id == reference:
            rows.append([_variant_link(snippet_id), shown, "the reference", "0"])
            continue
        error_map, mean = flip_image(truth, png_pixels(files[picture.path]))
        flip_path = FLIP_DIR / f"{snippet_id}.png"
        result.files[flip_path] = png_bytes(error_map)
        flip = _image(f"FLIP error of {snippet_id}", flip_path)
        rows.append([_variant_link(snippet_id), shown, flip, f"{mean:.4f}"])
    if len(rows) < 2:
        return ""
    scene = ref_picture.scene
    shown = {i: files[p.path] for i in ids if (p := pictures.get(i)) and p.path in files}
    return (
        "## Side by side\n\n"
        f"Each variant in {scene}, and its FLIP error image against {md_code(reference or '')}, "
        "the variant the reference tier takes (black: no visible difference; bright: "
        "large). The last column is the mean FLIP error over the picture. "
        + _how_much_they_differ(shown)
        + "\n\n"
        + table(["variant", "picture", "FLIP against the reference", "mean FLIP"], rows)
        + "\n"
    )


def _how_much_they_differ(pngs: Mapping[str, bytes]) -> str:
    """What the pictures show of the choice, in numbers: the median share of pixels two
    variants' pictures differ in (variant_contrast.py), and the variants whose pictures are the
    same here, so that a reader does not look for a difference that is not there."""
    from .variant_contrast import pairwise_shares  # also a script: not imported with the package

    same: dict[str, str] = {i: i for i in pngs}  # each variant's group: the first one like it

    def group(i: str) -> str:
        while same[i] != i:
            i = same[i]
        return i

    shares = pairwise_shares(pngs)
    for (a, b), share in shares.items():
        if share == 0.0:
            same[group(b)] = group(a)
    text = (
        f"Between two variants' pictures, a median {statistics.median(shares.values()):.1%} of the "
        f"pixels differ by more than 3/255."
    )
    groups: dict[str, list[str]] = {}
    for i in pngs:
        groups.setdefault(group(i), []).append(i)
    for members in groups.values():
        if len(members) > 1:
            names = ", ".join(md_code(m) for m in members[:-1]) + f" and {md_code(members[-1])}"
            text += (
                f" {names} give the same picture here (no pixel differs by more than 3/255): "
                "they differ in cost or float16 behaviour, or on inputs this scene does not "
                "reach (their pages say where)."
            )
    return text


def _curves(
    slot: str, ids: list[str], reference: str | None, cache_dir: Path | None,
    result: SlotComparisons,
) -> str:  # fmt: skip
    """The slot's curves chart (slot_curves.py), where the slot has a sweep."""
    from .slot_curves import curves_png, curves_section, slot_curves

    try:
        curves = slot_curves(slot, ids, reference)
    except glint.InputError as error:  # no GPU context to probe with: the page goes without
        log.warning("site: no curves for slot %s: %s", slot, error)
        return ""
    if curves is None:
        return ""
    path = CHART_DIR / f"{slot}-curves.png"
    result.files[path] = curves_png(curves, cache_dir)
    return curves_section(path_url(path, "../../"), curves)


def _image(alt: str, path: PurePosixPath) -> str:
    """A picture in the side-by-side table (from a slot's page, two folders down)."""
    return safe_image(md_text(alt), path_url(path, "../../")) + '{ width="192" }'


def _variant_link(snippet_id: str) -> str:
    return safe_link(md_code(snippet_id), f"../{url_part(snippet_id)}.md")


def _bench_section(
    slot: str,
    rows: list[dict[str, Any]],
    machine: str,
    cache_dir: Path | None,
    result: SlotComparisons,
) -> str:
    parts = ["## Cost and error\n\n"]
    measured = [r for r in rows if r.get("rms") is not None]
    if len(measured) >= 2:
        # Relative where every variant has it: references of one slot differ in scale (D_ggx
        # peaks near 1e5 where D_gaussian does not), and an absolute RMS compares their units.
        relative = all(r.get("rel_rms") is not None for r in measured)
        chart = _chart(slot, measured, cache_dir, "rel_rms" if relative else "rms")
        path = CHART_DIR / f"{slot}.png"
        result.files[path] = chart
        alt = md_text(f"cost and error of the {slot} variants")
        units = sorted({(str(r["reference"]), str(r.get("error_unit") or "")) for r in measured})
        if relative:
            error = "RMS error relative to its float64 reference's RMS"
        elif len({unit for _, unit in units}) == 1:
            error = f"RMS error against its float64 reference, in {md_text(units[0][1])}"
        else:  # not one scale: each reference's own unit, and the chart's colours keep them apart
            each = "; ".join(f"{md_code(ref)}: {md_text(unit)}" for ref, unit in units)
            error = f"RMS error against its float64 reference in that reference's unit ({each})"
        parts.append(
            f"{safe_image(alt, path_url(path, '../../'))}\n\n"
            f"Each variant's {error} over its time per call; the variants on the front "
            "(filled, joined) are those no other variant measured against the same reference "
            "beats on both.\n\n"
        )
    parts.append(_table(rows))
    if machine:
        parts.append(f"\nMeasured by `glint bench` on {md_text(machine)}.\n")
    return "".join(parts) + "\n"


def _table(rows: list[dict[str, Any]]) -> str:
    def num(value: float | None) -> str:
        return "–" if value is None else f"{value:.3g}"

    body = [
        [
            _variant_link(str(r["id"])),
            md_code(str(r["reference"])) if r.get("reference") else "–",
            num(r.get("max_abs")),
            num(r.get("rms")),
            num(r.get("rel_rms")),
            num(r.get("max_rel")),
            md_text(str(r["spirv"])),
            time_per_call(r["gpu_ns"], unit=False),
            "★" if r.get("pareto") else "",
        ]
        for r in rows
    ]
    header = ["variant", "reference", "max abs", "RMS", "RMS / ref.", "max rel", "SPIR-V", "ns"]
    header.append("front")
    return table(header, body)


def _chart(slot: str, rows: list[dict[str, Any]], cache_dir: Path | None, error: str) -> bytes:
    """The cost/error chart of a slot's measured variants, `error` ("rms" or "rel_rms") up."""
    data = [[r["id"], r["reference"], r["gpu_ns"], r[error], bool(r.get("pareto"))] for r in rows]
    key = hashlib.sha256(
        json.dumps([glint.__version__, CHART_VERSION, slot, error, data]).encode("utf-8")
    ).hexdigest()[:32]
    cached = cache_dir / f"chart-{key}.png" if cache_dir is not None else None
    if cached is not None and cached.is_file():
        return cached.read_bytes()
    png = _draw_chart(
        slot, data, "RMS error / reference's RMS" if error == "rel_rms" else "RMS error"
    )
    if cached is not None:
        cache_dir.mkdir(parents=True, exist_ok=True)  # type: ignore[union-attr]
        write_atomic(cached, png)
    return png


def _draw_chart(slot: str, data: list[list[Any]], ylabel: str) -> bytes:
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.0, 3.6), dpi=100, layout="constrained")
    references = sorted({row[1] for row in data})
    for colour, reference in enumerate(references):
        group = [row for row in data if row[1] == reference]
        ns = np.array([max(row[2], 0.01) for row in group])  # 0 ns: below what can be measured
        rms = np.array([max(row[3], 1e-9) for row in group])
        front = np.array([row[4] for row in group])
        ax.scatter(ns[~front], rms[~front], facecolors="none", edgecolors=f"C{colour}")
        ax.scatter(ns[front], rms[front], color=f"C{colour}", label=f"against {reference}")
        order = np.argsort(ns[front])
        ax.step(ns[front][order], rms[front][order], where="post", color=f"C{colour}", alpha=0.5)
        for row, x, y in zip(group, ns, rms, strict=True):
            ax.annotate(row[0].split(".", 1)[1], (x, y), fontsize=7, xytext=(3, 3),
                        textcoords="offset points")  # fmt: skip
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("ns per call")
    ax.set_ylabel(ylabel)
    ax.set_title(f"slot {slot}: cost against error", fontsize=9)
    ax.legend(fontsize=7)
    return figure_png(fig)
