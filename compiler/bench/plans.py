"""What each variant is measured on: its probe passes, the ground truth of each, and the unit.

- A function of its arguments (D, F, V, the lobes, attenuation, phase, media, irradiance, ...):
  a grid over its domain against its own float64 reference.
- Shadows: every variant against one disc light on the reference scenes, the hard shadow too,
  so that the cost/error front compares what a viewer sees, not each variant to its own model.
- AO: cosine-weighted visibility; subsurface: transmittance through reference spheres;
  specular occlusion: the share of the GGX lobe seen through the AO's visibility cone.
- Normals: angle to the exact normal on the reference scenes. The derivative-based flat normal
  cannot be probed point by point: its error is measured on a rendered box (flat faces only, so
  it is a reference group of its own); its cost on the same passes as the others.
- An approximation a variant makes that its entry's probe cannot show alone
  (`ibl.env_brdf_approx`'s split-sum fit, `ibl.simple_reflection`'s reflection of the sky):
  its error against its own float64 truth (approximations.py), its cost as the whole entry's.
- No reference (camera, background, tonemap, output, env, raymarch): cost only, on inputs from
  the domain where there is one, else plausible ones (samples.free_inputs).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from glint.compiler.bench.approximations import (
    RenderedErrors,
    area_errors,
    area_timing_inputs,
    env_brdf_errors,
    reflection_errors,
)
from glint.compiler.bench.flat_normal import flat_normal_errors, render_flat
from glint.compiler.bench.normals import normal_set
from glint.compiler.bench.occlusion import ao_sets, shadow_sets
from glint.compiler.bench.samples import ProbeSet, camera_rays, domain_set, free_inputs
from glint.compiler.bench.subsurface import subsurface_sets
from glint.compiler.catalog.loader import Catalog, Snippet
from glint.compiler.compose.pipeline import uses_derivatives
from glint.compiler.verify.probes import entry_function, probe_inputs
from glint.compiler.verify.references.normals import SCENES as NORMAL_SCENES

# The disc light every shadow variant is measured against: angular radius atan(1/8) ≈ 7.1°,
# the light that the soft variants' default SHADOW_K = 8 stands for.
SHADOW_LIGHT = "shadow_disc_light"
SHADOW_LIGHT_K = 8.0
FLAT_FACES = "sdf_normal (flat faces)"
# Slots whose values are a visible fraction that reaches 0 by design: no relative error.
FRACTIONS = {"specocc"}
# Variants whose error is that of an approximation they contain: its truth, unit and errors.


@dataclass
class Plan:
    """How one variant is measured. Every set is timed; those with `exact` give errors too."""

    reference: str | None  # the ground truth's name; None: cost only
    unit: str  # what the error is in ("" without a reference)
    sets: list[ProbeSet]
    relative: bool = False  # whether a relative error means something (values away from 0)
    # errors measured apart from the timed passes: a render, or a probe of the approximation
    rendered: RenderedErrors | None = None
    out_params: bool = False  # the entry returns through out parameters (cameraRay)


# Slots whose values are a visible fraction that reaches 0 by design: no relative error.
FRACTIONS = {"specocc"}
# Variants whose error is that of an approximation they contain: its truth, unit and errors.
APPROXIMATIONS: dict[str, tuple[str, str, RenderedErrors]] = {
    "ibl.env_brdf_approx": ("dfg_split_sum", "albedo", env_brdf_errors),
    "ibl.simple_reflection": ("specular_environment", "radiance", reflection_errors),
    "area.representative": ("area_light", "radiance", area_errors("area.representative")),
    "area.sampled": ("area_light", "radiance", area_errors("area.sampled")),
}


def _flat_errors(catalog: Catalog) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    return flat_normal_errors(render_flat(catalog))


def _normal_plan(snippet: Snippet) -> Plan:
    # Variants that tap `map` are probed point by point; the flat one uses screen derivatives,
    # which a probe (one unrelated point per pixel) cannot give: it is only timed there.
    # (The flat one taps map only where its derivatives straddle a silhouette; the analytic one
    # reads the primitive a composed scene names: cost only, its exactness is tested apart.)
    taps = "map" in snippet.requires and not uses_derivatives(snippet)
    sets = [normal_set(snippet, scene, with_reference=taps) for scene in sorted(NORMAL_SCENES)]
    if "sceneNormal" in snippet.requires:
        return Plan(None, "", sets)
    if taps:
        return Plan(snippet.reference, "degrees", sets)
    return Plan(FLAT_FACES, "degrees", sets, rendered=_flat_errors)


def plan_for(snippet: Snippet) -> Plan:
    """The passes a variant is measured on; see the module's docstring."""
    slot = snippet.slot
    if slot == "shadow":
        return Plan(SHADOW_LIGHT, "visibility", shadow_sets(SHADOW_LIGHT, SHADOW_LIGHT_K))
    if slot == "ao":
        return Plan("ao_cosine_visibility", "visibility", ao_sets())
    if slot == "sss":
        return Plan(snippet.reference, "transmittance", subsurface_sets())
    if slot == "normal":
        return _normal_plan(snippet)
    if slot == "area":
        truth, unit, errors = APPROXIMATIONS[snippet.id]
        return Plan(truth, unit, [ProbeSet(area_timing_inputs())], rendered=errors)
    if snippet.domain:
        case = domain_set(snippet)
        if case.exact is None:
            return Plan(None, "", [case])
        if slot in FRACTIONS:
            return Plan(snippet.reference, "visibility", [case])
        return Plan(snippet.reference, "value", [case], relative=True)
    if slot == "raymarch":
        return Plan(None, "", [ProbeSet(camera_rays())])
    out_params = any("out" in p.qualifier.split() for p in entry_function(snippet).params)
    names = probe_inputs(entry_function(snippet), out_params)[0]
    timed = [ProbeSet(free_inputs(names))]
    if snippet.id in APPROXIMATIONS:
        truth, unit, errors = APPROXIMATIONS[snippet.id]
        return Plan(truth, unit, timed, rendered=errors, out_params=out_params)
    return Plan(None, "", timed, out_params=out_params)
