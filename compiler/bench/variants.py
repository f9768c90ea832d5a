"""Per variant of each slot: its error against its float64 reference and what it costs.

- Error: the variant's own GLSL run on the GPU over the passes of `plans.plan_for`, compared
  with ground truth there (max |error|, RMS, max relative error, where the error is worst).
- Static cost: SPIR-V instructions of its probe shader after `spirv-opt -O`. Deterministic; it
  includes the probe's own texel fetches and output, the same for every variant of a slot.
- Measured cost: the median draw of its probe pass over a fixed 256 x 256 grid, each pixel
  calling it TIMED_CALLS times on inputs a little apart, minus that of an empty pass with the
  same loop and as many input textures, in ns per call. The loop resolves short functions that
  one call per pixel hid under the cost of fetching their inputs (46 of 71 variants measured
  0.00 ns that way). On llvmpipe this is CPU time.

The front of a slot (`mark_pareto`) is what the planner's tiers should choose from.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from glint.compiler.bench.errors import set_errors, summarize
from glint.compiler.bench.plans import Plan, plan_for
from glint.compiler.catalog.loader import Catalog, Snippet, load_catalog
from glint.compiler.catalog.slots import SLOTS
from glint.compiler.errors import InputError
from glint.compiler.target.glslang import spirv_instruction_count
from glint.compiler.verify.probes import (
    TIMED_CALLS,
    entry_function,
    probe_channels,
    probe_inputs,
    probe_shader,
    run_empty_probe,
    run_probe_timed,
)

CPU_RENDERERS = ("llvmpipe", "softpipe", "swrast", "lavapipe")
EMPTY_PASSES = 3


@dataclass
class VariantMeasure:
    id: str  # "D.ggx"
    slot: str
    reference: str | None  # the float64 reference compared against; None where there is none
    error_unit: str  # "value", "degrees", "visibility", "transmittance"; "" without a reference
    max_abs: float | None
    rms: float | None
    max_rel: float | None  # None where a relative error means nothing (values that reach 0)
    worst_at: dict[str, float] | None  # the inputs where |error| is largest
    samples: int  # how many points the error was measured on (0 without a reference)
    spirv: int  # SPIR-V instructions after spirv-opt -O
    gpu_ns: float  # median ns per call, the empty loop subtracted, at least 0
    pareto: bool = False  # on the cost/error front of its slot and reference
    rel_rms: float | None = None  # RMS error over the reference's RMS; None where max_rel is


def is_cpu_renderer(renderer: str) -> bool:
    """Whether the GL renderer is a software one, whose timings are CPU time."""
    return any(name in renderer.lower() for name in CPU_RENDERERS)


def measurable_ids(catalog: Catalog) -> list[str]:
    """Every variant of every one-variant slot with an entry function, in slot order."""
    order = {name: index for index, name in enumerate(SLOTS)}
    chosen = [s for s in catalog.snippets.values() if _measurable(s)]
    return [s.id for s in sorted(chosen, key=lambda s: (order[s.slot], s.id))]


def _measurable(snippet: Snippet) -> bool:
    slot = SLOTS[snippet.slot]
    return not slot.many and slot.entry is not None


class _EmptyPasses:
    """Seconds of the empty pass per number of input textures, measured once per run (fetching
    a texture costs about as much as a short function, so the count must match). It is the
    median of EMPTY_PASSES passes, each its draws' median: the baseline of every variant that
    reads as many textures, so one pass slowed by other work on the machine must not skew it."""

    def __init__(self, repeats: int) -> None:
        self.repeats = repeats
        self.seconds: dict[int, float] = {}

    def __call__(self, channels: int) -> float:
        if channels not in self.seconds:
            passes = [
                run_empty_probe(channels, self.repeats, calls=TIMED_CALLS)
                for _ in range(EMPTY_PASSES)
            ]
            self.seconds[channels] = float(np.median([p.median_draw() for p in passes]))
        return self.seconds[channels]


def _static_cost(snippet: Snippet, catalog: Catalog, plan: Plan) -> int:
    # The probe shader over the default scene stub: the same `map` for every scene variant.
    source = probe_shader(snippet, catalog, out_params=plan.out_params)[0]
    count = spirv_instruction_count(source)
    if count is None:
        raise InputError(f"{snippet.id}: its probe shader does not compile to SPIR-V")
    return count


def measure_variant(
    snippet: Snippet, catalog: Catalog, repeats: int, empty: Callable[[int], float]
) -> tuple[VariantMeasure, str]:
    """One variant's measure and the renderer that drew it; `empty(channels)` gives the
    seconds of the empty pass to subtract."""
    plan = plan_for(snippet)
    names = probe_inputs(entry_function(snippet), plan.out_params)[0]
    baseline = empty(probe_channels(names))
    errors, where, exact, ns = [], [], [], []
    renderer = ""
    # Scene variants run one pass per reference scene: their cost is the mean over the scenes.
    for case in plan.sets:
        run = run_probe_timed(
            snippet.id,
            case.inputs,
            catalog,
            case.scene_stub,
            repeats=repeats,
            out_params=plan.out_params,
            calls=TIMED_CALLS,
        )
        renderer = run.renderer
        ns.append((run.median_draw() - baseline) / run.evaluations * 1e9)
        if case.exact is not None:
            errors.append(set_errors(case, run.values))
            where.append(case.coordinates)
            exact.append(case.exact)
    if plan.rendered is not None:
        rendered, rendered_where = plan.rendered(catalog)
        errors.append(rendered)
        where.append(rendered_where)
    summary = summarize(errors, where, exact if plan.relative else None) if errors else None
    measure = VariantMeasure(
        id=snippet.id,
        slot=snippet.slot,
        reference=plan.reference if summary else None,
        error_unit=plan.unit if summary else "",
        max_abs=summary.max_abs if summary else None,
        rms=summary.rms if summary else None,
        max_rel=summary.max_rel if summary else None,
        rel_rms=summary.rel_rms if summary else None,
        worst_at=summary.worst_at if summary else None,
        samples=summary.samples if summary else 0,
        spirv=_static_cost(snippet, catalog, plan),
        # A trivial variant costs less than timing noise, and can come out slightly below
        # the empty pass: it is clamped to 0 (cheaper than we can measure).
        gpu_ns=max(0.0, float(np.mean(ns))),
    )
    return measure, renderer


def measure_variants(
    catalog: Catalog | None = None,
    ids: list[str] | None = None,
    repeats: int = 7,
    progress: Callable[[str], None] | None = None,
) -> tuple[list[VariantMeasure], str]:
    """Measure the variants `ids` (by default every measurable one, see `measurable_ids`) and
    mark their fronts. Returns the measures, in slot order, and the renderer label (GL_RENDERER
    and version; `is_cpu_renderer` tells whether its timings are CPU time). `progress(id)` is
    called as each variant is done. Passes run one at a time, so that timings do not compete."""
    catalog = catalog or load_catalog()
    chosen = measurable_ids(catalog) if ids is None else ids
    for snippet_id in chosen:
        if not _measurable(catalog.get(snippet_id)):
            raise InputError(f"{snippet_id}: a library variant or a slot without an entry")
    empty = _EmptyPasses(repeats)
    measures, renderer = [], ""
    for snippet_id in chosen:
        measure, renderer = measure_variant(catalog.get(snippet_id), catalog, repeats, empty)
        measures.append(measure)
        if progress is not None:
            progress(snippet_id)
    mark_pareto(measures)
    return measures, renderer


def _cost(measure: VariantMeasure) -> tuple[float, int]:
    return measure.gpu_ns, measure.spirv


def _dominates(a: VariantMeasure, b: VariantMeasure) -> bool:
    assert a.rms is not None and b.rms is not None
    no_worse = _cost(a) <= _cost(b) and a.rms <= b.rms
    return no_worse and (_cost(a) < _cost(b) or a.rms < b.rms)


def mark_pareto(measures: list[VariantMeasure]) -> None:
    """Set `pareto` on the variants that no other of the same slot and reference dominates:
    none is at most as costly and at most as wrong (RMS) with one of the two strictly better.

    Cost compares measured time first and SPIR-V instructions only where the times are equal
    (lexicographically): the time is what the user pays, and it is equal mostly where both
    variants were clamped to 0, below what can be measured, where the instruction count is the
    better guide. Variants without a reference have no error, so they are on no front. Two
    variants alike in cost and error are both on it."""
    groups: dict[tuple[str, str], list[VariantMeasure]] = {}
    for measure in measures:
        measure.pareto = False
        if measure.reference is not None and measure.rms is not None:
            groups.setdefault((measure.slot, measure.reference), []).append(measure)
    for group in groups.values():
        for measure in group:
            measure.pareto = not any(_dominates(other, measure) for other in group)
