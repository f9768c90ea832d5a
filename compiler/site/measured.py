"""What each variant's page says about its accuracy and cost, all of it measured by glint:

- error against the variant's float64 reference and cost (SPIR-V instructions, ns per call),
  from the bench report `site/docs/bench/bench.json` that `glint bench` writes, with the
  machine it ran on, next to the error budget of the snippet's front matter;
- a plot of the snippet's own GLSL output, run on the GPU over its domain, against the
  reference for a few parameter values, and of the error over the domain with its worst point;
  for a variant measured on sampled rays, points or scenes (shadows, AO, normals, subsurface)
  instead, its output against the reference sample by sample and the spread of its errors;
- whether it survives half precision, from the evaluator run at float16, float32 and float64.

Plots and precision results are cached by a hash of what they depend on (the snippet's code
with its dependencies, its domain, glint's version), so a rebuild computes nothing.
"""

from __future__ import annotations

import hashlib
import io
import json
import logging
import math
from collections.abc import Collection, Iterable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path, PurePosixPath
from typing import Any

import numpy as np

import glint
from glint.compiler.bench.errors import set_errors
from glint.compiler.bench.plans import plan_for
from glint.compiler.bench.samples import ProbeSet, domain_samples, per_axis
from glint.compiler.catalog.loader import Snippet, load_catalog
from glint.compiler.compose.linking.snippet_evaluation import snippet_source
from glint.compiler.evaluator.errors import UnsupportedError
from glint.compiler.files import write_atomic
from glint.compiler.markdown import md_code, md_prose, md_text, path_url, safe_image, table
from glint.compiler.verify.precision import SIMPLE_TYPES, entry_params, precision_report
from glint.compiler.verify.probes import run_probe

log = logging.getLogger(__name__)

BENCH_JSON = PurePosixPath("bench") / "bench.json"  # under the docs source folder
PLOT_DIR = PurePosixPath("img") / "accuracy"
PLOT_VERSION = "3"  # bump when the plot or the precision report changes, to recompute them
SLICES = 3  # curves per plot: the second axis at its ends and middle


@dataclass(frozen=True)
class Bench:
    """The bench report's rows (variants by id, scene tiers by scene and tier) and the
    machine that measured them."""

    machine: str = ""
    variants: dict[str, dict[str, Any]] = field(default_factory=dict)
    tiers: dict[tuple[str, str], dict[str, Any]] = field(default_factory=dict)  # (scene, tier)


@dataclass(frozen=True)
class Accuracy:
    """Everything a variant's page shows under "Accuracy and cost"."""

    measured: dict[str, Any] | None = None  # the bench row
    budget: dict[str, float] = field(default_factory=dict)  # the front matter's error_budget
    precision: dict[str, dict[str, Any]] | None = None  # precision_report, where it runs
    plot: PurePosixPath | None = None  # under the docs folder
    plot_kind: str = ""  # "domain" (over a grid of its inputs) or "samples" (rays and points)
    budget_why: str = ""  # the front matter's reason for the budget


@dataclass
class AccuracyBuild:
    by_id: dict[str, Accuracy] = field(default_factory=dict)
    files: dict[PurePosixPath, bytes] = field(default_factory=dict)
    computed: int = 0  # plots and precision reports computed rather than read from the cache


def load_bench(source: Path) -> Bench:
    """The bench report in the docs source folder; an empty one where there is none yet."""
    path = source / BENCH_JSON
    if not path.is_file():
        return Bench()
    data = json.loads(path.read_text(encoding="utf-8"))
    machine = data.get("machine", {})
    label = str(machine.get("renderer", "")).split(";")[0].strip()
    if machine.get("platform"):
        label = f"{label}, {machine['platform']}" if label else str(machine["platform"])
    variants = {row["id"]: row for row in data.get("variants", [])}
    tiers = {(row["scene"], row["tier"]): row for row in data.get("tiers", [])}
    return Bench(label, variants, tiers)


def variant_accuracy(
    ids: Iterable[str],
    bench: Bench,
    cache_dir: Path | None,
    plots: Collection[str] | None = None,
) -> AccuracyBuild:
    """Each variant's `Accuracy`. Plots and precision are computed only with a cache folder,
    and for the ids in `plots` when given (the tests compute a few)."""
    catalog = load_catalog()
    build = AccuracyBuild()
    for snippet_id in ids:
        snippet = catalog.get(snippet_id)
        accuracy = Accuracy(
            bench.variants.get(snippet_id),
            dict(snippet.error_budget),
            budget_why=snippet.budget_why,
        )
        if cache_dir is not None and (plots is None or snippet_id in plots):
            accuracy = _computed(snippet, accuracy, cache_dir, build)
        build.by_id[snippet_id] = accuracy
    return build


def _computed(
    snippet: Snippet, accuracy: Accuracy, cache_dir: Path, build: AccuracyBuild
) -> Accuracy:
    key = _cache_key(snippet)
    cached = cache_dir / f"accuracy-{key}.json"
    picture = cache_dir / f"accuracy-{key}.png"
    if cached.is_file():
        data = json.loads(cached.read_text(encoding="utf-8"))
    else:
        drawn = _plot(snippet)
        data = {"precision": _precision(snippet), "plot": drawn[1] if drawn else ""}
        cache_dir.mkdir(parents=True, exist_ok=True)
        if drawn is not None:
            write_atomic(picture, drawn[0])
        write_atomic(cached, json.dumps(data, sort_keys=True).encode("utf-8"))
        build.computed += 1
    plot = None
    if data["plot"] and picture.is_file():
        plot = PLOT_DIR / f"{snippet.id}.png"
        build.files[plot] = picture.read_bytes()
    return replace(accuracy, precision=data["precision"], plot=plot, plot_kind=data["plot"])


def _cache_key(snippet: Snippet) -> str:
    try:
        source = snippet_source(snippet.id)[0]
    except glint.InputError:
        source = snippet.body
    parts = [glint.__version__, PLOT_VERSION, snippet.reference, json.dumps(snippet.domain), source]
    return hashlib.sha256("\n".join(parts).encode("utf-8")).hexdigest()[:32]


def _precision(snippet: Snippet) -> dict[str, dict[str, Any]] | None:
    """The evaluator's half/single/double comparison, for entries it can run on plain inputs."""
    try:
        params = entry_params(snippet.id)
    except (ValueError, glint.InputError):
        return None
    if not all(q == "in" and t in SIMPLE_TYPES for q, t, _ in params):
        return None
    try:
        with np.errstate(all="ignore"):
            return precision_report(snippet.id)
    except (UnsupportedError, glint.InputError, ValueError) as error:
        log.info("site: no precision report for %s: %s", snippet.id, error)
        return None


# --- the plot ---------------------------------------------------------------------------


def _domain_set(snippet: Snippet) -> tuple[ProbeSet, list[str], list[np.ndarray]] | None:
    """The variant's probe pass over the grid of its domain, with the grid's axes; None where
    it is measured some other way (scenes, rays, renders) or has no reference."""
    if not snippet.domain or not snippet.reference or {"n0", "n1", "n2"} <= snippet.domain.keys():
        return None
    try:
        plan = plan_for(snippet)
    except glint.InputError:
        return None
    if len(plan.sets) != 1 or plan.sets[0].exact is None or plan.sets[0].metric != "abs":
        return None
    case = plan.sets[0]
    names = list(snippet.domain)
    if set(case.coordinates) != set(names):
        return None
    samples = domain_samples(snippet, per_axis(snippet))
    axes = [np.unique(samples[name]) for name in names]
    if math.prod(len(a) for a in axes) != len(case.exact):
        return None
    return case, names, axes


def _plot(snippet: Snippet) -> tuple[bytes, str] | None:
    """The PNG and its kind: "domain" (`_domain_plot`) for a variant measured on a grid of its
    domain, "samples" (`_sample_plot`) for one measured on rays and points; None where the bench
    measures no error of it."""
    domain = _domain_plot(snippet)
    if domain is not None:
        return domain, "domain"
    samples = _sample_plot(snippet)
    return (samples, "samples") if samples is not None else None


def _domain_plot(snippet: Snippet) -> bytes | None:
    """Two panels: output against reference along the first axis for a few values of the
    second; the error over the first two axes with its worst point."""
    found = _domain_set(snippet)
    if found is None:
        return None
    case, names, axes = found
    try:
        gpu = np.asarray(run_probe(snippet.id, case.inputs), np.float64)
    except glint.InputError as error:
        log.warning("site: no accuracy plot for %s: %s", snippet.id, error)
        return None
    shape = tuple(len(a) for a in axes)
    exact = np.asarray(case.exact, np.float64)
    value = gpu if gpu.ndim == 1 else gpu[:, 0]  # the first channel of a colour
    truth = exact if exact.ndim == 1 else exact[:, 0]
    error = set_errors(case, gpu)
    error = error if error.ndim == 1 else error.max(axis=1)
    value, truth, error = value.reshape(shape), truth.reshape(shape), error.reshape(shape)
    # Along x goes the axis the reference changes most with (cosθ for Fresnel, not f0).
    first = _liveliest_axis(truth)
    order = [first, *(i for i in range(len(axes)) if i != first)]
    return _figure(
        snippet,
        [names[i] for i in order],
        [axes[i] for i in order],
        *(np.transpose(a, order) for a in (value, truth, error)),
    )


@dataclass(frozen=True)
class SampleErrors:
    """A variant run on the bench's sample sets: per sample its error (in `unit`), and, where
    the error is a difference of values (not an angle), its output and the reference's."""

    reference: str
    unit: str
    error: np.ndarray
    value: np.ndarray | None = None
    truth: np.ndarray | None = None


def sample_errors(snippet: Snippet) -> SampleErrors | None:
    """The variant's GLSL run on the GPU over the bench's sample sets (rays and points in its
    reference scenes), as the bench runs it; None where the bench measures no error of it on
    probes (only its cost, or errors taken from a render)."""
    try:
        plan = plan_for(snippet)
    except glint.InputError:
        return None
    cases = [case for case in plan.sets if case.exact is not None]
    if plan.reference is None or not cases:
        return None
    catalog = load_catalog()
    values, truths, errors = [], [], []
    for case in cases:
        try:
            gpu = np.asarray(run_probe(snippet.id, case.inputs, catalog, case.scene_stub))
        except glint.InputError as error:
            log.warning("site: no accuracy plot for %s: %s", snippet.id, error)
            return None
        error = set_errors(case, gpu)
        errors.append(error if error.ndim == 1 else error.max(axis=1))
        if case.metric == "abs":  # a value to set against the reference (not an angle)
            exact = np.asarray(case.exact, np.float64)
            values.append(gpu if gpu.ndim == 1 else gpu[:, 0])
            truths.append(exact if exact.ndim == 1 else exact[:, 0])
    return SampleErrors(
        plan.reference,
        plan.unit,
        np.concatenate(errors),
        np.concatenate(values) if values else None,
        np.concatenate(truths) if truths else None,
    )


def _sample_plot(snippet: Snippet) -> bytes | None:
    """Its output against the reference sample by sample, and the share of samples under
    each error, with the worst."""
    measured = sample_errors(snippet)
    return _sample_figure(snippet, measured) if measured is not None else None


def _sample_figure(snippet: Snippet, measured: SampleErrors) -> bytes:
    value, truth, error, unit = measured.value, measured.truth, measured.error, measured.unit
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(8.0, 3.0), dpi=100, layout="constrained")
    if value is not None and truth is not None:
        left.scatter(truth, value, s=3, alpha=0.3, color="C0", linewidths=0)
        low, high = float(np.nanmin(truth)), float(np.nanmax(truth))
        left.plot([low, high], [low, high], color="k", linestyle="--", linewidth=1,
                  label="equal to the reference")  # fmt: skip
        left.set_xlabel(f"float64 reference ({unit})")
        left.set_ylabel("GLSL (GPU, float32)")
        left.legend(fontsize=7)
    finite = np.sort(np.where(np.isfinite(error), error, np.inf))
    worst = float(finite[-1])
    # Errors a millionth of the worst and below (exact samples among them) sit at the left edge.
    floor = max(worst * 1e-6, 1e-12) if np.isfinite(worst) and worst > 0 else 1e-12
    shown = np.maximum(finite, floor)
    counted = shown[np.isfinite(shown)]
    if (value is None or truth is None) and counted.size:  # an angle: its spread, not values
        bins = np.geomspace(floor, max(float(counted.max()), floor * 10), 40)
        left.hist(counted, bins=bins, color="C0")
        left.set_xscale("log")
        left.set_xlabel(f"|error| ({unit})")
        left.set_ylabel("samples")
    left.set_title(f"{snippet.id} against {measured.reference}, per sample", fontsize=9)
    share = np.arange(1, len(finite) + 1) / len(finite)
    right.plot(shown, share, color="C3")
    right.set_xscale("log")
    right.plot(max(worst, floor), 1.0, "kx", markersize=8)
    right.set_xlabel(f"|error| ({unit}); at most {floor:.2g} at the left edge")
    right.set_ylabel("share of samples at most this")
    right.set_title(f"{len(finite)} samples, worst {worst:.3g} (x)", fontsize=9)
    return figure_png(fig)


def _liveliest_axis(truth: np.ndarray) -> int:
    """The axis along which the values change most, in mean absolute step over their spread."""
    spread = float(np.nanmax(truth) - np.nanmin(truth)) if truth.size else 0.0
    if not np.isfinite(spread) or spread == 0.0 or truth.ndim == 1:
        return 0
    changes = [float(np.nanmean(np.abs(np.diff(truth, axis=i)))) * truth.shape[i]
               for i in range(truth.ndim)]  # fmt: skip
    return int(np.argmax(changes))


def _figure(
    snippet: Snippet,
    names: list[str],
    axes: list[np.ndarray],
    value: np.ndarray,
    truth: np.ndarray,
    error: np.ndarray,
) -> bytes:
    plt = pyplot()
    worst = np.unravel_index(
        int(np.argmax(np.where(np.isfinite(error), error, np.inf))), error.shape
    )
    # Axes beyond the second are held where the error is worst.
    index: list[Any] = [slice(None), slice(None)] + list(worst[2:])
    fig, (left, right) = plt.subplots(1, 2, figsize=(8.0, 3.0), dpi=100, layout="constrained")
    x = axes[0]
    if len(axes) == 1:
        left.plot(x, value, color="C0", label="GLSL (GPU, float32)")
        left.plot(x, truth, color="k", linestyle="--", linewidth=1, label="float64 reference")
    else:
        picks = sorted({0, len(axes[1]) // 2, len(axes[1]) - 1})[:SLICES]
        for colour, j in enumerate(picks):
            at = [*index]
            at[1] = j
            label = f"{names[1]} = {axes[1][j]:.3g}"
            left.plot(x, value[tuple(at)], color=f"C{colour}", label=label)
            left.plot(x, truth[tuple(at)], color="k", linestyle="--", linewidth=1)
        left.plot([], [], color="k", linestyle="--", linewidth=1, label="float64 reference")
    finite = truth[np.isfinite(truth)]
    if finite.size and finite.min() > 0 and finite.max() > 1e3 * finite.min():
        left.set_yscale("log")  # a peak such as GGX's at low roughness
    left.set_xlabel(names[0])
    left.set_title(f"{snippet.id} against {snippet.reference}", fontsize=9)
    left.legend(fontsize=7)
    if len(axes) == 1:
        right.semilogy(x, np.maximum(error, 1e-12), color="C3")
        right.plot(x[worst[0]], max(float(error[worst]), 1e-12), "kx", markersize=8)
        right.set_xlabel(names[0])
        right.set_ylabel("|error|")
    else:
        plane = error[tuple(index)]
        shown = np.log10(np.maximum(np.where(np.isfinite(plane), plane, np.nan), 1e-12))
        mesh = right.pcolormesh(axes[1], x, shown, shading="nearest", cmap="magma")
        fig.colorbar(mesh, ax=right, label="log10 |error|")
        right.plot(axes[1][worst[1]], x[worst[0]], "x", color="cyan", markersize=9, mew=2)
        right.set_xlabel(names[1])
        right.set_ylabel(names[0])
    right.set_title(f"error, worst {float(error[worst]):.3g} (x)", fontsize=9)
    return figure_png(fig)


def pyplot() -> Any:
    """matplotlib's pyplot drawing into files only (Agg), imported when a build draws."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot as plt

    return plt


def figure_png(fig: Any) -> bytes:
    """The figure as PNG bytes, then closed. No software version in the metadata, so the
    same figure gives the same bytes and a rebuild rewrites no file."""
    out = io.BytesIO()
    fig.savefig(out, format="png", metadata={"Software": None})
    pyplot().close(fig)
    return out.getvalue()


# --- the page section -----------------------------------------------------------------------


def accuracy_section(snippet_id: str, accuracy: Accuracy | None, machine: str) -> str:
    """The variant page's "Accuracy and cost" section (Markdown); "" where nothing is known."""
    if accuracy is None or (accuracy.measured is None and accuracy.precision is None):
        return ""
    parts = ["## Accuracy and cost\n\n"]
    row = accuracy.measured
    if row is not None:
        parts.append(_measured_table(row, accuracy.budget, machine))
        if accuracy.budget and accuracy.budget_why:
            parts.append(f"\nWhy the budget is what it is: {md_prose(accuracy.budget_why)}\n")
    if accuracy.plot is not None and accuracy.plot_kind == "samples":
        alt = f"{snippet_id}: its GLSL against the float64 reference, sample by sample, and "
        alt += "the spread of its errors"
        parts.append(
            f"\n{safe_image(md_text(alt), path_url(accuracy.plot, '../'))}\n\n"
            "Measured on the bench's samples (rays and points in its reference scenes) rather "
            "than a grid of inputs. Left: the snippet's own GLSL, run on the GPU in float32, "
            "against its float64 reference for each sample (on the dashed line where they "
            "agree); for an angle, how many samples have each error. Right: the share of "
            "samples within each error; the cross marks the worst.\n"
        )
    elif accuracy.plot is not None:
        alt = f"{snippet_id}: its GLSL against the float64 reference, and the error over "
        alt += "its domain"
        parts.append(
            f"\n{safe_image(md_text(alt), path_url(accuracy.plot, '../'))}\n\n"
            "Left: the snippet's own GLSL, run on the GPU in float32 (solid), against its "
            "float64 reference (dashed). Right: the error over the domain; the cross marks the "
            "worst point.\n"
        )
    if accuracy.precision is not None:
        parts.append("\n" + _precision_text(accuracy.precision))
    return "".join(parts) + "\n"


def _measured_table(row: dict[str, Any], budget: Mapping[str, float], machine: str) -> str:
    unit = "" if row.get("error_unit") == "value" else row.get("error_unit") or ""
    rows: list[list[str]] = []
    if row.get("reference"):
        rows.append(["reference", md_code(str(row["reference"])), ""])
        for key, label in (("max_abs", "max error"), ("rms", "RMS error"),
                           ("max_rel", "max relative error")):  # fmt: skip
            value = row.get(key)
            if value is None:
                continue
            shown = f"{value:.3g}" + (f" ({md_text(unit)})" if unit and key != "max_rel" else "")
            rows.append([label, shown, _budget(budget.get(key))])
            if key == "rms" and row.get("rel_rms") is not None:
                shown = f"{row['rel_rms']:.3g}"
                rows.append(["RMS error / the reference's RMS", shown, ""])
        if row.get("worst_at"):
            where = ", ".join(f"{k} = {v:.4g}" for k, v in row["worst_at"].items())
            rows.append(["worst at", md_text(where), ""])
        rows.append(["samples", md_text(str(row.get("samples", ""))), ""])
    rows.append(["SPIR-V instructions", md_text(str(row["spirv"])), ""])
    rows.append(["time per call", time_per_call(row["gpu_ns"]), ""])
    front = "yes" if row.get("pareto") else "no"
    rows.append(["on its slot's cost/error front", front, ""])
    note = f"Measured by `glint bench` on {md_text(machine)}." if machine else ""
    return table(["", "measured", "budget"], rows) + (f"\n{note}\n" if note else "")


def time_per_call(ns: float, unit: bool = True) -> str:
    """A measured time per call as the pages show it. The bench clamps to 0 a variant that
    costs no more than its probe's empty loop: that is below what it resolves, not free."""
    if ns <= 0.0:
        return "≈ 0, within the timing noise" if unit else "≈ 0"
    return f"{ns:.2f} ns" if unit else f"{ns:.2f}"


def _budget(value: float | None) -> str:
    return "" if value is None else f"≤ {value:.3g}"


# The relative error in float16 that a variant may have and still be said to hold there: an 8-bit
# display step is 0.4 % of white and 0.8 % of mid-grey, so 1 % is about where it starts to show.
HALF_ACCURATE = 0.01


def _where_half_fails(half: Mapping[str, Any]) -> str:
    """Where and why float16 fails, from the precision report: the inputs' spans over the
    failing samples, and how many of those hold a value float16 cannot (|x| > 65504)."""
    where = half.get("nonfinite_where")
    if where is None:
        return ""  # a report from before glint said where
    spans = ", ".join(
        f"{name} = {low:.3g}" if low == high else f"{name} {low:.3g} to {high:.3g}"
        for name, (low, high) in where.items()
    )
    text = f", at {md_text(spans)}" if spans else ""
    failing = int(half.get("nonfinite_lanes", 0))
    beyond = int(half.get("nonfinite_beyond_range", 0))
    if beyond == failing:
        return (
            f"{text}. There the true value itself is beyond float16's largest finite number "
            "(65504): no float16 code can hold it, only clamp it (as Filament's "
            "`saturateMediump` clamps to 65504)"
        )
    if beyond:
        return (
            f"{text}. In {beyond} of them the true value is beyond float16's largest finite "
            f"number (65504), which only a clamp can survive; in the other {failing - beyond} "
            "an intermediate step overflows or underflows float16"
        )
    return f"{text}. The true values fit float16: an intermediate step overflows or underflows"


def _precision_text(report: Mapping[str, Mapping[str, Any]]) -> str:
    half, single = report.get("float16", {}), report.get("float32", {})
    error = half.get("max_rel_err_vs_f64")
    if half.get("finite") and error is not None and error <= HALF_ACCURATE:
        survives = (
            f"Half precision: it holds in float16 (mediump): finite wherever float64 is, and "
            f"within {error:.3g} of it (relative)"
        )
    elif half.get("finite"):
        shown = "unknown" if error is None else f"{error:.3g}"
        survives = (
            f"Half precision: in float16 (mediump) it stays finite wherever float64 is, but "
            f"is not accurate: its largest relative error is {shown}, over the "
            f"{HALF_ACCURATE:.0%} a shading term can lose before 8-bit output shows it"
        )
    else:
        survives = (
            f"Half precision: it does **not** survive float16 (mediump): "
            f"{md_text(str(half.get('nonfinite_lanes', 0)))} sample(s) turn infinite or NaN "
            f"where float64 is finite{_where_half_fails(half)}"
        )
    single_err = single.get("max_rel_err_vs_f64")
    tail = f"; float32 is within {single_err:.3g} of float64" if single_err is not None else ""
    return (
        f"{survives}{tail} (glint's evaluator on a grid over the domain, "
        "the same code at each precision).\n"
    )
