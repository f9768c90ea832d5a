"""The variant benchmark: errors against the references, static and measured cost, the front.

No timed assertions: timings on a shared machine say nothing reliable in a test; only that the
measured cost is a number, at least 0.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from glint.compiler.bench.errors import summarize
from glint.compiler.bench.plans import SHADOW_LIGHT
from glint.compiler.bench.samples import free_inputs
from glint.compiler.bench.variants import (
    VariantMeasure,
    is_cpu_renderer,
    mark_pareto,
    measurable_ids,
    measure_variants,
)
from glint.compiler.catalog.loader import load_catalog
from glint.compiler.errors import InputError
from glint.compiler.verify.probes import run_empty_probe, run_probe, run_probe_timed

CATALOG = load_catalog()
MEASURED = ["F.schlick", "F.dielectric", "D.ggx", "shadow.hard", "shadow.soft", "tonemap.none"]
WITH_DOMAIN = ["F.schlick", "F.dielectric", "D.ggx"]


@pytest.fixture(scope="module")
def measured() -> tuple[dict[str, VariantMeasure], str]:
    done: list[str] = []
    measures, renderer = measure_variants(CATALOG, MEASURED, repeats=3, progress=done.append)
    assert done == MEASURED  # one call per variant, as each is finished
    return {m.id: m for m in measures}, renderer


@pytest.mark.render
def test_exact_fresnel_is_far_closer_than_schlick(measured) -> None:
    by_id, _ = measured
    exact, schlick = by_id["F.dielectric"], by_id["F.schlick"]
    assert exact.reference == schlick.reference == "F_dielectric"
    assert exact.rms is not None and schlick.rms is not None
    assert exact.rms < schlick.rms / 1000
    assert 0.05 < schlick.max_abs < 0.1  # Schlick is off by ~0.09 near grazing angles


@pytest.mark.render
def test_errors_are_finite_and_not_negative(measured) -> None:
    by_id, _ = measured
    for measure in by_id.values():
        if measure.reference is None:
            continue
        values = [measure.max_abs, measure.rms] + ([measure.max_rel] if measure.max_rel else [])
        assert all(v is not None and math.isfinite(v) and v >= 0 for v in values), measure
        assert measure.rms <= measure.max_abs
        assert measure.samples > 0


@pytest.mark.render
def test_costs_are_counted_and_the_static_count_repeats(measured) -> None:
    by_id, _ = measured
    again, _ = measure_variants(CATALOG, ["F.schlick", "shadow.hard"], repeats=2)
    for measure in again:
        first = by_id[measure.id]
        assert measure.spirv == first.spirv > 0
        # Same inputs, same numbers: the errors are deterministic too.
        assert (measure.max_abs, measure.rms, measure.worst_at) == (
            first.max_abs,
            first.rms,
            first.worst_at,
        )
    assert all(m.gpu_ns >= 0.0 and m.spirv > 0 for m in by_id.values())


@pytest.mark.render
def test_worst_error_lies_inside_the_domain(measured) -> None:
    by_id, _ = measured
    for snippet_id in WITH_DOMAIN:
        worst = by_id[snippet_id].worst_at
        domain = CATALOG.get(snippet_id).domain
        assert worst is not None and worst.keys() == domain.keys()
        for key, value in worst.items():
            # The samples are the float32 values the GPU received: 0.2 is 0.2000000030 there.
            lo, hi = (float(np.float32(end)) for end in domain[key])
            assert lo <= value <= hi, (snippet_id, key, value)


@pytest.mark.render
def test_every_shadow_is_held_to_the_disc_light(measured) -> None:
    # The hard shadow's own reference is a single ray; here it meets the same light as the
    # soft ones, so that a front of the slot compares what a viewer sees.
    by_id, _ = measured
    for snippet_id in ("shadow.hard", "shadow.soft"):
        measure = by_id[snippet_id]
        assert measure.reference == SHADOW_LIGHT and measure.error_unit == "visibility"
        assert measure.max_rel is None  # visibility reaches 0: no relative error
        assert measure.worst_at is not None and {"ro0", "rd0"} <= measure.worst_at.keys()
    assert by_id["shadow.hard"].max_abs > 0.3  # a hard edge against a penumbra


@pytest.mark.render
def test_a_variant_without_reference_has_costs_only(measured) -> None:
    by_id, renderer = measured
    none = by_id["tonemap.none"]
    assert none.reference is None and none.error_unit == ""
    assert (none.max_abs, none.rms, none.max_rel, none.worst_at) == (None, None, None, None)
    assert none.samples == 0 and none.spirv > 0 and none.gpu_ns >= 0.0
    assert not none.pareto
    assert renderer  # the device is named


@pytest.mark.render
def test_library_variants_are_not_measured() -> None:
    with pytest.raises(InputError, match="library"):
        measure_variants(CATALOG, ["sdf.sphere"])


def test_measurable_ids_skip_the_libraries_and_keep_the_camera() -> None:
    ids = measurable_ids(CATALOG)
    assert {"camera.orbit", "D.ggx", "shadow.soft_12"} <= set(ids)
    assert not {i.split(".")[0] for i in ids} & {"core", "sdf", "pattern", "light"}


def test_cpu_renderers_are_named_as_such() -> None:
    assert is_cpu_renderer("llvmpipe (LLVM 15.0.6, 256 bits) (OpenGL 4.5 (Core Profile) Mesa)")
    assert is_cpu_renderer("softpipe (OpenGL 3.3)")
    assert not is_cpu_renderer("NVIDIA GeForce RTX 4090/PCIe/SSE2 (OpenGL 4.6.0 NVIDIA 550)")


# --- the front ------------------------------------------------------------------------------


def _m(id_: str, gpu_ns: float, spirv: int, rms: float | None, reference: str | None = "R"):
    slot = id_.split(".")[0]
    return VariantMeasure(
        id_, slot, reference, "value", rms, rms, None, None, 10, spirv, gpu_ns, pareto=True
    )


def test_pareto_front_per_slot_and_reference() -> None:
    measures = [
        _m("D.cheap", 1.0, 10, 0.10),
        _m("D.cheap_twin", 1.0, 10, 0.10),  # identical to D.cheap: neither dominates
        _m("D.exact", 2.0, 10, 0.05),
        _m("D.exact_bigger", 2.0, 12, 0.05),  # same time and error, more code: dominated
        _m("D.worse", 3.0, 5, 0.20),  # slower and worse than D.cheap (spirv only breaks ties)
        _m("D.slow_exact", 5.0, 50, 0.0),  # the most accurate: on the front however slow
        _m("D.other", 10.0, 99, 1.0, reference="R2"),  # alone in its reference group
        _m("F.worse", 3.0, 5, 0.20),  # same numbers as D.worse, but another slot
        _m("D.none", 0.0, 1, None, reference=None),  # no error: on no front
    ]
    mark_pareto(measures)
    front = {m.id for m in measures if m.pareto}
    assert front == {"D.cheap", "D.cheap_twin", "D.exact", "D.slow_exact", "D.other", "F.worse"}


def test_pareto_breaks_equal_times_by_instruction_count() -> None:
    # Two trivial variants both clamped to 0 ns: the smaller shader wins at equal error,
    # and the larger one stays on the front only where it is more accurate.
    small, large = _m("F.small", 0.0, 40, 0.1), _m("F.large", 0.0, 60, 0.1)
    mark_pareto([small, large])
    assert (small.pareto, large.pareto) == (True, False)
    accurate = replace(large, rms=0.01)
    mark_pareto([small, accurate])
    assert (small.pareto, accurate.pareto) == (True, True)


# --- the pieces ---------------------------------------------------------------------------------


def test_summary_pools_passes_and_finds_the_worst_sample() -> None:
    first = np.array([0.1, 0.2])
    second = np.array([[0.0, 0.3, 0.1], [0.05, 0.05, 0.05]])  # an RGB pass: rows are samples
    where = [{"x": np.array([1.0, 2.0])}, {"x": np.array([3.0, 4.0])}]
    exact = [np.array([1.0, 0.0]), np.array([0.5, 1e-9])]
    summary = summarize([first, second], where, exact)
    assert summary.max_abs == pytest.approx(0.3) and summary.worst_at == {"x": 3.0}
    assert summary.samples == 4
    squares = [0.01, 0.04, 0.0, 0.09, 0.01, 0.0025, 0.0025, 0.0025]
    assert summary.rms == pytest.approx(math.sqrt(np.mean(squares)))
    # 0 and 1e-9 are not significant values to divide by: 0.3 / 0.5 is the largest left.
    assert summary.max_rel == pytest.approx(0.6)
    assert summarize([first], where[:1]).max_rel is None
    # the RMS error over the reference's own RMS, the scalar reference counted per channel
    reference_squares = [1.0, 0.0, 0.25, 0.25, 0.25, 1e-18, 1e-18, 1e-18]
    expected = math.sqrt(np.mean(squares)) / math.sqrt(np.mean(reference_squares))
    assert summary.rel_rms == pytest.approx(expected)
    assert summarize([first], where[:1]).rel_rms is None
    # the same error on values ten times larger is ten times smaller relatively
    scaled = summarize([first], where[:1], [np.array([10.0, 10.0])])
    assert scaled.rel_rms == pytest.approx(summarize([first], where[:1], [np.ones(2)]).rel_rms / 10)


@pytest.mark.render
def test_timed_probe_gives_run_probe_values_over_the_full_grid() -> None:
    inputs = {"NoH": np.linspace(0.0, 1.0, 1000), "a": np.full(1000, 0.3)}
    timed = run_probe_timed("D.ggx", inputs, CATALOG, repeats=3)
    np.testing.assert_array_equal(timed.values, run_probe("D.ggx", inputs, CATALOG))
    assert timed.evaluations == 256 * 256 and len(timed.draw_times) == 3
    empty = run_empty_probe(1, repeats=2)
    assert empty.evaluations == timed.evaluations and empty.median_draw() > 0.0
    # many calls per pixel: the values are still one call's, the evaluations count every call
    looped = run_probe_timed("D.ggx", inputs, CATALOG, repeats=3, calls=8)
    np.testing.assert_array_equal(looped.values, timed.values)
    assert looped.evaluations == 8 * 256 * 256
    assert run_empty_probe(1, repeats=2, calls=8).evaluations == looped.evaluations


@pytest.mark.render
def test_an_entry_with_out_parameters_is_timed_through_them() -> None:
    # cameraRay returns ro and rd; the cost probe writes their sum, so neither is dropped.
    inputs = free_inputs(["fragCoord0", "fragCoord1"], count=64)
    timed = run_probe_timed("camera.lookat", inputs, CATALOG, repeats=2, out_params=True)
    assert timed.values.shape == (64, 3) and np.isfinite(timed.values).all()
    rd = timed.values - np.array([0.0, 1.0, 4.0])  # ro is CAMERA_POSITION's default
    np.testing.assert_allclose(np.linalg.norm(rd, axis=1), 1.0, atol=1e-5)
