"""Each variant's own GLSL, run on the GPU, against its float64 reference: within the error
budget of its front matter over its domain, and finite and non-negative at the extremes."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from glint.compiler.bench.errors import set_errors, summarize
from glint.compiler.bench.samples import (
    LOBE_SLOTS,
    base_name,
    domain_set,
    lobe_inputs,
    scalar_names,
)
from glint.compiler.catalog.loader import Snippet, load_catalog
from glint.compiler.verify.probes import run_probe

pytestmark = pytest.mark.render

CATALOG = load_catalog()
# Slots whose entry is a function of its arguments alone; those that query the scene's distance
# field (AO, shadows, normals, subsurface) are held to ground truth on reference scenes elsewhere.
SCENE_SLOTS = {"ao", "shadow", "normal", "sss"}
WITH_REFERENCE = sorted(
    s.id for s in CATALOG.snippets.values() if s.reference and s.slot not in SCENE_SLOTS
)
BRDF_TERMS = sorted(
    s.id for s in CATALOG.snippets.values() if s.slot in {"D", "F", "V"} | LOBE_SLOTS
)

# Values at which lighting code breaks: cosines at and just beyond their ends, roughness 0, the
# smallest roughness anyone clamps to, and 1; F0 of nothing and of a perfect mirror.
COSINE_EXTREMES = [-1.0, -1e-7, 0.0, 1e-7, 0.5, 1.0, 1.0 + 1e-6]
ROUGHNESS_EXTREMES = [0.0, 0.002, 0.045, 0.5, 1.0]
F0_EXTREMES = [0.0, 0.04, 1.0]


@pytest.mark.parametrize("snippet_id", WITH_REFERENCE)
def test_variant_within_its_error_budget(snippet_id: str) -> None:
    # The samples and the reference values are the benchmark's (bench/samples.py): a grid over
    # the domain, float32-rounded on the way to the GPU and to the reference alike.
    snippet = CATALOG.snippets[snippet_id]
    case = domain_set(snippet)
    gpu = run_probe(snippet.id, case.inputs, CATALOG)
    assert np.isfinite(gpu).all()
    assert case.exact is not None
    error = summarize([set_errors(case, gpu)], [case.coordinates], [case.exact])
    budget = snippet.error_budget
    assert error.max_abs <= budget["max_abs"], f"max abs {error.max_abs:.3g} at {error.worst_at}"
    if "max_rel" in budget:
        assert error.max_rel is not None and error.max_rel <= budget["max_rel"], (
            f"max rel {error.max_rel:.3g}"
        )
    if "rms" in budget:  # an approximation by design: its typical error, not only its worst
        assert error.rms <= budget["rms"], f"RMS {error.rms:.3g}"


def extreme_axes(name: str) -> list[float]:
    key = base_name(name)
    if key == "a":
        return ROUGHNESS_EXTREMES
    if key == "f0":
        return F0_EXTREMES
    return COSINE_EXTREMES


def extreme_inputs(snippet: Snippet) -> tuple[list[str], np.ndarray, dict[str, np.ndarray]]:
    """Every combination of extreme values: the axis names, the rows, and the probe inputs."""
    names = scalar_names(snippet)
    if snippet.slot in LOBE_SLOTS:
        # N·V as makeSurface clamps it; N·L = −N·V with φ = π puts L at −V, where H is 0.
        keys = ["NoL", "NoV", "phi", "roughness"]
        axes = [
            COSINE_EXTREMES + [-0.5],
            [1e-4, 0.5, 1.0],
            [0.0, np.pi / 2, np.pi],
            [r**0.5 for r in ROUGHNESS_EXTREMES],
        ]
        table = np.array(list(itertools.product(*axes)), dtype=np.float64)
        base = lobe_inputs({k: table[:, i] for i, k in enumerate(keys)})
        return keys, table, {name: base[base_name(name)] for name in names}
    # Vector components share one value so that the product of axes stays small.
    keys = list(dict.fromkeys(base_name(n) for n in names))
    table = np.array(list(itertools.product(*(extreme_axes(k) for k in keys))), np.float64)
    return keys, table, {name: table[:, keys.index(base_name(name))] for name in names}


@pytest.mark.parametrize("snippet_id", BRDF_TERMS)
def test_finite_and_non_negative_at_the_extremes(snippet_id: str) -> None:
    snippet = CATALOG.snippets[snippet_id]
    keys, table, inputs = extreme_inputs(snippet)
    values = run_probe(snippet.id, inputs, CATALOG)
    bad = ~np.isfinite(values) | (values < 0)
    if values.ndim == 2:
        bad = bad.any(axis=1)
    example = dict(zip(keys, table[int(np.argmax(bad))], strict=True))
    assert not bad.any(), f"{bad.sum()} bad outputs, e.g. at {example}"
