"""Errors of the variants that approximate a quantity their entry does not return alone: the
approximation is measured against its own float64 truth, apart from the timed passes.

- `ibl.env_brdf_approx`: Karis's analytic (A, B) against the split-sum integral of the GGX lobe
  (`references.environment.dfg_split_sum`), as the directional albedo f0·A + B that the
  reflection is weighted by: the error is the larger of its two ends, f0 = 0 and f0 = 1 (it is
  linear in f0 between them).
- `ibl.simple_reflection`: the light it reflects from the gradient sky (a dielectric, no
  occlusion) against the GGX lobe integrated over that sky (`specular_environment`), for
  normals all around, views above the surface and roughness over [0, 1].

Each function returns the errors per sample and the samples' coordinates, as a Plan's
`rendered` errors do.
"""

from __future__ import annotations

import numpy as np

from glint.compiler.catalog.loader import Catalog
from glint.compiler.verify.probes import run_probe, run_statements
from glint.compiler.verify.references.environment import dfg_split_sum, specular_environment

GRID = 64  # samples per axis of a two-input approximation
MIN_NOV = 1e-4  # as core.surface's
REFLECTION_SAMPLES = 2048
SEED = 7
# A dielectric Surface from its own normal, view and roughness (makeSurface, as a scene builds
# it), lit by the environment with nothing occluded.
REFLECTION_PROBE = """    Surface s = makeSurface(vec3(0.0), in0.xyz, in1.xyz, vec3(1.0), in0.w);
    fragColor = vec4(environmentLight(s, 1.0), 1.0);
"""


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
