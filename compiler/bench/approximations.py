"""Errors of the variants that approximate a quantity their entry does not return alone: the
approximation is measured against its own float64 truth, apart from the timed passes.

- `ibl.env_brdf_approx`: Karis's analytic (A, B) against the split-sum integral of the GGX lobe
  (`references.environment.dfg_split_sum`), as the directional albedo f0·A + B that the
  reflection is weighted by: the error is the larger of its two ends, f0 = 0 and f0 = 1 (it is
  linear in f0 between them).
- `area.representative` and `area.sampled`: the light of a sphere, disc or rectangle off a white
  dielectric against the light integrated over its surface in float64 (`references.area`),
  over lights of many sizes, distances and tilts, some past the horizon or seen from behind.
- `ibl.simple_reflection`: the light it reflects from the gradient sky (a dielectric, no
  occlusion) against the GGX lobe integrated over that sky (`specular_environment`), for
  normals all around, views above the surface and roughness over [0, 1].

Each function returns the errors per sample and the samples' coordinates, as a Plan's
`rendered` errors do.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from glint.compiler.catalog.loader import Catalog
from glint.compiler.verify.probes import run_probe, run_statements
from glint.compiler.verify.references.area import area_light
from glint.compiler.verify.references.environment import dfg_split_sum, specular_environment

RenderedErrors = Callable[[Catalog], tuple[np.ndarray, dict[str, np.ndarray]]]

GRID = 64  # samples per axis of a two-input approximation
MIN_NOV = 1e-4  # as core.surface's
REFLECTION_SAMPLES = 2048
SEED = 7
# A dielectric Surface from its own normal, view and roughness (makeSurface, as a scene builds
# it), lit by the environment with nothing occluded.
REFLECTION_PROBE = """    Surface s = makeSurface(vec3(0.0), in0.xyz, in1.xyz, vec3(1.0), in0.w);
    fragColor = vec4(environmentLight(s, 1.0), 1.0);
"""


AREA_CASES = 120  # per shape
# A white dielectric with its normal on +z, seen along in0.xyz at roughness in0.w, lit by the
# light in1..in3 (centre, right, up, shape) of radiance 1.
AREA_PROBE = """    vec3 V = normalize(in0.xyz);
    Surface s = makeSurface(vec3(0.0), vec3(0.0, 0.0, 1.0), V, vec3(1.0), in0.w);
    vec3 right = vec3(in1.w, in2.xy);
    vec3 up = vec3(in2.zw, in3.x);
    fragColor = vec4(areaLight(s, in1.xyz, right, up, int(in3.y + 0.5), vec3(1.0)), 1.0);
"""


def area_cases(count: int = AREA_CASES, seed: int = SEED) -> dict[str, np.ndarray]:
    """Lights of every shape around a surface whose normal is +z: centres 0.5 to 6 away, most
    above the horizon and some straddling it; sizes up to about 60° across; discs and
    rectangles tilted up to 60° from facing the point, one in ten facing away; views from
    grazing to overhead, roughness 0.1 to 1 (below, a highlight is narrower than the float64
    grid resolves). Keys: the probe's inputs, each (3 · count,)."""
    rng = np.random.default_rng(seed)
    total = 3 * count
    shape = np.repeat(np.arange(3), count).astype(np.float64)
    direction = rng.normal(size=(total, 3))
    direction[:, 2] = np.abs(direction[:, 2]) - 0.3 * rng.uniform(size=total)
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    dist = rng.uniform(0.5, 6.0, total)
    center = direction * dist[:, None]
    size = dist * rng.uniform(0.02, 0.5, total)  # radius or half side
    toward = -direction + rng.normal(scale=0.5, size=(total, 3))
    toward[rng.uniform(size=total) < 0.1] *= -1.0  # facing away
    toward /= np.linalg.norm(toward, axis=1, keepdims=True)
    helper = np.where(np.abs(toward[:, 1:2]) < 0.99, [[0.0, 1.0, 0.0]], [[1.0, 0.0, 0.0]])
    right = np.cross(helper, toward)
    right /= np.linalg.norm(right, axis=1, keepdims=True)
    up = np.cross(toward, right)
    aspect = np.where(shape == 2, rng.uniform(0.3, 1.0, total), 1.0)
    right *= size[:, None]
    up *= (size * aspect)[:, None]
    v = rng.normal(size=(total, 3))
    v[:, 2] = np.abs(v[:, 2]) + 0.02
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    roughness = rng.uniform(0.1, 1.0, total)
    columns = [*v.T, roughness, *center.T, *right.T, *up.T, shape]
    names = ["v0", "v1", "v2", "roughness", "c0", "c1", "c2", "r0", "r1", "r2", "u0", "u1",
             "u2", "shape"]  # fmt: skip
    return {
        n: np.asarray(c, np.float32).astype(np.float64) for n, c in zip(names, columns, strict=True)
    }


def area_timing_inputs() -> dict[str, np.ndarray]:
    """The cases of area_cases as the entry's own probe takes them (areaLight(s, center,
    right, up, shape, radiance) with a fixed white Surface of its roughness and N·V), so that
    the cost is timed on the same mix of shapes as the error."""
    cases = area_cases()
    inputs = {"s.roughness": cases["roughness"], "s.NoV": np.maximum(cases["v2"], 1e-4)}
    for key, name in (("c", "center"), ("r", "right"), ("u", "up")):
        inputs |= {f"{name}{i}": cases[f"{key}{i}"] for i in range(3)}
    inputs["shape"] = cases["shape"]
    inputs |= {f"radiance{i}": np.ones_like(cases["shape"]) for i in range(3)}
    return inputs


def area_errors(variant: str) -> RenderedErrors:
    """|areaLight − the float64 integral| per colour channel of an area variant."""

    def errors(catalog: Catalog) -> tuple[np.ndarray, dict[str, np.ndarray]]:
        inputs = area_cases()
        names = list(inputs)
        gpu = run_statements(variant, AREA_PROBE, names, inputs, 3, catalog)
        stack = {k: np.stack([inputs[f"{k}{i}"] for i in range(3)], axis=1) for k in "vcru"}
        exact = area_light(
            v=stack["v"], roughness=inputs["roughness"], center=stack["c"], right=stack["r"],
            up=stack["u"], shape=inputs["shape"],
        )  # fmt: skip
        error = np.abs(np.asarray(gpu, np.float64) - exact[:, None])
        where = {"shape": inputs["shape"], "roughness": inputs["roughness"], "exact": exact}
        return np.where(np.isfinite(error), error, np.inf), where

    return errors


def _grid(first: tuple[float, float], second: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Two inputs over a GRID x GRID tensor grid of their ranges, rounded to float32 as the GPU
    receives them."""
    axes = [
        np.linspace(*span, GRID).astype(np.float32).astype(np.float64) for span in (first, second)
    ]
    one, two = np.meshgrid(*axes, indexing="ij")
    return one.ravel(), two.ravel()


def env_brdf_errors(catalog: Catalog) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """|f0·A + B − exact| at its worst f0, for roughness over [0, 1] and N·V over [MIN_NOV, 1]
    (core.surface never lets N·V reach 0, where the lobe's albedo is degenerate)."""
    nov, roughness = _grid((MIN_NOV, 1.0), (0.0, 1.0))
    inputs = {"NoV": nov, "roughness": roughness}
    gpu = run_probe("ibl.env_brdf_approx", inputs, catalog, function="envBRDFApprox")
    exact = dfg_split_sum(roughness, nov)
    delta = np.asarray(gpu, np.float64) - exact
    error = np.maximum(np.abs(delta[:, 1]), np.abs(delta[:, 0] + delta[:, 1]))
    return np.where(np.isfinite(error), error, np.inf), inputs


def reflection_errors(catalog: Catalog) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """|reflected − exact| per colour channel of ibl.simple_reflection over the gradient sky."""
    rng = np.random.default_rng(SEED)
    n = rng.normal(size=(REFLECTION_SAMPLES, 3))
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    v = rng.normal(size=(REFLECTION_SAMPLES, 3))
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    v *= np.where(np.sum(n * v, axis=1) < 0.0, -1.0, 1.0)[:, None]  # above the surface
    roughness = rng.uniform(0.0, 1.0, REFLECTION_SAMPLES)
    n, v, roughness = (x.astype(np.float32).astype(np.float64) for x in (n, v, roughness))
    names = ["n0", "n1", "n2", "roughness", "v0", "v1", "v2"]
    values = [*n.T, roughness, *v.T]
    inputs = dict(zip(names, values, strict=True))
    gpu = run_statements("ibl.simple_reflection", REFLECTION_PROBE, names, inputs, 3, catalog)
    exact = specular_environment(n, v, roughness)
    error = np.abs(np.asarray(gpu, np.float64) - exact)
    where = {"NoV": np.sum(n * v, axis=1), "N.y": n[:, 1], "roughness": roughness}
    return np.where(np.isfinite(error), error, np.inf), where
