"""Shadow and AO variants on the reference SDF scenes, against many-ray float64 ground truth
(references/occlusion.py) at the points of references/occlusion_cases.py.

One probe pass per scene: its `map` is the scene's GLSL, and the cases of its lights share it.
The probe tests (tests/verify/test_occlusion_probes.py) and the benchmark both measure from here.
"""

from __future__ import annotations

from functools import cache

import numpy as np

from glint.compiler.bench.samples import ProbeSet
from glint.compiler.verify.references import reference
from glint.compiler.verify.references.occlusion_cases import ao_cases, shadow_cases
from glint.compiler.verify.references.scenes import scene as reference_scene

# The default scene's shadow ray starts 0.02 off the surface; every occluder of the reference
# scenes is within 20, so no variant is cut short by tmax, only by its own step count.
TMIN, TMAX = 0.02, 20.0


def shadow_inputs(ro: np.ndarray, rd: np.ndarray, tmin: float, tmax: float) -> dict:
    count = len(ro)
    rd = np.broadcast_to(rd, ro.shape)
    inputs = {f"ro{i}": ro[:, i] for i in range(3)} | {f"rd{i}": rd[:, i] for i in range(3)}
    return inputs | {"tmin": np.full(count, tmin), "tmax": np.full(count, tmax)}


def ao_inputs(p: np.ndarray, n: np.ndarray) -> dict:
    return {f"p{i}": p[:, i] for i in range(3)} | {f"n{i}": n[:, i] for i in range(3)}


@cache
def shadow_truth(reference_name: str, case: int, k: float | None = None) -> np.ndarray:
    """Ground truth of one shadow case: `shadow_disc_light` (a disc of angular radius
    atan(1/k)) or `shadow_ray` (the hard shadow, no k). Cached: variants share it."""
    c = shadow_cases()[case]
    args = {"scene": c.scene, "ro": c.ro, "rd": c.light, "tmax": TMAX}
    if k is not None:
        args["k"] = k
    return reference(reference_name)(**args)


@cache
def ao_truth(case: int) -> np.ndarray:
    c = ao_cases()[case]
    return reference("ao_cosine_visibility")(scene=c.scene, p=c.p, n=c.n)


def _by_scene(names: list[str]) -> dict[str, list[int]]:
    groups: dict[str, list[int]] = {}
    for index, name in enumerate(names):
        groups.setdefault(name, []).append(index)
    return groups


def shadow_sets(reference_name: str, k: float | None = None) -> list[ProbeSet]:
    """Per reference scene, every shadow case of its lights in one pass, with the ground truth
    of `reference_name` (and `k` for the disc light)."""
    cases = shadow_cases()
    sets = []
    for scene, indices in _by_scene([c.scene for c in cases]).items():
        ro = np.concatenate([cases[i].ro for i in indices])
        rd = np.concatenate([np.broadcast_to(cases[i].light, cases[i].ro.shape) for i in indices])
        exact = np.concatenate([shadow_truth(reference_name, i, k) for i in indices])
        stub = reference_scene(scene).glsl(queries=True)
        sets.append(ProbeSet(shadow_inputs(ro, rd, TMIN, TMAX), stub, exact))
    return sets


def ao_sets() -> list[ProbeSet]:
    """Per reference scene, its AO points in one pass, with cosine-weighted visibility."""
    return [
        ProbeSet(ao_inputs(c.p, c.n), reference_scene(c.scene).glsl(), ao_truth(index))
        for index, c in enumerate(ao_cases())
    ]
