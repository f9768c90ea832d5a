"""Each variant's own GLSL, run on the GPU, against its float64 reference: within the error
budget of its front matter over its domain, and finite and non-negative at the extremes."""

from __future__ import annotations

import inspect
import itertools

import numpy as np
import pytest

from glint.compiler.catalog import Snippet, load_catalog
from glint.compiler.probes import entry_function, probe_inputs, run_probe
from glint.compiler.references import reference
from glint.compiler.references.geometry import dots

pytestmark = pytest.mark.render

CATALOG = load_catalog()
# Slots whose entry is a function of its arguments alone; those that query the scene's distance
# field (AO, shadows, normals, subsurface) are held to ground truth on reference scenes elsewhere.
SCENE_SLOTS = {"ao", "shadow", "normal", "sss"}
WITH_REFERENCE = sorted(
    s.id for s in CATALOG.snippets.values() if s.reference and s.slot not in SCENE_SLOTS
)
# The lobes take a Surface and Dots; their domains are the geometry (NoL signed, NoV, phi) and
# the roughness, from which the probe's Dots are derived as `lightDots` derives them.
LOBE_SLOTS = {"diffuse", "specular"}
BRDF_TERMS = sorted(
    s.id for s in CATALOG.snippets.values() if s.slot in {"D", "F", "V"} | LOBE_SLOTS
)

# Values at which lighting code breaks: cosines at and just beyond their ends, roughness 0, the
# smallest roughness anyone clamps to, and 1; F0 of nothing and of a perfect mirror.
COSINE_EXTREMES = [-1.0, -1e-7, 0.0, 1e-7, 0.5, 1.0, 1.0 + 1e-6]
ROUGHNESS_EXTREMES = [0.0, 0.002, 0.045, 0.5, 1.0]
F0_EXTREMES = [0.0, 0.04, 1.0]
# Dots fields a variant's domain does not name get a plausible fixed value.
DOTS_DEFAULTS = {"NoL": 0.5, "NoV": 0.5, "NoH": 1.0, "VoH": 1.0, "LoV": 0.0, "NoLsigned": 0.5}


def scalar_names(snippet: Snippet) -> list[str]:
    return probe_inputs(entry_function(snippet))[0]


def base_name(name: str) -> str:
    """'d.NoL' -> 'NoL'; 'f01' -> 'f0', 'F2' -> 'F' (vector components); others as they are."""
    name = name.split(".")[-1]
    for vector in ("f0", "F"):
        if name.startswith(vector) and name[len(vector) :].isdigit():
            return vector
    return name


def lobe_inputs(geometry: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """Base-named probe values of a lobe from its geometry: the Dots, the roughness, F = 1."""
    values = dict(dots(geometry["NoL"], geometry["NoV"], geometry.get("phi", 0.0)))
    count = len(values["NoL"])
    values["roughness"] = np.broadcast_to(geometry.get("roughness", 0.5), (count,))
    values["F"] = np.ones(count)
    return values


def grid(axes: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    mesh = np.meshgrid(*axes.values(), indexing="ij")
    return {key: values.ravel() for key, values in zip(axes, mesh, strict=True)}


def domain_samples(snippet: Snippet, per_axis: int) -> dict[str, np.ndarray]:
    """Base-named float64 inputs: a grid over the domain, with points just inside its ends."""
    axes = {}
    for key, (lo, hi) in snippet.domain.items():
        inner = np.linspace(lo, hi, per_axis)
        axes[key] = np.unique(np.concatenate([inner, [lo + 1e-7, hi - 1e-7]]).clip(lo, hi))
    return grid(axes)


def unit_directions(samples: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """A unit-vector input (`n` of irradiance: n0, n1, n2 in the domain) is the grid over the
    cube pushed onto the sphere, without its centre: the entry takes directions, not points."""
    if not {"n0", "n1", "n2"} <= samples.keys():
        return samples
    n = np.stack([samples["n0"], samples["n1"], samples["n2"]], -1)
    length = np.linalg.norm(n, axis=-1)
    keep = length > 1e-3
    n = n[keep] / length[keep, None]
    rest = {key: values[keep] for key, values in samples.items()}
    return rest | {"n0": n[:, 0], "n1": n[:, 1], "n2": n[:, 2]}


def probe_values(snippet: Snippet, base: dict[str, np.ndarray]) -> np.ndarray:
    if snippet.slot in LOBE_SLOTS:
        base = lobe_inputs(base)
    count = len(next(iter(base.values())))
    inputs = {}
    for name in scalar_names(snippet):
        key = base_name(name)
        value = base.get(key, DOTS_DEFAULTS.get(key, 0.0))
        inputs[name] = np.broadcast_to(value, (count,))
    return run_probe(snippet.id, inputs, CATALOG)


def reference_values(snippet: Snippet, base: dict[str, np.ndarray]) -> np.ndarray:
    args = dict(base)
    if snippet.slot == "V":
        args = {key: base.get(key, DOTS_DEFAULTS[key]) for key in DOTS_DEFAULTS}
        args["a"] = base.get("a", 0.5)
    # A reference may take the snippet's own parameters by name: it gets their defaults.
    accepted = inspect.signature(reference(snippet.reference)).parameters
    args |= {name: p.default for name, p in snippet.params.items() if name in accepted}
    result = np.asarray(reference(snippet.reference)(**args), dtype=np.float64)
    return result


@pytest.mark.parametrize("snippet_id", WITH_REFERENCE)
def test_variant_within_its_error_budget(snippet_id: str) -> None:
    snippet = CATALOG.snippets[snippet_id]
    per_axis = 48 if len(snippet.domain) <= 2 else 20 if len(snippet.domain) == 3 else 10
    # The GPU receives float32 inputs; the reference gets the same values, so that what is
    # measured is the snippet's arithmetic, not how 0.9999999 rounds on the way in.
    samples = unit_directions(domain_samples(snippet, per_axis))
    base = {k: v.astype(np.float32).astype(np.float64) for k, v in samples.items()}
    gpu = probe_values(snippet, base).astype(np.float64)
    exact = reference_values(snippet, base)
    if gpu.ndim == 2:
        exact = np.broadcast_to(exact[..., None] if exact.ndim == 1 else exact, gpu.shape)
    assert np.isfinite(gpu).all()
    error = np.abs(gpu - exact)
    significant = np.abs(exact) > 1e-6
    relative = error[significant] / np.abs(exact[significant])
    worst = np.unravel_index(np.argmax(error), error.shape)[0]
    where = {key: float(values[worst]) for key, values in base.items()}
    budget = snippet.error_budget
    assert error.max() <= budget["max_abs"], f"max abs {error.max():.3g} at {where}"
    if "max_rel" in budget:
        assert relative.max() <= budget["max_rel"], f"max rel {relative.max():.3g}"


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
