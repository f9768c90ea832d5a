"""Where a variant is measured: the inputs of a probe pass and, where it has one, what its
float64 reference says the output should be.

A variant whose entry is a function of its arguments alone is sampled on a grid over the
`domain` of its front matter; its reference is evaluated at the same (float32-rounded) points.
The probe tests (tests/verify/test_probe_references.py) and the benchmark (bench/variants.py)
both take their samples from here, so that they measure the same thing.
"""

from __future__ import annotations

import inspect
from dataclasses import dataclass, field

import numpy as np

from glint.compiler.catalog.loader import Snippet
from glint.compiler.compose.linking.standalone import SCENE_STUB
from glint.compiler.verify.probes import entry_function, probe_inputs
from glint.compiler.verify.references import reference
from glint.compiler.verify.references.geometry import dots

# The lobes take a Surface and Dots; their domains are the geometry (NoL signed, NoV, phi) and
# the roughness, from which the probe's Dots are derived as `lightDots` derives them.
LOBE_SLOTS = {"diffuse", "specular"}
# Dots fields a variant's domain does not name get a plausible fixed value.
DOTS_DEFAULTS = {"NoL": 0.5, "NoV": 0.5, "NoH": 1.0, "VoH": 1.0, "LoV": 0.0, "NoLsigned": 0.5}
# Below this |reference| a relative error is not taken (it would divide by nearly nothing).
SIGNIFICANT = 1e-6
# Inputs that are directions: a variant without a domain gets unit vectors for them.
DIRECTION_INPUTS = {"dir", "rd", "n", "N", "L", "V"}
# The seed of every random input here: the same samples on every run.
SEED = 5


@dataclass(frozen=True)
class ProbeSet:
    """One probe pass of a variant: its inputs, the scene it runs in, and the expected output.

    `exact` is None where only the cost is measured. `where` holds the coordinates that a worst
    error is reported at (the domain's own names); by default the probe inputs themselves.
    `metric` is "abs" (|GPU − exact| per component) or "degrees" (angle between vectors)."""

    inputs: dict[str, np.ndarray]
    scene_stub: str = SCENE_STUB
    exact: np.ndarray | None = None
    where: dict[str, np.ndarray] = field(default_factory=dict)
    metric: str = "abs"

    @property
    def coordinates(self) -> dict[str, np.ndarray]:
        return self.where or self.inputs


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


def per_axis(snippet: Snippet) -> int:
    """Grid points per axis: about 2 500 to 10 000 samples whatever the dimension."""
    return 48 if len(snippet.domain) <= 2 else 20 if len(snippet.domain) == 3 else 10


def probe_arguments(snippet: Snippet, base: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """The probe's scalar inputs from base-named values (a lobe's from its geometry)."""
    if snippet.slot in LOBE_SLOTS:
        base = lobe_inputs(base)
    count = len(next(iter(base.values())))
    inputs = {}
    for name in scalar_names(snippet):
        key = base_name(name)
        value = base.get(key, DOTS_DEFAULTS.get(key, 0.0))
        inputs[name] = np.broadcast_to(value, (count,))
    return inputs


def reference_values(snippet: Snippet, base: dict[str, np.ndarray]) -> np.ndarray:
    args = dict(base)
    if snippet.slot == "V":
        args = {key: base.get(key, DOTS_DEFAULTS[key]) for key in DOTS_DEFAULTS}
        args["a"] = base.get("a", 0.5)
    # A reference may take the snippet's own parameters by name: it gets their defaults.
    accepted = inspect.signature(reference(snippet.reference)).parameters
    args |= {name: p.default for name, p in snippet.params.items() if name in accepted}
    return np.asarray(reference(snippet.reference)(**args), dtype=np.float64)


def domain_set(snippet: Snippet) -> ProbeSet:
    """The variant over a grid of its domain, with its reference's values where it has one.
    The GPU receives float32 inputs; the reference gets the same values, so that what is
    measured is the snippet's arithmetic, not how 0.9999999 rounds on the way in."""
    samples = unit_directions(domain_samples(snippet, per_axis(snippet)))
    base = {k: v.astype(np.float32).astype(np.float64) for k, v in samples.items()}
    exact = reference_values(snippet, base) if snippet.reference else None
    return ProbeSet(probe_arguments(snippet, base), exact=exact, where=base)


def free_inputs(names: list[str], count: int = 4096, seed: int = SEED) -> dict[str, np.ndarray]:
    """Inputs for a variant with no domain, only to time it: unit vectors for the components
    of a direction, pixel coordinates of the 256-wide probe grid for `fragCoord`, [0, 1]
    otherwise (colours, cosines, roughness, ao)."""
    rng = np.random.default_rng(seed)
    inputs: dict[str, np.ndarray] = {}
    vectors: dict[str, list[str]] = {}
    for name in names:
        stem = name.split(".")[-1].rstrip("0123456789")
        if stem in DIRECTION_INPUTS and name[-1].isdigit():
            vectors.setdefault(stem, []).append(name)
        elif stem == "fragCoord":
            inputs[name] = rng.uniform(0.0, 256.0, count)
        else:
            inputs[name] = rng.uniform(0.0, 1.0, count)
    for components in vectors.values():
        v = rng.normal(size=(count, len(components)))
        v /= np.linalg.norm(v, axis=1, keepdims=True)
        inputs |= {name: v[:, i] for i, name in enumerate(components)}
    return inputs


def camera_rays(count: int = 4096, seed: int = SEED) -> dict[str, np.ndarray]:
    """Primary rays of a camera at (0, 1, 4) looking at the default scene stub (a unit sphere
    on the plane y = -1): hits on the sphere and the ground and misses to the sky, as a
    raymarcher meets them, rather than rays that start inside the sphere."""
    rng = np.random.default_rng(seed)
    uv = rng.uniform(-1.0, 1.0, (count, 2))
    rd = np.stack([uv[:, 0], uv[:, 1] - 0.25, np.full(count, -1.5)], -1)
    rd /= np.linalg.norm(rd, axis=1, keepdims=True)
    ro = {f"ro{i}": np.full(count, v) for i, v in enumerate((0.0, 1.0, 4.0))}
    return ro | {f"rd{i}": rd[:, i] for i in range(3)}
