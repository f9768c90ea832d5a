"""Float64 numpy references of the exact models the catalog's variants implement or approximate.

A snippet names its reference in front matter (`reference = "D_ggx"`); the probes evaluate the
GLSL on a grid of its `domain` and compare with `reference(name)(**inputs)`. Every reference
takes its inputs by keyword, named like the GLSL entry's parameters (V takes the `Dots` fields
NoL, NoV, NoH, VoH, LoV and a), and broadcasts them as numpy does.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from . import distribution, fresnel, visibility

REFERENCES: dict[str, Callable[..., np.ndarray]] = {
    "D_ggx": distribution.D_ggx,
    "D_beckmann": distribution.D_beckmann,
    "D_blinn_phong": distribution.D_blinn_phong,
    "D_gaussian": distribution.D_gaussian,
    "F_dielectric": fresnel.F_dielectric,
    "V_smith_ggx_correlated": visibility.V_smith_ggx_correlated,
    "V_smith_ggx_separable": visibility.V_smith_ggx_separable,
    "V_smith_ggx_separable_remapped": visibility.V_smith_ggx_separable_remapped,
    "V_smith_beckmann_correlated": visibility.V_smith_beckmann_correlated,
    "V_smith_beckmann_separable": visibility.V_smith_beckmann_separable,
    "V_cook_torrance": visibility.V_cook_torrance,
}


def reference(name: str) -> Callable[..., np.ndarray]:
    """The reference called `name`; KeyError naming the known ones otherwise."""
    try:
        return REFERENCES[name]
    except KeyError:
        known = ", ".join(sorted(REFERENCES))
        raise KeyError(f"unknown reference '{name}'; known: {known}") from None
