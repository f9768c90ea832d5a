"""What `glint bench` writes: the results as JSON, a Markdown report and PNG charts; and the
measurements file the planner reads (`--update`)."""

from __future__ import annotations

import io
import json
import math
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from glint.compiler.bench.scenes import (
    REFERENCE_TIER,
    SCENE_SPEEDUP,
    TEMPLATE_ROW,
    TEMPLATE_SCENE,
    Goal,
    TierMeasure,
)
from glint.compiler.bench.variants import VariantMeasure
from glint.compiler.catalog.measurements import measurements_path
from glint.compiler.files import write_atomic
from glint.compiler.markdown import md_text


@dataclass
class BenchResult:
    machine: dict[str, Any]  # renderer, whether timings are CPU time, platform, glint version
    variants: list[VariantMeasure] = field(default_factory=list)
    tiers: list[TierMeasure] = field(default_factory=list)
    goals: list[Goal] = field(default_factory=list)


def to_json(result: BenchResult) -> str:
    return json.dumps(asdict(result), indent=2, sort_keys=True) + "\n"


def static_part(result: BenchResult) -> dict[str, Any]:
    """What does not depend on timing: errors and SPIR-V counts of the variants, FLIP and
    SPIR-V counts of the tiers. Two runs on one machine give the same."""
    variants = {
        v.id: {
            k: getattr(v, k) for k in ("reference", "max_abs", "rms", "rel_rms", "max_rel", "spirv")
        }
        for v in result.variants
    }
    tiers = {
        f"{t.scene}/{t.tier}": {k: getattr(t, k) for k in ("flip", "flip_p99", "outliers", "spirv")}
        for t in result.tiers
    }
    return {"variants": variants, "tiers": tiers}


def measurements_json(result: BenchResult) -> str:
    """The generated file the planner's --budget reads: per variant its cost and error, per
    scene and tier the frame time and FLIP, and the machine it was measured on."""
    data = {
        "generated_by": "glint bench --update; do not edit by hand",
        "machine": result.machine,
        "variants": {
            v.id: {
                "slot": v.slot,
                "reference": v.reference,
                "rms": v.rms,
                "rel_rms": v.rel_rms,
                "max_abs": v.max_abs,
                "spirv": v.spirv,
                "gpu_ns": round(v.gpu_ns, 3),
                "pareto": v.pareto,
            }
            for v in result.variants
        },
        "tiers": {
            f"{t.scene}/{t.tier}": {
                "frame_ms": round(t.frame_ms, 3),
                "flip": t.flip,
                "time_vs_reference": round(t.time_vs_reference, 3),
            }
            for t in result.tiers
        },
    }
    return json.dumps(data, indent=1, sort_keys=True) + "\n"


def write_measurements(result: BenchResult) -> Path:
    path = measurements_path()
    write_atomic(path, measurements_json(result).encode("utf-8"))
    return path


def _num(value: float | None, digits: int = 3) -> str:
    if value is None:
        return "–"
    if value == 0 or (1e-3 <= abs(value) < 1e5):
        return f"{value:.{digits}g}"
    return f"{value:.2e}"


def _where(worst: dict[str, float] | None) -> str:
    if not worst:
        return "–"
    return ", ".join(f"{k}={v:.3g}" for k, v in worst.items())


def to_markdown(result: BenchResult) -> str:
    machine = result.machine
    timing = "CPU time (software renderer)" if machine.get("cpu") else "GPU time"
    lines = [
        "# glint bench",
        "",
        f"Measured on {md_text(str(machine.get('renderer', '?')))}: {timing}; "
        f"{md_text(str(machine.get('platform', '')))}.",
        "",
    ]
    if result.goals:
        lines += [
            "## Goals",
            "",
            "On the default scene against the seed template; on every other scene, fast against "
            "that scene's reference tier.",
            "",
        ]
        lines += ["| goal | target | measured | reached |", "|---|---|---|---|"]
        lines += [
            f"| {md_text(g.name)} | {md_text(g.target)} | {md_text(g.measured)} "
            f"| {'yes' if g.reached else '**no**'} |"
            for g in result.goals
        ]
        lines.append("")
    if result.tiers:
        lines += tier_table(result.tiers) + [""]
    if result.variants:
        lines += ["## Variants", ""]
        lines += [
            "Error against each variant's float64 reference over its domain; cost as SPIR-V "
            "instructions after `spirv-opt -O` and as measured time per evaluation of a probe "
            "pass (empty pass subtracted). ★: on the cost/error front of its slot among the "
            "variants with the same reference.",
            "",
        ]
        slot = None
        for v in result.variants:
            if v.slot != slot:
                slot = v.slot
                lines += [
                    "",
                    f"### {md_text(slot)}",
                    "",
                    "| variant | reference | max abs | rms | rms / reference's | max rel "
                    "| worst at | SPIR-V | ns | front |",
                    "|---|---|---|---|---|---|---|---|---|---|",
                ]
            lines.append(
                f"| {md_text(v.id)} | {md_text(v.reference or '–')} "
                f"| {_num(v.max_abs)} | {_num(v.rms)} | {_num(v.rel_rms)} "
                f"| {_num(v.max_rel)} | {_where(v.worst_at)} | {v.spirv} | {_num(v.gpu_ns)} "
                f"| {'★' if v.pareto else ''} |"
            )
    return "\n".join(lines) + "\n"


def _label(text: str) -> str:
    """A label for a chart: matplotlib reads text between two `$` as math (and fails on what is
    not), so a dollar in a scene's name is shown as a dollar."""
    return text.replace("$", r"\$")


def _share(value: float | None) -> str:
    return "–" if value is None else f"{value:.3%}"


def tier_table(tiers: list[TierMeasure]) -> list[str]:
    """The trade table: per scene and tier, frame time with its ratios, and the accuracy
    against the scene's reference tier: mean FLIP, its 99th percentile and the share of
    luminance outliers (under half or over twice reference's), all views' pixels pooled."""
    lines = [
        "| scene | tier | frame ms | × reference | × template | FLIP vs reference "
        "| FLIP p99 | outliers | FLIP vs truth | SPIR-V |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for t in tiers:
        p99 = "–" if t.flip_p99 is None else f"{t.flip_p99:.4f}"
        lines.append(
            f"| {md_text(t.scene)} | {md_text(t.tier)} "
            f"| {t.frame_ms:.2f} | {t.time_vs_reference:.2f} "
            f"| {_num(t.time_vs_template, 2)} | {t.flip:.4f} | {p99} | {_share(t.outliers)} "
            f"| {_num(t.flip_vs_truth, 3)} | {t.spirv} |"
        )
    return lines


def write_charts(result: BenchResult, folder: Path) -> list[Path]:
    """variants.png: per slot, error against measured cost, the front joined; tiers.png: frame
    time against FLIP, every point labelled with its tier (see _tiers_chart)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    written = []
    timing = "CPU ns" if result.machine.get("cpu") else "GPU ns"
    slots = sorted({v.slot for v in result.variants if v.rms is not None})
    if slots:
        columns = 4
        rows = math.ceil(len(slots) / columns)
        fig, axes = plt.subplots(rows, columns, figsize=(4 * columns, 3.2 * rows), squeeze=False)
        for ax, slot in zip(axes.flat, slots, strict=False):
            measured = [v for v in result.variants if v.slot == slot and v.rms is not None]
            for v in measured:
                ax.scatter(v.gpu_ns, v.rms, color="C3" if v.pareto else "C0", zorder=3)
                ax.annotate(v.id.split(".", 1)[1], (v.gpu_ns, v.rms), fontsize=7)
            # A front per reference: variants of different models are not on one line.
            for reference in sorted({v.reference or "" for v in measured}):
                front = sorted(
                    (v.gpu_ns, v.rms) for v in measured if v.pareto and v.reference == reference
                )
                if len(front) > 1:
                    ax.plot(*zip(*front, strict=True), color="C3", lw=1)
            ax.set_title(slot)
            ax.set_xlabel(f"{timing} per evaluation")
            ax.set_ylabel("RMS error")
            if min(v.rms for v in measured) > 0:  # type: ignore[type-var]
                ax.set_yscale("log")
        for ax in list(axes.flat)[len(slots) :]:
            ax.axis("off")
        fig.tight_layout()
        path = folder / "variants.png"
        _save_figure(fig, path, dpi=80)
        plt.close(fig)
        written.append(path)
    if result.tiers:
        path = folder / "tiers.png"
        _tiers_chart(plt, result, path)
        written.append(path)
    return written


_MARKERS = {"fast": "v", "balanced": "o", "reference": "s", "template": "*"}


def _tiers_chart(plt: Any, result: BenchResult, path: Path) -> None:
    """Two panels, every point labelled with its tier. Left, the default scene (the template's):
    frame time in ms against mean FLIP vs its reference tier, the template included, each label
    with its time as a multiple of the template's. Right, every scene: time as a multiple of the
    scene's reference tier (paired by round) against mean FLIP, so that the scenes share one
    axis; the reference tiers all sit at (1, 0), and the line at 1/SCENE_SPEEDUP is fast's goal."""
    timing = "CPU, llvmpipe" if result.machine.get("cpu") else "GPU"
    scenes = list(dict.fromkeys(t.scene for t in result.tiers))
    colour = {scene: f"C{index % 10}" for index, scene in enumerate(scenes)}
    fig, (left, right) = plt.subplots(1, 2, figsize=(14, 5.2))

    default = [t for t in result.tiers if t.scene == TEMPLATE_SCENE]
    for t in default:
        left.scatter(
            t.frame_ms,
            t.flip,
            marker=_MARKERS.get(t.tier, "x"),
            s=70,
            color="black" if t.tier == TEMPLATE_ROW else colour[t.scene],
            zorder=3,
        )
        ratio = "" if t.time_vs_template is None else f" {t.time_vs_template:.2f}×"
        left.annotate(
            f"{t.tier}{ratio}",
            (t.frame_ms, t.flip),
            xytext=(6, -13 if t.tier == "fast" else 4),
            textcoords="offset points",
            fontsize=9,
        )
    if default:
        left.set_xlim(0, 1.15 * max(t.frame_ms for t in default))
        left.set_ylim(-0.005, 1.25 * max(max(t.flip for t in default), 0.02))
    else:
        left.text(
            0.5, 0.5, f"{TEMPLATE_SCENE} scene not measured", ha="center", transform=left.transAxes
        )
    left.set_title(f"{TEMPLATE_SCENE} scene: tiers and the seed template (× its time)")
    left.set_xlabel(f"frame time, ms ({timing})")
    left.set_ylabel("mean FLIP against the reference tier")

    for scene in scenes:
        rows = [t for t in result.tiers if t.scene == scene and t.tier != TEMPLATE_ROW]
        rows.sort(key=lambda t: t.time_vs_reference)
        right.plot(
            [t.time_vs_reference for t in rows],
            [t.flip for t in rows],
            color=colour[scene],
            lw=1,
            label=_label(scene),
        )
        for t in rows:
            right.scatter(
                t.time_vs_reference,
                t.flip,
                marker=_MARKERS.get(t.tier, "x"),
                s=40,
                color=colour[scene],
                zorder=3,
            )
            if t.tier != REFERENCE_TIER:
                right.annotate(
                    _label(f"{scene} {t.tier}"),
                    (t.time_vs_reference, t.flip),
                    xytext=(4, -11 if t.tier == "fast" else 3),
                    textcoords="offset points",
                    fontsize=7,
                    color=colour[scene],
                )
    if any(t.tier == REFERENCE_TIER for t in result.tiers):
        right.annotate(
            "reference (every scene)",
            (1.0, 0.0),
            xytext=(-6, 8),
            textcoords="offset points",
            fontsize=8,
            ha="right",
        )
    right.axvline(1.0 / SCENE_SPEEDUP, color="gray", ls="--", lw=1)
    right.annotate(
        f"fast's goal: {SCENE_SPEEDUP:g}× faster",
        (1.0 / SCENE_SPEEDUP, 1.0),
        xycoords=("data", "axes fraction"),
        xytext=(4, -12),
        textcoords="offset points",
        fontsize=8,
        color="gray",
    )
    ratios = [t.time_vs_reference for t in result.tiers if t.tier != TEMPLATE_ROW]
    right.set_xlim(min([0.5, *ratios]) - 0.02, max([1.1, *ratios]) + 0.15)  # room for labels
    right.set_title("every scene: tiers against their reference")
    right.set_xlabel("frame time × the scene's reference tier")
    right.set_ylabel("mean FLIP against the reference tier")
    right.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), title="scene")
    fig.tight_layout()
    _save_figure(fig, path, dpi=90)
    plt.close(fig)


def _save_figure(fig: Any, path: Path, dpi: int) -> None:
    """A chart as PNG through the one output writer (whole, a regular file or nothing)."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=dpi)
    write_atomic(path, buffer.getvalue())


def write_report(result: BenchResult, folder: Path, charts: bool = True) -> list[Path]:
    """bench.json, bench.md and the charts in `folder`; the paths written."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = [folder / "bench.json", folder / "bench.md"]
    write_atomic(paths[0], to_json(result).encode("utf-8"))
    write_atomic(paths[1], to_markdown(result).encode("utf-8"))
    if charts:
        paths += write_charts(result, folder)
    return paths
